package masl.grammar;
import org.junit.jupiter.api.Test;
import org.antlr.v4.runtime.*;
import static org.junit.jupiter.api.Assertions.*;
class SmokeTest {
  @Test void parses() {
    MASLParser p = new MASLParser(new CommonTokenStream(new MASLLexer(CharStreams.fromString(""))));
    p.program();
    assertEquals(0, p.getNumberOfSyntaxErrors());
  }
}
