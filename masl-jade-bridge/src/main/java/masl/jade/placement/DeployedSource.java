package masl.jade.placement;

import java.util.Map;
import java.util.TreeMap;

/**
 * What a coordinator sends the containers it deploys agents to, instead of code: the MASL program's
 * name and text, the descriptors next to it (file name to text), and the key of its translation
 * ({@link ProgramTranslator}), which a container must find again translating them itself.
 */
public record DeployedSource(String programName, String programText, Map<String, String> descriptors, String key) {

    public DeployedSource {
        descriptors = Map.copyOf(new TreeMap<>(descriptors));
    }
}
