package masl.jade.placement;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.TimeUnit;
import masl.jade.MainContainerMain;
import masl.jade.TestPrograms;
import masl.jade.platform.JadeOptions;
import masl.jade.platform.JadeThreads;
import masl.jade.trust.MissionSecret;
import masl.runtime.MissionProgram;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * A {@link MaslContainer} whose main container's JVM is killed ends its mission at once, saying
 * why, instead of waiting for a coordinator's {@code masl-end} that will never come.
 */
@Timeout(120)
@Tag("slow")
class TwoJvmLostCoordinatorTest {

    @Test
    void aContainerWhoseMainContainerDiesEndsItsMissionSayingWhy() throws Exception {
        Process main = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-cp", System.getProperty("java.class.path"), MainContainerMain.class.getName())
                .redirectError(ProcessBuilder.Redirect.DISCARD)
                .start();
        try {
            String first = new BufferedReader(new InputStreamReader(main.getInputStream(), StandardCharsets.UTF_8))
                    .readLine();
            assertTrue(first != null && first.startsWith("port "), "the main container's JVM said " + first);
            int port = Integer.parseInt(first.substring("port ".length()));
            try (MaslContainer container = MaslContainer.start(JadeOptions.join("127.0.0.1", port), "c2",
                    className -> TestPrograms.type(new MissionProgram.AgentSpec("", className)),
                    getClass().getClassLoader(), event -> { }, MissionSecret.Source.of(MissionSecret.generate()))) {
                main.destroyForcibly();
                assertTrue(main.waitFor(30, TimeUnit.SECONDS));
                assertTrue(container.awaitMissionEnd(Duration.ofSeconds(30)), "the container noticed within 30 s");
                assertEquals(Optional.of("the platform's main container is gone"),
                        container.lostPlatform());
            }
            // A JADE thread may start another as its last act: wait for them to end, as the other tests do.
            assertEquals(List.of(), JadeThreads.awaitNone(Duration.ofSeconds(10)),
                    "JADE threads left 10 s after the container closed");
        } finally {
            main.destroyForcibly();
        }
    }
}
