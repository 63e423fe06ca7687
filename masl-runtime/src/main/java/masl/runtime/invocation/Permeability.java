package masl.runtime.invocation;

import java.util.Optional;
import masl.runtime.Agent;
import masl.runtime.descriptor.AgentType;
import masl.runtime.descriptor.Attribute;
import masl.runtime.descriptor.PermeabilityState.Requester;
import masl.runtime.descriptor.PermeabilityState;
import masl.runtime.descriptor.Primitive;
import masl.runtime.entry.EntryCoordinator;
import masl.runtime.entry.MemberAgent;

/**
 * One agent's permeability (MASL §11): its type's states and the current one, and what the
 * current state lets a requester do: invoke a primitive, read or write an attribute, decided at
 * the time of the access from the requester's relation to the agent. A type without states, or an
 * agent declared without a type, allows everything. The current state is written by the agent only
 * and read by any thread.
 *
 * <p><b>Internal:</b> not part of the API; public only for the other packages of the runtime (Java has no
 * friend packages), and may change without notice.
 */
public final class Permeability {

    private final AgentType type;
    private final MemberAgent owner;
    private final EntryCoordinator coordinator;
    private volatile PermeabilityState current;

    /**
     * @param type the agent's type, or null when the mission was built without descriptors
     * @param owner the agent
     * @param coordinator whose lock guards the memberships that decide the requester's relation
     */
    public Permeability(AgentType type, MemberAgent owner, EntryCoordinator coordinator) {
        this.type = type;
        this.owner = owner;
        this.coordinator = coordinator;
        this.current = type == null ? null : type.initialState().orElse(null);
    }

    public AgentType type() {
        return type;
    }

    /** The current state; null when everything is allowed (no states). */
    public PermeabilityState current() {
        return current;
    }

    /** {@code getAcceptState()}: the current state's name, {@code ""} for a type without states. */
    public String currentName() {
        PermeabilityState state = current;
        return state == null ? "" : state.name();
    }

    /** The type's state named {@code name}, if it declares one. */
    public Optional<PermeabilityState> find(String name) {
        return type == null ? Optional.empty() : type.findState(name);
    }

    public void set(PermeabilityState state) {
        current = state;
    }

    /** The member id of primitive {@code name}, null if the type has none (or no type is known). */
    public String primitiveId(String name) {
        return type == null ? null : type.findPrimitive(name).map(Primitive::memberId).orElse(null);
    }

    public boolean isStaticPrimitive(String name) {
        return type != null && type.findPrimitive(name).map(Primitive::isStatic).orElse(false);
    }

    public String attributeId(String name) {
        return type == null ? null : type.findAttribute(name).map(Attribute::memberId).orElse(null);
    }

    public boolean isStaticAttribute(String name) {
        return type != null && type.findAttribute(name).map(Attribute::isStatic).orElse(false);
    }

    /**
     * Whether {@code state} gives {@code requester} {@code permission} on member {@code memberId}: a
     * null state allows everything; a member the type does not declare has no rights.
     */
    public static boolean allows(PermeabilityState state, String memberId, Requester requester, int permission) {
        if (state == null) {
            return true;
        }
        return memberId != null && state.allows(memberId, requester, permission);
    }

    /** Whether {@code state} of the agent lets the invocation run, its requester's relation decided now (§11). */
    boolean permits(PermeabilityState state, PendingInvocation invocation) {
        String primitive = invocation.primitive();
        if (primitive == null || state == null) {
            return true;
        }
        // The relation needs the coordinator's lock: decided only when a state's rights depend on it.
        return allows(state, primitiveId(primitive), relationOf(invocation.requester(), isStaticPrimitive(primitive)),
                PermeabilityState.INVOKE);
    }

    /** Whether the current state gives {@code requester} {@code permission} on {@code attribute}. */
    public boolean permitsAttribute(Agent requester, String attribute, int permission) {
        return allows(current, attributeId(attribute), relationOf(requester, isStaticAttribute(attribute)), permission);
    }

    /**
     * The requester's digit of the rights (§11), decided at the time of the access: u for the agent,
     * g for an agent whose innermost current block is exactly the agent's, o otherwise. For a static
     * member, a requester of the same type is filtered by u, another by g or o.
     */
    private Requester relationOf(Agent requester, boolean staticMember) {
        if (requester == owner) {
            return Requester.SELF;
        }
        if (requester == null) {
            return Requester.OTHER;
        }
        if (staticMember && requester.permeability().type() == type) {
            return Requester.SELF;
        }
        boolean sameBlock = coordinator.query(() -> !owner.memberships.isEmpty()
                && !requester.memberships.isEmpty() && owner.innermost().entry == requester.innermost().entry);
        return sameBlock ? Requester.GROUP : Requester.OTHER;
    }
}
