package masl.jade.placement;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.HashSet;
import java.util.Set;
import masl.jade.acl.PlacementContent;
import masl.jade.deployment.DeployedTeam;
import masl.jade.deployment.Wire;

/**
 * A container's side of a deployment: it translates the program it was sent itself, refuses it when
 * its translation's key is not the coordinator's (a different masl, program or descriptor), and runs
 * the deployed agents' programs ({@link DeployedTeam}); and the JSON of the coordination messages.
 */
final class DeployedTeams {

    private static final ObjectMapper MAPPER = new ObjectMapper();

    private DeployedTeams() {
    }

    /** @throws ProgramTranslator.Refusal if this container cannot run the deployed agents' programs, saying why */
    static DeployedTeam make(PlacementContent.Deploy deploy, ProgramTranslator translator, String container, Wire wire)
            throws ProgramTranslator.Refusal {
        if (translator == null) {
            throw new ProgramTranslator.Refusal("container " + container + " runs no deployed programs"
                    + " (it was started without a translator)");
        }
        ProgramTranslator.Translated translated = translator.translate(new DeployedSource(deploy.program(),
                deploy.text(), deploy.descriptors(), deploy.key()));
        if (!translated.key().equals(deploy.key())) {
            throw new ProgramTranslator.Refusal("its translation of " + deploy.program() + " is not the coordinator's"
                    + " (translation key " + abbreviated(translated.key()) + " here, " + abbreviated(deploy.key())
                    + " there): a different masl, program or descriptor");
        }
        Set<String> declared = new HashSet<>();
        translated.program().agents().forEach(agent -> declared.add(agent.name()));
        for (String agent : deploy.agents()) {
            if (!declared.contains(agent)) {
                throw new ProgramTranslator.Refusal(deploy.program() + " declares no agent " + agent);
            }
        }
        return new DeployedTeam(translated.program(), Set.copyOf(deploy.agents()), translated.implementations(), wire);
    }

    private static String abbreviated(String key) {
        return key.length() <= 12 ? key : key.substring(0, 12) + "…";
    }

    /** @throws IllegalArgumentException if {@code content} is not a JSON object */
    static ObjectNode read(String content) {
        try {
            JsonNode json = MAPPER.readTree(content == null ? "" : content);
            if (json instanceof ObjectNode object) {
                return object;
            }
        } catch (JsonProcessingException malformed) {
            // said below
        }
        throw new IllegalArgumentException("not a coordination message: " + content);
    }
}
