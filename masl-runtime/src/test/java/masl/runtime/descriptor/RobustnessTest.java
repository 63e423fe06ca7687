package masl.runtime.descriptor;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Random;
import masl.runtime.diagnostic.Diagnostic;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Whatever the bytes, loading ends in a type or a DescriptorException with problems, never anything else. */
@Tag("slow")
class RobustnessTest {

    @TempDir
    Path folder;

    @Test
    void everyTruncationOfAValidDescriptor() throws IOException {
        byte[] valid = Files.readAllBytes(TestDescriptors.fixtureFolder().resolve("Khepera.xml"));
        int end = new String(valid, java.nio.charset.StandardCharsets.UTF_8).lastIndexOf("</Agent>") + "</Agent>".length();
        for (int length = 0; length < end; length++) {
            loadRejected(Arrays.copyOf(valid, length), "truncated to " + length + " bytes");
        }
    }

    @Test
    void randomBytes() throws IOException {
        Random random = new Random(20261122);
        for (int i = 0; i < 300; i++) {
            byte[] bytes = new byte[random.nextInt(400)];
            random.nextBytes(bytes);
            loadRejected(bytes, "random bytes #" + i);
        }
    }

    @Test
    void randomlyCorruptedValidDescriptor() throws IOException {
        byte[] valid = Files.readAllBytes(TestDescriptors.fixtureFolder().resolve("Khepera.xml"));
        Random random = new Random(42);
        for (int i = 0; i < 300; i++) {
            byte[] bytes = valid.clone();
            for (int flips = 1 + random.nextInt(4); flips > 0; flips--) {
                bytes[random.nextInt(bytes.length)] = (byte) random.nextInt(256);
            }
            loadEndsCleanly(bytes, "corruption #" + i);
        }
    }

    /** The decoder under the parser gives no position: the problem is placed at the first byte that is not UTF-8. */
    @Test
    void aByteThatIsNotUtf8IsReportedAtItsLineAndColumn() throws IOException {
        byte[] text = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<!-- é -->\n<Agent short_class_name=\"K?\"/>\n"
                .getBytes(StandardCharsets.UTF_8);
        int question = new String(text, StandardCharsets.ISO_8859_1).indexOf('?', 60);
        text[question] = (byte) 0xcb;
        try {
            load(text);
            fail("a descriptor that is not UTF-8 was accepted");
        } catch (DescriptorException expected) {
            Diagnostic problem = expected.problems().get(0);
            assertEquals(3, problem.line(), problem::toString);
            assertEquals(27, problem.column(), problem::toString);
        }
    }

    /** Content that cannot be a valid descriptor must give a DescriptorException with problems. */
    private void loadRejected(byte[] content, String what) throws IOException {
        try {
            load(content);
            fail(what + " was accepted");
        } catch (DescriptorException expected) {
            assertFalse(expected.problems().isEmpty(), what);
        }
    }

    /** A corruption may leave a valid descriptor (in a comment, say): a type or a DescriptorException. */
    private void loadEndsCleanly(byte[] content, String what) throws IOException {
        try {
            load(content);
        } catch (DescriptorException expected) {
            assertFalse(expected.problems().isEmpty(), what);
        }
    }

    private void load(byte[] content) throws IOException {
        Path file = folder.resolve("Khepera.xml");
        Files.write(file, content);
        // A fresh loader each time: the cache must not hide a re-read.
        TestDescriptors.loader().load(file);
    }
}
