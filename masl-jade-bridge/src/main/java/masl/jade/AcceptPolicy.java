package masl.jade;

import masl.runtime.descriptor.AgentType;
import masl.runtime.descriptor.PermeabilityState;
import masl.runtime.descriptor.Primitive;

/**
 * Whether an agent's permeability lets a requester from outside the mission (a FIPA agent: an
 * <em>other</em>, MASL §11) invoke one of its primitives now. Asked on the callee's thread, when the
 * invocation is served; a denied invocation is answered with {@code REFUSE}.
 */
@FunctionalInterface
public interface AcceptPolicy {

    /**
     * The rights of <em>others</em> to invoke in the type's initial state ({@code default} if declared,
     * else the first; a type without states allows everything): what the agent accepts until its
     * program changes its state. The runtime does not track changes of state yet, so this is the
     * launcher's default for now.
     */
    AcceptPolicy INITIAL_STATE = (agentName, type, primitive) -> type.initialState()
            .map(state -> state.allows(primitive.memberId(), PermeabilityState.Requester.OTHER,
                    PermeabilityState.INVOKE))
            .orElse(true);

    boolean allowsOther(String agentName, AgentType type, Primitive primitive);
}
