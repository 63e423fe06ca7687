package masl.jade.deployment;

import java.util.Optional;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import masl.runtime.descriptor.AgentType;
import masl.runtime.descriptor.Attribute;
import masl.runtime.descriptor.PermeabilityState;
import masl.runtime.descriptor.PermeabilityState.Requester;
import masl.runtime.descriptor.Primitive;
import masl.runtime.invocation.Permeability;

/**
 * A deployed agent's permeability as its container knows it, so that the agent's calls of its own
 * primitives and accesses to its own attributes run in the container with no message (MASL §11;
 * the bridge's README, "Deployed programs"). Only the agent changes its own state, and each change
 * is answered by the mission with the state it now is in, so the container's copy is the mission's.
 * What the copy does not allow, and an own primitive a launch of the agent armed a countermeasure on
 * (the mission disarms it at the next call), goes to the mission, which applies the rule as
 * in-process.
 */
final class OwnPermeability {

    private final AgentType type;
    private volatile PermeabilityState current;
    private final Set<String> armed = ConcurrentHashMap.newKeySet();

    OwnPermeability(AgentType type) {
        this.type = type;
        this.current = type == null ? null : type.initialState().orElse(null);
    }

    /** Whether the agent may run its own {@code primitive} here, now. */
    boolean letsInvoke(String primitive) {
        String memberId = type == null ? null : type.findPrimitive(primitive).map(Primitive::memberId).orElse(null);
        return !armed.contains(primitive)
                && Permeability.allows(current, memberId, Requester.SELF, PermeabilityState.INVOKE);
    }

    /**
     * Whether the agent's state lets another agent invoke its {@code primitive} now, whatever the
     * caller's relation to it, which only the mission knows (§11: g or o; u too for a static
     * primitive, whose callers of the agent's type count as the agent).
     */
    boolean letsOthersInvoke(String primitive) {
        Optional<Primitive> declared = type == null ? Optional.empty() : type.findPrimitive(primitive);
        String memberId = declared.map(Primitive::memberId).orElse(null);
        PermeabilityState state = current;
        boolean anyOther = Permeability.allows(state, memberId, Requester.GROUP, PermeabilityState.INVOKE)
                && Permeability.allows(state, memberId, Requester.OTHER, PermeabilityState.INVOKE);
        boolean isStatic = declared.map(Primitive::isStatic).orElse(false);
        return anyOther && (!isStatic || Permeability.allows(state, memberId, Requester.SELF, PermeabilityState.INVOKE));
    }

    /** Whether the agent may read ({@link PermeabilityState#READ}) or write its own {@code attribute} here, now. */
    boolean letsAccess(String attribute, int permission) {
        String memberId = type == null ? null : type.findAttribute(attribute).map(Attribute::memberId).orElse(null);
        return Permeability.allows(current, memberId, Requester.SELF, permission);
    }

    /** The mission says the agent's state is now {@code name} ({@code ""}: a type without states). */
    void nowIn(String name) {
        current = type == null ? null : type.findState(name).orElse(null);
    }

    /** A launch of the agent's own {@code primitive} armed a countermeasure: its calls go to the mission. */
    void armed(String primitive) {
        armed.add(primitive);
    }
}
