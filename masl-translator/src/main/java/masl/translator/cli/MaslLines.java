package masl.translator.cli;

import java.util.HashMap;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import masl.translator.Translation;

/**
 * Puts MASL lines into the runtime's words about agents: {@code agent k1 (0) at pc 7} becomes
 * {@code agent k1 (0) at pc 7 (hello.masl:5: .logln("in");)}, read from the comment of case 7 of the
 * program class that agent runs. A user reads the report of a deadlock or failure in terms of the
 * program, not of the generated code.
 */
final class MaslLines {

    private static final Pattern AGENT_DECLARATION = Pattern.compile(
            "builder\\.agent\\(\"([^\"]+)\", .*, (\\w+)::new\\);");
    private static final Pattern CASE = Pattern.compile("(?m)^\\s*case (\\d+): // (.*)$");
    private static final Pattern AGENT_AT_PC = Pattern.compile("agent (\\S+) \\((\\d+)\\) at pc (\\d+)");

    /** For each agent's name, the comment of each case of its program. */
    private final Map<String, Map<Integer, String>> casesByAgent = new HashMap<>();

    MaslLines(Translation translation) {
        String packageName = translation.missionClassName()
                .substring(0, translation.missionClassName().lastIndexOf('.') + 1);
        Matcher agents = AGENT_DECLARATION.matcher(translation.javaSources().get(translation.missionClassName()));
        Map<String, Map<Integer, String>> casesByClass = new HashMap<>();
        while (agents.find()) {
            String programClass = agents.group(2);
            casesByAgent.put(agents.group(1), casesByClass.computeIfAbsent(programClass,
                    c -> cases(translation.javaSources().getOrDefault(packageName + c, ""))));
        }
    }

    private static Map<Integer, String> cases(String source) {
        Map<Integer, String> cases = new HashMap<>();
        Matcher matcher = CASE.matcher(source);
        while (matcher.find()) {
            cases.put(Integer.parseInt(matcher.group(1)), matcher.group(2));
        }
        return cases;
    }

    /** {@code text} with the MASL line after each {@code agent NAME (ID) at pc N} it knows. */
    String annotate(String text) {
        Matcher matcher = AGENT_AT_PC.matcher(text);
        StringBuilder out = new StringBuilder();
        while (matcher.find()) {
            String line = casesByAgent.getOrDefault(matcher.group(1), Map.of())
                    .get(Integer.parseInt(matcher.group(3)));
            matcher.appendReplacement(out, Matcher.quoteReplacement(
                    matcher.group() + (line == null ? "" : " (" + line + ")")));
        }
        matcher.appendTail(out);
        return out.toString();
    }
}
