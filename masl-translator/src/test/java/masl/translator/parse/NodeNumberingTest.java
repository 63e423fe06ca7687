package masl.translator.parse;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.BitSet;
import java.util.List;
import java.util.stream.Stream;
import masl.grammar.MaslRuleContext;
import masl.translator.diagnostics.Diagnostics;
import masl.translator.source.SourceFile;
import org.antlr.v4.runtime.tree.ParseTree;
import org.junit.jupiter.api.Test;

/**
 * The analysis keeps what it learns about each node in arrays indexed by the node's number: every rule
 * node of a parsed tree must have its own number, from 0 to {@code nodes - 1}, whichever way it was parsed.
 */
class NodeNumberingTest {

    private static final Path CORPUS = Path.of("..", "masl-grammar", "src", "test", "resources", "corpus");

    @Test
    void everyNodeOfTheCorpusProgramsHasItsOwnNumber() throws IOException {
        List<Path> programs;
        try (Stream<Path> files = Files.list(CORPUS)) {
            programs = files.filter(file -> file.toString().endsWith(".masl")).sorted().toList();
        }
        assertFalse(programs.isEmpty());
        for (Path program : programs) {
            ProgramParser.Parsed parsed = ProgramParser.parse(SourceFile.of(program.toString(), Files.readString(program)),
                    new Diagnostics());
            assertFalse(parsed.repaired(), program.toString());
            assertNumberedOnce(parsed, program.toString());
        }
    }

    @Test
    void aTreeRepairedAfterSyntaxErrorsIsNumberedToo() {
        Diagnostics diagnostics = new Diagnostics();
        ProgramParser.Parsed parsed = ProgramParser.parse(SourceFile.of("p.masl", """
                import Default.xml as Default;
                Default a, b = newAgent(Default);
                asynchronous entry main (true) {
                  local int x = (1 + ;
                  while (x < 3 { x++; }
                  .logln("x=" + x);
                }
                """), diagnostics);
        assertTrue(diagnostics.hasErrors());
        assertTrue(parsed.repaired());
        assertNumberedOnce(parsed, "p.masl");
    }

    private static void assertNumberedOnce(ProgramParser.Parsed parsed, String name) {
        BitSet seen = new BitSet();
        int nodes = visit(parsed.tree(), seen, parsed.nodes(), name);
        assertEquals(parsed.nodes(), nodes, name + ": nodes in the tree");
        assertEquals(parsed.nodes(), seen.cardinality(), name + ": distinct numbers");
    }

    private static int visit(ParseTree tree, BitSet seen, int bound, String name) {
        if (!(tree instanceof MaslRuleContext node)) {
            return 0;
        }
        int index = node.index();
        assertTrue(index >= 0 && index < bound, name + ": number " + index + " of " + node.getText());
        assertFalse(seen.get(index), name + ": number " + index + " given twice");
        seen.set(index);
        int count = 1;
        for (int i = 0; i < node.getChildCount(); i++) {
            count += visit(node.getChild(i), seen, bound, name);
        }
        return count;
    }
}
