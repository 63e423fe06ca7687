package masl.translator.analysis;

import static masl.translator.analysis.Analysis.analyze;
import static masl.translator.analysis.Analysis.analyzeBody;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import org.junit.jupiter.api.Test;

/** Errors that depend on where a statement or a declaration stands (MASL §3, §6.4–§6.7, §7, §8, §12). */
class BlockErrorsTest {

    @Test
    void breakMustNameAnEnclosingBlock() {
        analyzeBody("""
                asynchronous entry a (true) { }
                asynchronous entry b (true) { break(a); }""")
                .assertError(8, 37, "break(a): a is not an enclosing block");
    }

    @Test
    void reelectMustNameAnEnclosingBlock() {
        analyzeBody("reelect(nowhere);").assertError(7, 9, "reelect(nowhere): nowhere is not an enclosing block");
    }

    @Test
    void breakCannotLeaveMoreBlocksThanEncloseIt() {
        analyzeBody("asynchronous entry a (true) { break(3); }")
                .assertError(7, 37, "break(3) leaves 3 blocks but only 2 enclose it");
    }

    @Test
    void reelectCannotLeaveMoreBlocksThanEncloseIt() {
        analyzeBody("reelect(2);").assertError(7, 9, "reelect(2) leaves 2 blocks but only 1 encloses it");
    }

    @Test
    void breakInAReactionCountsFromTheReactionsBlock() {
        analyzeBody("""
                shared event go;
                asynchronous entry a (true) { react (go) { break(2); } }
                react (go) { break(2); }""")
                .assertError(9, 20, "break(2) leaves 2 blocks but only 1 encloses it");
    }

    @Test
    void jumpCountsAreReadAsJavaIntegerLiterals() {
        analyzeBody("asynchronous entry a (true) { break(0b10); reelect(0x2); break(0b11); }")
                .assertError(7, 64, "break(0b11) leaves 0b11 blocks but only 2 enclose it");
    }

    @Test
    void exitOutsideALoopIsReported() {
        analyzeBody("exit;").assertError(7, 1, "exit outside a loop");
    }

    @Test
    void exitCannotLeaveMoreLoopsThanEncloseIt() {
        analyzeBody("while (true) { do { exit(2); } loop for (;;) exit(3); }")
                .assertError(7, 51, "exit(3) leaves 3 loops but only 2 enclose it");
    }

    @Test
    void resumeOutsideAReactionIsReported() {
        analyzeBody("resume;").assertError(7, 1, "resume can only be used in a reaction");
    }

    @Test
    void clearEventsOutsideAReactionIsReported() {
        analyzeBody("react (default) { clearEvents; }\nclearEvents();")
                .assertError(8, 1, "clearEvents can only be used in a reaction");
    }

    @Test
    void nonScalarBlockInsideAScalarBlockIsReported() {
        analyzeBody("scalar entry s (true) { scalar entry t (true) { } synchronous entry u (true) { } }")
                .assertError(7, 51,
                        "a synchronous block cannot be nested in scalar block s: only scalar blocks may be");
    }

    @Test
    void nameVisibleFromAnEnclosingBlockCannotBeRedeclared() {
        analyzeBody("local int x;\nasynchronous entry a (true) { local double x; }")
                .assertError(8, 44, "x is already declared in enclosing block main");
    }

    @Test
    void nameDeclaredTwiceInABlockIsReported() {
        analyzeBody("local int x;\nshared event x;").assertError(8, 14, "x is already declared in block main");
    }

    @Test
    void sameNameInSiblingBlocksIsFine() {
        analyzeBody("asynchronous entry a (true) { local int x; }\nasynchronous entry b (true) { LLabel x; }")
                .assertNoError();
    }

    @Test
    void agentAndSystemEventNamesCannotBeRedeclared() {
        Analysis.Result result = analyzeBody("local int k;\nlocal event timeout;");
        assertEquals("""
                test.masl:7:11: error: k is already declared as an agent
                test.masl:8:13: error: timeout is already declared as a system event""", result.rendered());
    }

    @Test
    void entryNamesAreUniqueInAProgram() {
        analyzeBody("asynchronous entry a (true) { }\nif (true) { asynchronous entry a (true) { } }")
                .assertError(8, 32, "entry name a is already used by another block");
    }

    @Test
    void declarationAfterAnInstructionIsReported() {
        analyzeBody(".nop();\nlocal int x = 0;")
                .assertError(8, 1, "declarations must come before the instructions and reactions of block main");
    }

    @Test
    void emitOfAnEventNotInScopeIsReported() {
        analyzeBody("asynchronous entry a (true) { local event go; }\nemit(go);")
                .assertError(8, 6, "cannot find event go");
    }

    @Test
    void emitOfANameThatIsNotAnEventIsReported() {
        analyzeBody("local int x;\nemitWithMessage(x, \"now\");").assertError(8, 17, "x is not an event");
    }

    @Test
    void unknownEventIsReportedAtItsFirstUseOnly() {
        analyzeBody("emit(go);\nemit(go);\nreact (go) { .logln(getMessageFromEvent(go)); }")
                .assertError(7, 6, "cannot find event go");
    }

    @Test
    void reactionToAnUnknownEventIsReported() {
        analyzeBody("react (go) { resume; }").assertError(7, 8, "cannot find event go");
    }

    @Test
    void systemEventsAreDeclaredEverywhere() {
        analyzeBody("""
                react (timeout) { resume; }
                react (uncaught_exception) { .logln(getMessageFromEvent(uncaught_exception)); }
                react (forbidden_access) { emit(timeout); }""").assertNoError();
    }

    @Test
    void twoReactionsToTheSameEventInABlockAreReported() {
        analyzeBody("react (timeout) { resume; }\nreact (timeout) { restart; }")
                .assertError(8, 1, "block main already reacts to timeout");
    }

    @Test
    void entryMembersNeedAnEntryDeclaration() {
        analyzeBody("asynchronous entry team (true) { }\n.logln(\"\" + team.count + main.count);")
                .assertError(8, 13, "entry team is not declared: add 'Entry team;' to use its members");
    }

    @Test
    void entryBlockInsideAReactionIsReported() {
        analyzeBody("react (timeout) { asynchronous entry a (true) { } }")
                .assertError(7, 19, "entry block a cannot stand in a reaction");
    }

    @Test
    void threeUnrelatedErrorsAreAllReported() {
        Analysis.Result result = analyzeBody("exit;\nresume;\nlocal int x = 0;");
        assertEquals("""
                test.masl:7:1: error: exit outside a loop
                test.masl:8:1: error: resume can only be used in a reaction
                test.masl:9:1: error: declarations must come before the instructions and reactions of block main""",
                result.rendered());
    }

    @Test
    void errorsOfDifferentKindsAreAllReported() {
        Analysis.Result result = analyze("""
                import robots/Nope.xml;
                import Default.xml;
                Default a = newAgent(Default);
                asynchronous entry main ("x") {
                  resume;
                }
                """);
        assertEquals("test.masl:1:8: error: cannot find descriptor robots/Nope.xml: looked in the program's folder "
                + Analysis.FIXTURES + " and the descriptors shipped with masl\n" + """
                test.masl:4:26: error: the test of entry main must be boolean or numeric, found String
                test.masl:5:3: error: resume can only be used in a reaction""", result.rendered());
    }

    @Test
    void programWithoutBlockOnlyCreatesAgents() {
        Analysis.Result result = analyze(Analysis.HEADERS);
        result.assertNoError();
        assertNull(result.program().root());
    }
}
