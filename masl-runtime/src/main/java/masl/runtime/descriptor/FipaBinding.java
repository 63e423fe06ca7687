package masl.runtime.descriptor;

/**
 * A type whose agents are external FIPA agents ({@code <Fipa>}): inside JADE, the primitives the
 * type declares (not those of {@code Default}) are {@code REQUEST}s to a FIPA agent found by DF
 * service type or by AID name, written in {@code language}.
 *
 * @param serviceType the DF service type the agent is found by, or null
 * @param agentName   the agent's name (local, or global {@code name@platform}), or null; exactly one
 *                    of the two is given
 * @param language    {@code json} or {@code string}
 * @param ontology    the ontology of the requests, or null
 */
public record FipaBinding(String serviceType, String agentName, String language, String ontology) {

    public static final String JSON = "json";
    public static final String STRING = "string";
}
