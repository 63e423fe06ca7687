package masl.translator.generate;

import static org.junit.jupiter.api.Assertions.assertTrue;

import masl.runtime.descriptor.AgentPath;
import masl.translator.MissionLoader;
import masl.translator.Translation;
import org.junit.jupiter.api.Test;

/**
 * A class file holds at most 65,535 constants. The constants of a block's statements go to the parts
 * of the split state machine, each a class with a pool of its own, so the program class's pool grows
 * with the parts, not with the statements: a block of 70,000 statements was javac's "too many
 * constants" in the program class, where each statement cost a synthetic accessor of {@code pc}.
 */
class ConstantPoolTest {

    @Test
    void theProgramClassPoolGrowsWithThePartsNotWithTheStatements() {
        int fewer = programClassConstants(1_000);
        int more = programClassConstants(3_000);

        assertTrue(more - fewer < (3_000 - 1_000) / 10,
                "2,000 statements more cost the program class " + (more - fewer) + " constants (" + fewer + ", then " + more + ")");
    }

    /** The constant pool's size in the program class of a block of {@code statements} assignments of distinct constants. */
    private static int programClassConstants(int statements) {
        StringBuilder program = new StringBuilder("import Default.xml as Default;\nDefault a = newAgent(Default);\n"
                + "scalar entry main (true) {\n  local int x = 0;\n");
        for (int i = 0; i < statements; i++) {
            program.append("  x = ").append(100_000 + i).append(";\n");
        }
        program.append("  .logln(x);\n}\n");
        Translation translation = Programs.translate("pool.masl", program.toString());
        assertTrue(translation.succeeded(), () -> translation.diagnostics().sorted().toString());
        byte[] programClass = MissionLoader.load(translation, AgentPath.parse("")).classFiles().get("masl.generated.pool.DefaultProgram");
        // JVMS 4.1: magic (4 bytes), minor and major version (2 each), then constant_pool_count (u2).
        return ((programClass[8] & 0xff) << 8) | (programClass[9] & 0xff);
    }
}
