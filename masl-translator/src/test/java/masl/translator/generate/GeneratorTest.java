package masl.translator.generate;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import java.util.stream.IntStream;
import java.util.stream.Stream;
import masl.runtime.MissionProgram;
import masl.runtime.descriptor.AgentPath;
import masl.runtime.diagnostic.Diagnostic;
import masl.translator.MissionLoader;
import masl.translator.Translation;
import masl.translator.compile.GeneratedCodeException;
import masl.translator.diagnostics.Diagnostics;
import masl.translator.source.SourceFile;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/** The generated Java: names, structure, comments, and the constructs refused with a positioned error. */
class GeneratorTest {

    private static final Path CORPUS = Path.of("..", "masl-grammar", "src", "test", "resources", "corpus");

    private static final String E2 = """
            import Default.xml as Default;
            Default a, b, c, d, e = newAgent(Default);
            synchronous entry main (true) {
              shared int n = 0;
              local int mine = 0;
              n++;
              mine++;
              scalar entry report (true) { .logln("n=" + n); }
              .logln("mine=" + mine);
            }
            """;

    @Test
    void packageAndClassNamesComeFromTheFileName() {
        Translation hello = Programs.translate("missions/hello.masl", E2);
        assertEquals("masl.generated.hello.HelloMission", hello.missionClassName());
        assertEquals(List.of("masl.generated.hello.HelloMission", "masl.generated.hello.DefaultProgram"),
                List.copyOf(hello.javaSources().keySet()));
        assertEquals("masl.generated.my_run_2.MyRun2Mission",
                Programs.translate("My-Run 2.masl", E2).missionClassName());
        assertEquals("masl.generated._1st.M1stMission", Programs.translate("1st.masl", E2).missionClassName());
    }

    @Test
    void everyResumptionPointIsCommentedWithItsMaslLine() {
        String program = Programs.translate("e2.masl", E2).javaSources().get("masl.generated.e2.DefaultProgram");
        Matcher cases = Pattern.compile("(?m)^ *case \\d+:(.*)$").matcher(program);
        int count = 0;
        while (cases.find()) {
            count++;
            assertTrue(cases.group(1).matches(" // e2\\.masl:\\d+: .+"), "uncommented case: " + cases.group());
        }
        assertEquals(13, count, program);
        // §6.4: report, a scalar child of synchronous main, is one instruction of main
        assertTrue(program.contains("case 7: // e2.masl:8: end of report, one instruction of main\n"
                + "                    pc = 8;\n                    if (!ctx.endOfChild(REPORT)) return;\n"), program);
        assertTrue(program.contains("case 0: // e2.masl:3: synchronous entry main (true)"), program);
        assertTrue(program.contains("// e2.masl:6: n++;\n"), program);
        assertTrue(program.contains("ctx.shared(MAIN_N).getAndUpdate(n -> n + 1);"), program);
        assertTrue(program.contains("invokeSelf$logln(ctx, \"n=\" + ctx.shared(MAIN_N).get());"), program);
    }

    @Test
    void eachReactionHasACaseThatReactionPcNames() throws IOException {
        Translation e4 = Programs.translate("e4.masl", Files.readString(CORPUS.resolve(
                "e4-events-lookup-in-the-parent-resume.masl")));
        String mission = e4.javaSources().get("masl.generated.e4.E4Mission");
        assertTrue(mission.contains("static final Event MAIN_GO = MAIN.declareSharedEvent(\"go\");"), mission);
        assertTrue(mission.contains("static final Reaction MAIN_REACT_GO = MAIN.react(MAIN_GO);"), mission);
        String program = e4.javaSources().get("masl.generated.e4.DefaultProgram");
        Matcher reactionPc = Pattern.compile("if \\(reaction == MAIN_REACT_GO\\) \\{\\s+return (\\d+);").matcher(program);
        assertTrue(reactionPc.find(), program);
        String reaction = program.substring(program.indexOf("case " + reactionPc.group(1) + ": // e4.masl:"));
        assertTrue(reaction.startsWith("case " + reactionPc.group(1) + ": // e4.masl:17: react (go)"), reaction);
        assertTrue(reaction.contains("invokeSelf$logln(ctx, \"heard \" + ctx.messageOf(MAIN_GO));"), reaction);
        assertTrue(reaction.contains("if (!ctx.endReaction()) return;\n"), reaction);
        assertTrue(reaction.contains("if (!ctx.resumeInterrupted()) return;\n"), reaction);
        assertEquals(0, occurrences(reaction.substring(0, reaction.indexOf("default:")), "ctx.stepBoundary()"),
                "no step boundary in a reaction: " + reaction);
    }

