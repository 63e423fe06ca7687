package masl.runtime.invocation;

import java.util.Optional;
import masl.runtime.descriptor.AgentType;
import masl.runtime.descriptor.Attribute;
import masl.runtime.descriptor.PermeabilityState.Requester;
import masl.runtime.descriptor.PermeabilityState;
import masl.runtime.descriptor.Primitive;

/**
 * One agent's permeability (MASL §11): its type's states and the current one. A type without
 * states, or an agent declared without a type, allows everything. The current state is written by
 * the agent only and read by any thread.
 *
 * <p><b>Internal:</b> not part of the API; public only for the other packages of the runtime (Java has no
 * friend packages), and may change without notice.
 */
public final class Permeability {

    private final AgentType type;
    private volatile PermeabilityState current;

    /** @param type the agent's type, or null when the mission was built without descriptors */
    public Permeability(AgentType type) {
        this.type = type;
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
}
