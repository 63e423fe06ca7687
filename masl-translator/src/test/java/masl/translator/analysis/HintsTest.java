package masl.translator.analysis;

import static masl.translator.analysis.Analysis.analyze;
import static masl.translator.analysis.Analysis.analyzeBody;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * "Did you mean …?" as a good compiler says it: for a misspelt member, variable, event, entry
 * member, type, agent type, descriptor or keyword, the nearest name that would have been found,
 * and nothing when no name is near.
 */
class HintsTest {

    @Test
    void aMisspeltPrimitive() {
        analyzeBody(".logn(\"x\");").assertError(7, 2,
                "cannot find primitive logn in any imported agent type; did you mean `logln`?");
    }

    @Test
    void aMisspeltAttribute() {
        analyzeBody("k.MAX_SPED = 1.0;").assertError(7, 3,
                "cannot find attribute MAX_SPED in any imported agent type; did you mean `MAX_SPEED`?");
    }

    @Test
    void aMisspeltVariable() {
        analyzeBody("local int count = 0;\ncuont++;").assertError(8, 1, "cannot find symbol cuont; did you mean `count`?");
    }

    @Test
    void aMisspeltAgent() {
        analyzeBody("kk.nop();").assertError(7, 1, "cannot find symbol kk; did you mean `k`?");
    }

    @Test
    void aMisspeltEvent() {
        analyzeBody("shared event ready;\nemit(raedy);").assertError(8, 6, "cannot find event raedy; did you mean `ready`?");
    }

    @Test
    void aMisspeltEntryMember() {
        analyzeBody("local int n = main.getActivCount();").assertError(7, 20,
                "entry main has no member getActivCount; did you mean `getActiveCount`?");
    }

    @Test
    void aMisspeltType() {
        analyzeBody("local Strng s = \"\";").assertError(7, 7, "cannot find type Strng; did you mean `String`?");
    }

    @Test
    void aMisspeltAgentType() {
        analyze("import Default.xml;\nDefualt d = newAgent(Default);\n")
                .assertError(2, 1, "cannot find agent type Defualt; did you mean `Default`?");
    }

    @Test
    void aMisspeltDescriptorSaysWhereItLookedAndTheNearestFile() {
        String message = analyze("import robots/Kepera.xml;\n").rendered();
        assertTrue(message.startsWith("test.masl:1:8: error: cannot find descriptor robots/Kepera.xml: looked in "
                + "the program's folder "), message);
        assertTrue(message.endsWith(" and the descriptors shipped with masl; did you mean `robots/Khepera.xml`?"), message);
    }

    @Test
    void aMisspeltShippedDescriptorIsFoundAmongTheShippedOnes() {
        String message = analyze("import Defautl.xml;\n").rendered();
        assertTrue(message.endsWith("; did you mean `Default.xml`?"), message);
    }

    @Test
    void noHintWhenNothingIsNear() {
        analyzeBody(".fly();").assertError(7, 2, "cannot find primitive fly in any imported agent type");
        analyzeBody("zzzzzz++;").assertError(7, 1, "cannot find symbol zzzzzz");
    }

    @Test
    void aMisspeltModeKeywordIsOneErrorWithAHint() {
        Analysis.Result result = analyze("import Default.xml;\nDefault d = newAgent(Default);\n"
                + "synchronus entry main (true) {\n    .logln(\"x\");\n}\n");
        assertEquals("test.masl:3:1: error: unknown mode synchronus; did you mean `synchronous`?", result.rendered());
    }
}
