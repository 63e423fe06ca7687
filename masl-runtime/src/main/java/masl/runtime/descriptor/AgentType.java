package masl.runtime.descriptor;

import java.util.ArrayList;
import java.util.Collection;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.function.Function;

/**
 * An agent type as loaded from its descriptor by a {@link DescriptorLoader}, supertypes resolved and
 * every rule of agent-types.md checked. Immutable.
 *
 * <p>Members: the supertype's members are inherited; a member the type declares with the name of an
 * inherited one of the same kind redefines it, keeping the inherited member id or taking its own (ids
 * belong to the descriptor that declares them). Visible members keep the supertype's order,
 * redefinitions in place, new members after them in declaration order.
 */
public final class AgentType {

    /** The initial permeability state's name when the type has it (MASL §11). */
    public static final String DEFAULT_STATE = "default";

    private final String shortName;
    private final String fullClassName;
    private final String superFullClassName;
    private final DescriptorSource source;
    private final int line;
    private final AgentType supertype;
    private final List<Primitive> declaredPrimitives;
    private final List<Attribute> declaredAttributes;
    private final List<String> utilityClasses;
    private final List<PermeabilityState> states;
    private final Map<String, Primitive> primitives;
    private final Map<String, Attribute> attributes;
    private final FipaBinding fipa;

    AgentType(Declaration declaration, DescriptorSource source, AgentType supertype, List<PermeabilityState> states) {
        this.shortName = declaration.shortName();
        this.fullClassName = declaration.fullClassName();
        this.superFullClassName = supertype == null ? null : supertype.fullClassName();
        this.source = source;
        this.line = declaration.line();
        this.supertype = supertype;
        this.declaredPrimitives = List.copyOf(declaration.primitives());
        this.declaredAttributes = List.copyOf(declaration.attributes());
        this.utilityClasses = inheritedThenOwn(supertype == null ? List.of() : supertype.utilityClasses(),
                declaration.utilityClasses().stream().map(Declaration.UtilityClass::name).toList());
        this.states = List.copyOf(states);
        this.primitives = visible(supertype == null ? List.of() : supertype.primitives(), declaredPrimitives,
                Primitive::name);
        this.attributes = visible(supertype == null ? List.of() : supertype.attributes(), declaredAttributes,
                Attribute::name);
        this.fipa = declaration.fipa() != null || supertype == null ? declaration.fipa() : supertype.fipa;
    }

    /**
     * The external FIPA agent each agent of this type stands for ({@code <Fipa>}, its own or its
     * supertype's); empty for a type implemented in Java only.
     */
    public Optional<FipaBinding> fipa() {
        return Optional.ofNullable(fipa);
    }

    /** The default MASL name of the type ({@code short_class_name}). */
    public String shortName() {
        return shortName;
    }

    /** The implementation class ({@code full_class_name}). */
    public String fullClassName() {
        return fullClassName;
    }

    /**
     * The supertype's implementation class: {@code super_full_class_name}, or the implicit root's
     * (the {@code Default.xml} found first, see {@link DescriptorLoader}) when the descriptor names
     * none; null only for a root.
     */
    public String superFullClassName() {
        return superFullClassName;
    }

    /** The descriptor this type was loaded from. */
    public DescriptorSource source() {
        return source;
    }

    /** 1-based line of the {@code <Agent>} element. */
    public int line() {
        return line;
    }

    /** The resolved supertype, or null for a root type. */
    public AgentType supertype() {
        return supertype;
    }

    /** The primitives this descriptor declares (redefinitions included), in order. */
    public List<Primitive> declaredPrimitives() {
        return declaredPrimitives;
    }

    /** The attributes this descriptor declares (redefinitions included), in order. */
    public List<Attribute> declaredAttributes() {
        return declaredAttributes;
    }

    /** Every visible primitive: inherited (or redefined here) then new ones. */
    public List<Primitive> primitives() {
        return List.copyOf(primitives.values());
    }

    /** Every visible attribute: inherited (or redefined here) then new ones. */
    public List<Attribute> attributes() {
        return List.copyOf(attributes.values());
    }

    /** The visible primitive named {@code name}: this type's own, else the nearest supertype's. */
    public Optional<Primitive> findPrimitive(String name) {
        return Optional.ofNullable(primitives.get(name));
    }

    /** The visible attribute named {@code name}: this type's own, else the nearest supertype's. */
    public Optional<Attribute> findAttribute(String name) {
        return Optional.ofNullable(attributes.get(name));
    }

    /** Utility classes ({@code <Class>}) of the supertypes then of this type, without repetition. */
    public List<String> utilityClasses() {
        return utilityClasses;
    }

    /**
     * The permeability states: the supertype's, in its order (a state this descriptor redeclares stays
     * in place), then the ones new here. The rights of each are described in the README, "Descriptors".
     */
    public List<PermeabilityState> states() {
        return states;
    }

    /** The state named {@code name}, if the type has it. */
    public Optional<PermeabilityState> findState(String name) {
        return states.stream().filter(state -> state.name().equals(name)).findFirst();
    }

    /**
     * The state an agent starts in (MASL §11): {@code default} if the type has it, else the first one;
     * empty when the type has no state, and then everything is allowed.
     */
    public Optional<PermeabilityState> initialState() {
        return findState(DEFAULT_STATE).or(() -> states.stream().findFirst());
    }

    /** Whether {@code other} is this type or one of its supertypes, compared by implementation class name. */
    public boolean isSubtypeOf(AgentType other) {
        for (AgentType type = this; type != null; type = type.supertype) {
            if (type.fullClassName.equals(other.fullClassName)) {
                return true;
            }
        }
        return false;
    }

    @Override
    public String toString() {
        return shortName + " (" + fullClassName + ", " + source.displayName() + ")";
    }

    private static List<String> inheritedThenOwn(List<String> inherited, List<String> own) {
        List<String> all = new ArrayList<>(inherited);
        own.stream().filter(name -> !all.contains(name)).forEach(all::add);
        return List.copyOf(all);
    }

    private static <M> Map<String, M> visible(Collection<M> inherited, List<M> own,
            Function<M, String> name) {
        Map<String, M> visible = new LinkedHashMap<>();
        inherited.forEach(member -> visible.put(name.apply(member), member));
        // put() keeps the position of an existing key: a redefinition stays where the inherited one was.
        own.forEach(member -> visible.put(name.apply(member), member));
        return Collections.unmodifiableMap(visible);
    }
}
