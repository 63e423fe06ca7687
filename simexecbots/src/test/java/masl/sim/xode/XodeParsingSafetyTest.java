package masl.sim.xode;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.io.InputStream;
import java.util.Random;
import org.junit.jupiter.api.Test;

/** The parser never reaches outside the file, and no input makes the loader throw anything but XodeException. */
class XodeParsingSafetyTest {

    @Test
    void doctypeWithRemoteDtdIsIgnoredUnfetched() throws XodeException {
        LoadedModel model = Xode.load("<?xml version=\"1.0\"?>\n<!DOCTYPE xode SYSTEM \"http://example.invalid/xode.dtd\">\n"
                + "<xode version=\"1.0r23\"><world><space><body name=\"b\"/></space></world></xode>");
        assertEquals("b", model.body("b").getData());
    }

    @Test
    void externalEntityIsNeverExpanded() {
        String xml = "<?xml version=\"1.0\"?>\n<!DOCTYPE xode [<!ENTITY x SYSTEM \"file:///etc/passwd\">]>\n"
                + "<xode version=\"1.0r23\" name=\"&x;\"><world><space><body name=\"&x;\"/></space></world></xode>";
        XodeException e = Xode.failure(xml, LoadOptions.defaults());
        assertTrue(e.getMessage().contains("test.xode:3:"), e::getMessage);
        assertTrue(e.getMessage().contains("Undeclared general entity \"x\""), e::getMessage);
        assertFalse(e.getMessage().contains("root:"), e::getMessage);
    }

    @Test
    void randomBytesOnlyEverGiveXodeExceptions() {
        Random random = new Random(42);
        for (int i = 0; i < 300; i++) {
            byte[] bytes = new byte[random.nextInt(200)];
            random.nextBytes(bytes);
            expectOnlyXodeException(bytes, "random input " + i);
        }
    }

    @Test
    void everyTruncationOfARobotFileGivesAnXodeExceptionOrAModel() throws IOException {
        byte[] robot = resource("masl/agents/robots/wheeled-robot.xode");
        for (int length = 0; length < robot.length; length += 7) {
            expectOnlyXodeException(java.util.Arrays.copyOf(robot, length), "truncated at " + length);
        }
    }

    @Test
    void mutatedRobotFilesOnlyEverGiveXodeExceptions() throws IOException {
        byte[] robot = resource("masl/agents/robots/maam-atom.xode");
        Random random = new Random(7);
        byte[] alphabet = "<>/=\"' -.0123456789eEaxyz&;!?".getBytes(java.nio.charset.StandardCharsets.US_ASCII);
        for (int i = 0; i < 300; i++) {
            byte[] mutated = robot.clone();
            for (int j = 0; j < 3; j++) {
                mutated[random.nextInt(mutated.length)] = alphabet[random.nextInt(alphabet.length)];
            }
            expectOnlyXodeException(mutated, "mutation " + i);
        }
    }

    private static void expectOnlyXodeException(byte[] bytes, String what) {
        try {
            new XodeLoader().load(XodeSource.bytes("fuzz.xode", bytes));
        } catch (XodeException e) {
            assertTrue(e.getMessage().startsWith("fuzz.xode:"), () -> what + ": " + e.getMessage());
        } catch (RuntimeException | Error e) {
            fail(what + " threw " + e, e);
        }
    }

    private static byte[] resource(String path) throws IOException {
        try (InputStream in = XodeParsingSafetyTest.class.getClassLoader().getResourceAsStream(path)) {
            return in.readAllBytes();
        }
    }
}
