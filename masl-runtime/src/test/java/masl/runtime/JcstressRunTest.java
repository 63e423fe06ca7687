package masl.runtime;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * The suite's short run of the jcstress tests in {@code src/jcstress} (the parking word, a
 * barrier's arrivals against each other and against a join, a label's store, count and
 * registration): one iteration of each, in a JVM of jcstress's own, every outcome checked against
 * the outcomes the test allows. {@code gradle jcstress} runs them at length.
 */
@Tag("slow")
class JcstressRunTest {

    private static final Pattern RESULTS = Pattern.compile(
            "\\(Results: (\\d+) planned; (\\d+) passed, (\\d+) failed, (\\d+) soft errs, (\\d+) hard errs\\)");

    @Test
    @Timeout(value = 5, unit = TimeUnit.MINUTES)
    void everyOutcomeOfEveryRaceIsOneItsContractAllows() throws IOException, InterruptedException {
        String classPath = System.getProperty("masl.jcstress.classpath");
        assertNotNull(classPath, "the build passes the jcstress class path");
        Path results = Files.createDirectories(Path.of(System.getProperty("masl.jcstress.results")));
        Path log = results.resolve("output.txt");
        Process jcstress = new ProcessBuilder(List.of(
                Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-cp", classPath, "org.openjdk.jcstress.Main",
                "-m", "sanity", "-f", "1", "-iters", "1", "-time", "200", "-sc", "false",
                "-jvmArgs", "-Xmx256m", "-r", results.resolve("report").toString()))
                .directory(results.toFile())
                .redirectErrorStream(true)
                .redirectOutput(log.toFile())
                .start();
        assertTrue(jcstress.waitFor(4, TimeUnit.MINUTES), "jcstress ended");
        String output = Files.readString(log, StandardCharsets.UTF_8);
        Matcher last = null;
        for (Matcher m = RESULTS.matcher(output); m.find(); ) {
            last = RESULTS.matcher(m.group());
            last.matches();
        }
        assertNotNull(last, "jcstress reported its results:\n" + output);
        int planned = Integer.parseInt(last.group(1));
        assertTrue(planned >= 7, "every jcstress test ran: " + last.group());
        assertEquals(planned, Integer.parseInt(last.group(2)), "every run passed, see " + log + ": " + last.group());
        assertEquals(0, jcstress.exitValue(), "jcstress's status, see " + log);
    }
}