    @Test
    void theMissionClassBuildsTheBlocksInProgramOrderAndDeclaresTheAgents() {
        String mission = Programs.translate("e2.masl", E2).javaSources().get("masl.generated.e2.E2Mission");
        int main = mission.indexOf("static final EntryDefinition MAIN = EntryDefinition.main(\"main\", Mode.SYNCHRONOUS);");
        int shared = mission.indexOf("static final SharedDeclaration<Integer> MAIN_N = MAIN.declareShared(\"n\", 0);");
        int report = mission.indexOf("static final EntryDefinition REPORT = MAIN.child(\"report\", Mode.SCALAR);");
        assertTrue(main >= 0 && main < shared && shared < report, mission);
        assertTrue(mission.contains("AGENTS = specs(\n            \"masl.agents.Default\",\n            \"a,b,c,d,e\");"), mission);
        assertTrue(mission.contains("for (int i = 0; i < 5; i++) {\n"
                + "            builder.agent(AGENTS.get(i).name(), (masl.agents.Default) population[i], Types.DEFAULT,"
                + " self -> new DefaultProgram(self, population));"),
                mission);
    }

    @Test
    void namesThatCountUpAreListedAsRangesEachAnAgentOfItsOwn() {
        Translation translation = Programs.translate("count.masl", "import Default.xml as Default;\n"
                + "Default a8, a9, a10, a11, b1, b2, x01, x02, x03, c, d5, d6, d7, d9 = newAgent(Default);\n"
                + "scalar entry main (true) { .logln(\"hi\"); }\n");
        String mission = translation.javaSources().get(translation.missionClassName());
        MissionProgram program = MissionLoader.load(translation, AgentPath.parse("")).program();

        assertTrue(mission.contains("\"a8..a11,b1,b2,x01,x02,x03,c,d5..d7,d9\""), mission);
        assertEquals(List.of("a8", "a9", "a10", "a11", "b1", "b2", "x01", "x02", "x03", "c", "d5", "d6", "d7", "d9"),
                program.agents().stream().map(MissionProgram.AgentSpec::name).toList());
    }

    @Test
    void tenThousandAgentsFitTheLimitsOfJavaMethodsAndConstants() {
        // Names that do not count up by one: the mission class lists each of them.
        String names = IntStream.range(0, 10_000).mapToObj(i -> "agent" + 2 * i)
                .collect(Collectors.joining(", "));
        Translation translation = Programs.translate("team.masl", "import Default.xml as Default;\n"
                + "Default lead = newAgent(Default);\n"
                + "Default " + names + " = newAgent(Default);\n"
                + "scalar entry main (true) { .logln(\"hi\"); }\n");
        MissionProgram mission = MissionLoader.load(translation, AgentPath.parse("")).program();

        assertEquals(10_001, mission.agents().size());
        assertEquals(new MissionProgram.AgentSpec("lead", "masl.agents.Default"), mission.agents().get(0));
        assertEquals(new MissionProgram.AgentSpec("agent19998", "masl.agents.Default"), mission.agents().get(10_000));
    }

