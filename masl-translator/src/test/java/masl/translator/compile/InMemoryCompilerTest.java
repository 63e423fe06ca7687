package masl.translator.compile;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/** The class loader of a program's compiled classes ({@link InMemoryCompiler#loaderOf}). */
class InMemoryCompilerTest {

    private static final String NAME = "masl.generated.p.Which";

    /**
     * A class of the same name on the class path or agent path (here: in the parent loader) does not
     * stand in for the class the program was compiled to; the parent's other classes are still found.
     */
    @Test
    void theProgramsOwnClassesAreDefinedByItsLoaderWhateverTheParentHolds() throws Exception {
        ClassLoader parent = InMemoryCompiler.loaderOf(compiled(
                new InMemoryCompiler.Source(NAME, which("impostor")),
                new InMemoryCompiler.Source("masl.generated.p.Helper", "package masl.generated.p; public class Helper { }")),
                getClass().getClassLoader());
        ClassLoader program = InMemoryCompiler.loaderOf(compiled(new InMemoryCompiler.Source(NAME, which("compiled"))), parent);

        Class<?> which = Class.forName(NAME, true, program);

        assertEquals("compiled", which.getConstructor().newInstance().toString());
        assertSame(program, which.getClassLoader());
        assertSame(parent, Class.forName("masl.generated.p.Helper", false, program).getClassLoader());
        assertSame(String.class, Class.forName("java.lang.String", false, program));
    }

    private static String which(String text) {
        return "package masl.generated.p; public class Which { public String toString() { return \"" + text + "\"; } }";
    }

    private static Map<String, byte[]> compiled(InMemoryCompiler.Source... sources) {
        return new InMemoryCompiler(List.of()).compileToBytes(List.of(sources));
    }
}
