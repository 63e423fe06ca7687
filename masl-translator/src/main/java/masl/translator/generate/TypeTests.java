package masl.translator.generate;

import java.util.List;
import masl.grammar.MASLParser;
import masl.translator.analysis.AgentDecl;
import masl.translator.analysis.AnalyzedProgram;
import masl.translator.analysis.ImportedType;
import masl.translator.analysis.MaslType;

/**
 * {@code e instanceof T} where {@code T} is an agent type (MASL §4). An agent type is not its
 * implementation class: {@code type Spare use SoftWheeledRobot.xml;} makes a type distinct from the
 * one imported from that file, with the same class. So a type test on {@code this} is decided for the
 * program's type when it is generated, and one on another agent asks whether it is among the agents
 * of {@code T}, which are known here: agents are only created at start-up, their proxy ids in
 * declaration order.
 */
final class TypeTests {

    static final String HELPER = "agentAmong";

    private final AnalyzedProgram program;
    private final ImportedType selfType;
    private boolean used;

    TypeTests(AnalyzedProgram program, ImportedType selfType) {
        this.program = program;
        this.selfType = selfType;
    }

    /** Whether {@code test} tests an agent type, which {@link #write} translates. */
    boolean isAgentTypeTest(MASLParser.InstanceofExprContext test) {
        return program.typeOf(test.javaType()) instanceof MaslType.AgentRef ref && ref.type() != null;
    }

    /** The Java of an agent type test whose tested value is {@code value} (Java). */
    String write(MASLParser.InstanceofExprContext test, String value) {
        ImportedType tested = ((MaslType.AgentRef) program.typeOf(test.javaType())).type();
        if (TreeQueries.isThis(test.expression())) {
            return String.valueOf(selfType.isSubtypeOf(tested));
        }
        used = true;
        List<String> ids = program.agents().stream()
                .filter(agent -> agent.instantiatedType().isSubtypeOf(tested))
                .map(AgentDecl::proxyId).map(String::valueOf).toList();
        return HELPER + "(" + value + (ids.isEmpty() ? "" : ", " + String.join(", ", ids)) + ")";
    }

    /** Whether a test on another agent was written: the program class then needs {@link #helper()}. */
    boolean used() {
        return used;
    }

    static List<String> helper() {
        return List.of(
                "    /** Whether {@code agent} is one of the agents {@code proxyIds}: a type test on an agent (MASL 4). */",
                "    private static boolean " + HELPER + "(Object agent, int... proxyIds) {",
                "        if (agent instanceof AgentImplementation member) {",
                "            int id = AgentImplementation.proxyIdOf(member);",
                "            for (int proxyId : proxyIds) {",
                "                if (proxyId == id) {",
                "                    return true;",
                "                }",
                "            }",
                "        }",
                "        return false;",
                "    }");
    }
}
