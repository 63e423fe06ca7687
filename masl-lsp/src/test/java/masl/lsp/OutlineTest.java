package masl.lsp;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;
import org.eclipse.lsp4j.DocumentSymbol;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/** Document symbols: the types, the agents, then the block tree with declarations and reactions. */
class OutlineTest {

    private final Editor editor = new Editor();

    @AfterEach
    void close() {
        editor.close();
    }

    /** Each symbol as {@code indentation name (detail)}, depth first. */
    private static List<String> lines(List<DocumentSymbol> symbols, String indentation) {
        List<String> lines = new ArrayList<>();
        for (DocumentSymbol symbol : symbols) {
            lines.add(indentation + symbol.getName() + (symbol.getDetail() == null ? "" : " (" + symbol.getDetail() + ")"));
            lines.addAll(lines(symbol.getChildren(), indentation + "  "));
        }
        return lines;
    }

    @Test
    void theBlockTreeIsTheOutline() {
        editor.open(Programs.team(""));
        assertEquals(List.of(
                "Default (Default.xml)",
                "Rover (SoftWheeledRobot.xml)",
                "leader (agent Default)",
                "r1 (agent Rover)",
                "r2 (agent Rover)",
                "main (asynchronous (true))",
                "  total (shared int)",
                "  go (shared event)",
                "  calls (SLabel)",
                "  work (asynchronous (.getProxyID() > 0))",
                "    distance (local double)",
                "    done (local event)",
                "    inner (synchronous (total < 3))",
                "      steps (local int)",
                "  other (scalar (true))",
                "    hidden (local int)",
                "  react(go)"), lines(editor.symbols(), ""));
    }

    @Test
    void aBlockSpansItsBracesAndIsSelectedAtItsName() {
        editor.open(Programs.team(""));
        DocumentSymbol main = editor.symbols().get(5);
        DocumentSymbol work = main.getChildren().get(3);
        assertEquals(editor.startOf("asynchronous entry work"), work.getRange().getStart());
        assertEquals(editor.startOf("work (.get"), work.getSelectionRange().getStart());
        assertEquals(editor.startOf("  scalar entry other").getLine() - 1, work.getRange().getEnd().getLine());
    }

    @Test
    void anUnclosedBlockStillHasItsPlaceWhileBeingTyped() {
        editor.open("import Default.xml;\nDefault a = newAgent(Default);\nasynchronous entry main (true) {\n"
                + "  scalar entry first (true) {\n    .nop();\n");
        List<String> outline = lines(editor.symbols(), "");
        assertEquals(List.of("Default (Default.xml)", "a (agent Default)", "main (asynchronous (true))",
                "  first (scalar (true))"), outline);
    }
}
