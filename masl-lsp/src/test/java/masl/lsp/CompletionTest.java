package masl.lsp;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.eclipse.lsp4j.CompletionItem;
import org.eclipse.lsp4j.InsertTextFormat;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/** Completion: what the editor offers after a dot, in a jump, in an emit, and among plain names. */
class CompletionTest {

    private final Editor editor = new Editor();

    @AfterEach
    void close() {
        editor.close();
    }

    @Test
    void afterADotTheCurrentAgentsPrimitivesOfEveryTypeWithTheirSignatures() {
        editor.open(Programs.team(".‸"));
        assertEquals("void log(String message)", editor.completion("log").getDetail());
        assertEquals("int getProxyID()", editor.completion("getProxyID").getDetail());
        CompletionItem moveForward = editor.completion("moveForward");
        assertEquals("double moveForward(double distance)", moveForward.getDetail());
        assertEquals("Rover", moveForward.getLabelDetails().getDescription());
        assertEquals("Default, Rover", editor.completion("log").getLabelDetails().getDescription());
        assertFalse(editor.completionLabels().contains("while"), "no keyword after a dot");
    }

    @Test
    void afterAnAgentsNameThePrimitivesAndAttributesOfItsType() {
        editor.open(Programs.team("r1.‸"));
        assertEquals("boolean calibrate()", editor.completion("calibrate").getDetail());
        assertEquals("static final int MOVE_COST = 5", editor.completion("MOVE_COST").getDetail());
        editor.open(Programs.team("leader.‸"));
        assertFalse(editor.completionLabels().contains("calibrate"), editor.completionLabels().toString());
        assertTrue(editor.completionLabels().contains("logln"));
    }

    @Test
    void theTypedPrefixDoesNotChangeWhatIsOffered() {
        editor.open(Programs.team("this.lo‸"));
        assertTrue(editor.completionLabels().containsAll(List.of("log", "logln")), editor.completionLabels().toString());
    }

    @Test
    void afterADeclaredBlocksNameItsEntryMembers() {
        editor.open(Programs.team("work.‸"));
        List<String> labels = editor.completionLabels();
        assertTrue(labels.containsAll(List.of("count", "getList", "getActiveCount", "getWaitingInCount", "getLockPolicy",
                "lock", "release")), labels.toString());
        assertFalse(labels.contains("log"), labels.toString());
        assertEquals("int getActiveCount()", editor.completion("getActiveCount").getDetail());
        editor.open(Programs.team("main.‸"));
        assertTrue(editor.completionLabels().contains("getList"), editor.completionLabels().toString());
        editor.open(Programs.team("other.‸"));
        assertEquals(List.of(), editor.completionLabels(), "other is not declared with Entry");
    }

    @Test
    void inABreakTheBlocksAroundTheCursorInnermostFirst() {
        editor.open(Programs.team("break(‸"));
        assertEquals(List.of("inner", "work", "main"), editor.completionLabels());
        assertEquals("synchronous entry inner", editor.completion("inner").getDetail());
        editor.open(Programs.team("reelect(w‸"));
        assertEquals(List.of("inner", "work", "main"), editor.completionLabels());
    }

    @Test
    void plainNamesAreTheVariablesEventsAndLabelsInScopeTheAgentsAndTheKeywords() {
        editor.open(Programs.team("‸"));
        List<String> labels = editor.completionLabels();
        assertTrue(labels.containsAll(List.of("steps", "distance", "done", "total", "go", "calls", "leader", "r1",
                "timeout", "main", "work", "Rover", "while", "emit", "synchronous")), labels.toString());
        assertFalse(labels.contains("hidden"), "a sibling block's variable is out of scope: " + labels);
        assertEquals("local double distance", editor.completion("distance").getDetail());
    }

    @Test
    void inAnEmitOrAReactionTheEventsInScope() {
        editor.open(Programs.team("emit(‸"));
        assertEquals(List.of("done", "go", "timeout", "uncaught_exception", "forbidden_access"), editor.completionLabels());
        editor.open(Programs.team("emitWithMessage(‸"));
        assertTrue(editor.completionLabels().contains("done"));
    }

    @Test
    void afterALabelItsMembersTheAgentsAndThePrimitivesItLaunches() {
        editor.open(Programs.team("calls.‸"));
        List<String> labels = editor.completionLabels();
        assertTrue(labels.containsAll(List.of("isFinished", "free", "this", "r1", "calibrate", "log")), labels.toString());
        editor.open(Programs.team("calls.r1.‸"));
        assertTrue(editor.completionLabels().contains("calibrate"), editor.completionLabels().toString());
        assertFalse(editor.completionLabels().contains("isFinished"));
    }

    @Test
    void aVariableOfAnAgentTypeOrAnElementOfAnArrayOfThem() {
        editor.open(Programs.team("r1.stop();\n").replace("local int steps = 0;",
                "local int steps = 0;\n      local Rover[] team = null;\n      local Rover one = null;\n      one.‸"));
        assertTrue(editor.completionLabels().contains("calibrate"), editor.completionLabels().toString());
        editor.open(Programs.team("").replace("local int steps = 0;",
                "local Rover[] team = null;\n      team[0].‸"));
        assertTrue(editor.completionLabels().contains("calibrate"), editor.completionLabels().toString());
    }

    @Test
    void nothingInsideAStringOrAComment() {
        editor.open(Programs.team(".logln(\"a.‸\");"));
        assertEquals(List.of(), editor.completionLabels());
        editor.open(Programs.team("// see .‸"));
        assertEquals(List.of(), editor.completionLabels());
    }

    @Test
    void amongTheHeadersTheHeaderWordsAndTheTypes() {
        editor.open(Programs.TEAM.replace("Entry work;", "Entry work;\n‸"));
        List<String> labels = editor.completionLabels();
        assertTrue(labels.containsAll(List.of("import", "Entry", "asynchronous", "Rover")), labels.toString());
        assertFalse(labels.contains("while"), labels.toString());
        editor.open(Programs.TEAM.replace("newAgent(Rover)", "newAgent(‸)"));
        assertEquals(List.of("Default", "Rover"), editor.completionLabels());
    }

    @Test
    void aClientWithSnippetsGetsTheParentheses() {
        try (Editor snippets = new Editor(true)) {
            snippets.open(Programs.team(".lo‸"));
            CompletionItem logln = snippets.completion("logln");
            assertEquals("logln($1)$0", logln.getInsertText());
            assertEquals(InsertTextFormat.Snippet, logln.getInsertTextFormat());
            assertEquals("nop()$0", snippets.completion("nop").getInsertText());
        }
    }
}