    @Test
    void busyWaitsParkAndOtherLoopsOnlyYield() {
        String program = program("""
                shared int flag = 0;
                local int i = 0;
                LLabel l;
                while (flag != 1) {}
                while (i < 10) { i++; }
                while (System.currentTimeMillis() < 0) {}
                while (l.getRemainingInvocations() > 0 && !l.isFinished()) {}
                """);
        assertEquals(2, occurrences(program, "ctx.busyWaitIteration()"), program);
        assertEquals(2, occurrences(program, "ctx.loopIteration()"), program);
    }

    @Test
    void zeroDurationStatementsHaveNoStepBoundary() {
        String program = program("""
                .getProxyID();
                main.release();
                .nop();
                """);
        assertEquals(1, occurrences(program, "ctx.stepBoundary()"), program);
    }

    @Test
    void aCompoundAssignmentOfASharedVariableEvaluatesItsValueBeforeTakingTheLock() {
        String program = program("""
                shared int n = 0;
                n += .getProxyID() * 2;
                n = n * 2 + .getProxyID();
                """);
        assertTrue(program.contains("tmp$1 = invokeSelf$getProxyID(ctx) * 2;\n"), program);
        assertTrue(program.contains("ctx.shared(MAIN_N).update(n -> n + tmp$1);"), program);
        assertTrue(program.contains("ctx.shared(MAIN_N).update(n -> n * 2 + invokeSelf$getProxyID(ctx));"), program);
        assertTrue(program.contains("private int tmp$1;"), program);
    }

    @Test
    void anIfWhoseBranchesCannotSuspendIsAPlainJavaIf() {
        String program = program("if (main.count > 1) main.lock(); else main.release(2);");
        assertTrue(program.contains("if (ctx.entry(MAIN).count() > 1) {"), program);
        assertTrue(program.contains("} else {"), program);
    }

    @Test
    void anotherAgentsPrimitiveIsInvokedThenAwaitedInACaseOfItsOwn() {
        Translation translation = Programs.translate("ask.masl", """
                import Default.xml;
                Default a, b = newAgent(Default);
                synchronous entry main (true) {
                  local int seen = b.getProxyID() + .getProxyID();
                  seen = b.getProxyID();
                }
                """);
        assertTrue(translation.succeeded(), () -> translation.diagnostics().sorted().toString());
        String program = translation.javaSources().get("masl.generated.ask.DefaultProgram");
        assertTrue(program.contains("private final masl.agents.Default agent$b;"), program);
        assertTrue(program.contains("this.agent$b = (masl.agents.Default) agents[1];"), program);
        assertTrue(program.contains("tmp$1 = invoke$getProxyID(ctx, agent$b);\n"
                + "                    pc = 2;\n"
                + "                    if (!ctx.await(tmp$1)) return;\n"
                + "                case 2: // ask.masl:4: the result of b.getProxyID()\n"), program);
        assertTrue(program.contains("main$seen = tmp$1.join() + invokeSelf$getProxyID(ctx);"), program);
        assertTrue(program.contains("return ctx.invoke(callee, \"getProxyID\", 0, () -> callee.getProxyID());"),
                program);
        assertTrue(program.contains("return ctx.invokeSelf(\"getProxyID\", 0, () -> self.getProxyID());"), program);
        MissionLoader.load(translation, AgentPath.parse(""));
    }

    @Test
    void anInternalAccessorCallTakesNoStepBoundaryAnExternalOneDoes() {
        String program = program(".getProxyID();\nthis.getProxyID();\na.getProxyID();");
        assertEquals(1, occurrences(program, "ctx.stepBoundary()"), program);
    }

    @Test
    void anInitialiserCallingAnInstructionIsFollowedByItsStepBoundary() {
        Translation translation = Programs.translate("init.masl", """
                import robots/Khepera.xml;
                Khepera k, j = newAgent(Khepera);
                synchronous entry main (true) {
                  local int near = .getProximity(1);
                  local Vector2d where = .position();
                  shared int theirs = j.getProximity(2);
                }
                """);
        assertTrue(translation.succeeded(), () -> translation.diagnostics().sorted().toString());
        String program = translation.javaSources().get("masl.generated.init.KheperaProgram");
        // The internal accessor takes no time; .position() and the external invocation take a step each.
        assertEquals(2, occurrences(program, "ctx.stepBoundary()"), program);
        assertTrue(program.contains("main$where = invokeSelf$position(ctx);\n"
                + "                    pc = "), program);
        assertTrue(program.contains("case 4: // init.masl:5: after .position()"), program);
    }

