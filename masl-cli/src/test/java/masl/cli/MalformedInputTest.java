package masl.cli;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Random bytes and truncated programs never make {@code masl check} fail with anything but
 * positioned errors: status 0 or 1, no internal error, no stack trace.
 */
class MalformedInputTest {

    private static final long SEED = 20261122L;

    @TempDir
    Path folder;

    @Test
    void randomBytes() throws IOException {
        Random random = new Random(SEED);
        for (int i = 0; i < 300; i++) {
            byte[] bytes = new byte[random.nextInt(200)];
            random.nextBytes(bytes);
            assertChecksCleanly(bytes, "random bytes #" + i + " of seed " + SEED);
        }
    }

    @Test
    void randomTokensOfTheLanguage() throws IOException {
        String[] words = {"import", "Default.xml", "as", "Default", "a", "=", "newAgent", "(", ")", ";", "{", "}",
            "synchronous", "scalar", "asynchronous", "entry", "main", "true", ".log", "\"x\"", "local", "shared",
            "int", "event", "react", "default", "resume", "break", "reelect", "emit", "LLabel", "l", ".", "+", "1",
            "while", "if", "else", "do", "loop", "exit", "wait", "getAcceptState", "Entry", ",", "this", "new"};
        Random random = new Random(SEED);
        for (int i = 0; i < 300; i++) {
            StringBuilder program = new StringBuilder();
            for (int n = random.nextInt(60); n > 0; n--) {
                program.append(words[random.nextInt(words.length)]).append(random.nextInt(8) == 0 ? "\n" : " ");
            }
            assertChecksCleanly(program.toString().getBytes(StandardCharsets.UTF_8), "token soup #" + i + ":\n" + program);
        }
    }

    @Test
    void everyPrefixOfAnExample() throws IOException {
        String example;
        try (InputStream in = MalformedInputTest.class.getResourceAsStream("/corpus/every-production.masl")) {
            example = new String(in.readAllBytes(), StandardCharsets.UTF_8);
        }
        for (int length = 0; length < example.length(); length += 7) {
            assertChecksCleanly(example.substring(0, length).getBytes(StandardCharsets.UTF_8),
                    "prefix of length " + length);
        }
    }

    private void assertChecksCleanly(byte[] bytes, String what) throws IOException {
        Path program = folder.resolve("fuzz.masl");
        Files.write(program, bytes);
        CheckCommandTest.Run run = CheckCommandTest.Run.of("check", program.toString());
        assertTrue(run.status() == 0 || run.status() == 1, what + " gave status " + run.status() + ": " + run.err());
        assertFalse(run.err().contains("\tat "), what + " printed a stack trace: " + run.err());
        assertFalse(run.err().contains("internal error"), what + ": " + run.err());
    }
}
