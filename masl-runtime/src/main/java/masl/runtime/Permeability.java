package masl.runtime;

import java.util.Optional;
import masl.runtime.descriptor.AgentType;
import masl.runtime.descriptor.Attribute;
import masl.runtime.descriptor.PermeabilityState;
import masl.runtime.descriptor.PermeabilityState.Requester;
import masl.runtime.descriptor.Primitive;

/**
 * One agent's permeability (MASL §11): its type's states and the current one. A type without
 * states, or an agent declared without a type, allows everything. The current state is written by
 * the agent only and read by any thread.
 */
final class Permeability {

    private final AgentType type;
    private volatile PermeabilityState current;

    /** @param type the agent's type, or null when the mission was built without descriptors */
    Permeability(AgentType type) {
        this.type = type;
        this.current = type == null ? null : type.initialState().orElse(null);
    }

    AgentType type() {
        return type;
    }

    /** The current state; null when everything is allowed (no states). */
    PermeabilityState current() {
        return current;
    }

    /** {@code getAcceptState()}: the current state's name, {@code ""} for a type without states. */
    String currentName() {
        PermeabilityState state = current;
        return state == null ? "" : state.name();
    }

    /** The type's state named {@code name}, if it declares one. */
    Optional<PermeabilityState> find(String name) {
        return type == null ? Optional.empty() : type.findState(name);
    }

    void set(PermeabilityState state) {
        current = state;
    }

    /** The member id of primitive {@code name}, null if the type has none (or no type is known). */
    String primitiveId(String name) {
        return type == null ? null : type.findPrimitive(name).map(Primitive::memberId).orElse(null);
    }

    boolean isStaticPrimitive(String name) {
        return type != null && type.findPrimitive(name).map(Primitive::isStatic).orElse(false);
    }

    String attributeId(String name) {
        return type == null ? null : type.findAttribute(name).map(Attribute::memberId).orElse(null);
    }

    boolean isStaticAttribute(String name) {
        return type != null && type.findAttribute(name).map(Attribute::isStatic).orElse(false);
    }

    /**
     * Whether {@code state} gives {@code requester} {@code permission} on member {@code memberId}: a
     * null state allows everything; a member the type does not declare has no rights.
     */
    static boolean allows(PermeabilityState state, String memberId, Requester requester, int permission) {
        if (state == null) {
            return true;
        }
        return memberId != null && state.allows(memberId, requester, permission);
    }
}