    /**
     * A label's store into another agent's attribute names the owner and the attribute, so that the
     * runtime writes it where the owner runs (another JVM's for a deployed agent); in-process it is the
     * field write it always was.
     */
    @Test
    void aLabelsStoreIntoAnAttributeNamesItsOwnerAndTheAttribute() {
        Translation translation = Programs.translate("store.masl", """
                import robots/Khepera.xml;
                Khepera k, j = newAgent(Khepera);
                synchronous entry main (true) {
                  LLabel l;
                  l.j.battery = j.getProximity(1);
                }
                """);
        assertTrue(translation.succeeded(), () -> translation.diagnostics().sorted().toString());
        String program = translation.javaSources().get("masl.generated.store.KheperaProgram");
        assertTrue(program.contains("return new masl.runtime.AttributeStore<>(owner, \"battery\", value -> owner.battery"
                + " = value);"), program);
        MissionLoader.load(translation, AgentPath.parse(""));
    }

    @Test
    void unsupportedConstructsArePositionedErrors() {
        Translation translation = Programs.translate("wait.masl", """
                import Default.xml;
                Default a, b = newAgent(Default);
                asynchronous entry main (true) {
                  if (.getProxyID() == 0 && b.getProxyID() == 1) .nop();
                }
                """);
        assertFalse(translation.succeeded());
        assertNull(translation.missionClassName());
        assertTrue(translation.javaSources().isEmpty());
        List<Diagnostic> errors = translation.diagnostics().sorted();
        assertEquals(1, errors.size(), errors.toString());
        assertEquals("wait.masl:4:29: error: waiting for a result (an invocation of another agent, a future) in the right"
                + " operand of &&, is not supported yet by the translator", errors.get(0).headline());
    }

    static Stream<Path> corpus() throws IOException {
        try (Stream<Path> files = Files.list(CORPUS)) {
            return files.filter(file -> file.toString().endsWith(".masl")).sorted().toList().stream();
        }
    }

    /** Whatever the program, the translator compiles it or says what it cannot translate yet; it never crashes. */
    @ParameterizedTest
    @MethodSource("corpus")
    void everyCorpusProgramCompilesOrIsRefusedWithErrors(Path file) throws IOException {
        Translation translation = Programs.translate(file.getFileName().toString(), Files.readString(file));
        if (translation.succeeded()) {
            MissionLoader.load(translation, AgentPath.parse("")).program();
        } else {
            for (Diagnostic error : translation.diagnostics().sorted()) {
                assertTrue(error.message().endsWith(" is not supported yet by the translator"), error.headline());
            }
        }
    }

    @Test
    void javaThatDoesNotCompileIsAnInternalErrorNotTheUsersProblem() {
        Translation broken = new Translation(SourceFile.of("x.masl", ""), new Diagnostics(),
                "masl.generated.x.XMission", Map.of("masl.generated.x.XMission", "package masl.generated.x; class {"));
        assertThrows(GeneratedCodeException.class, () -> MissionLoader.load(broken, AgentPath.parse("")));
    }

    private static String program(String body) {
        Translation translation = Programs.translate("t.masl", "import Default.xml;\nDefault a = newAgent(Default);\n"
                + "synchronous entry main (true) {\n" + body + "\n}\n");
        assertTrue(translation.succeeded(), () -> translation.diagnostics().sorted().toString());
        MissionLoader.load(translation, AgentPath.parse(""));
        return translation.javaSources().get("masl.generated.t.DefaultProgram");
    }

    private static int occurrences(String text, String part) {
        int count = 0;
        for (int at = text.indexOf(part); at >= 0; at = text.indexOf(part, at + 1)) {
            count++;
        }
        return count;
    }
}
