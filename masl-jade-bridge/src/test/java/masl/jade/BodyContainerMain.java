package masl.jade;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import masl.jade.placement.MaslContainer;
import masl.jade.platform.JadeOptions;
import masl.jade.platform.JadePlatform;
import masl.jade.trust.MissionSecret;
import masl.runtime.MissionProgram;
import masl.testing.jade.SecondJvm;

/**
 * Run in a second JVM by the tests of missions spanning containers: joins the platform at
 * {@code host port} as container {@code name} (the mission's secret in file {@code secret}), hosts the bodies the coordinator asks for (test
 * agent types), prints each shared event it is sent and the bodies it hosted, and returns from {@code main} once the
 * coordinator says the mission ended (exit status 0), without {@code System.exit}: the JVM ends by
 * itself only if no thread is left. Exit status 3 if no mission ended within a minute.
 */
public final class BodyContainerMain {

    /** The secret of the missions whose bodies these containers host: give it to their launchers. */
    public static final MissionSecret SECRET = MissionSecret.generate();

    private BodyContainerMain() {
    }

    /**
     * Starts a second JVM running this as container {@code name} of {@code platform}, which finds
     * {@link #SECRET} in a file of its own.
     */
    public static SecondJvm start(JadePlatform platform, String name) throws IOException {
        Path folder = Files.createTempDirectory("masl-mission");
        Path secretFile = folder.resolve("secret");
        folder.toFile().deleteOnExit();
        secretFile.toFile().deleteOnExit();
        SECRET.writeTo(secretFile);
        return SecondJvm.start(BodyContainerMain.class, platform.host(), Integer.toString(platform.port()), name,
                secretFile.toString());
    }

    public static void main(String[] args) throws Exception {
        boolean ended;
        List<String> hosted;
        try (MaslContainer container = MaslContainer.start(JadeOptions.join(args[0], Integer.parseInt(args[1])),
                args[2], className -> TestPrograms.type(new MissionProgram.AgentSpec("", className)),
                BodyContainerMain.class.getClassLoader(),
                event -> System.out.println("event " + event.getContent()),
                MissionSecret.Source.file(Path.of(args[3])))) {
            ended = container.awaitMissionEnd(Duration.ofMinutes(1));
            hosted = container.hostedAgents();
        }
        System.out.println("hosted " + String.join(", ", hosted));
        System.out.println(ended ? "mission ended" : "no mission ended");
        if (!ended) {
            System.exit(3);
        }
    }
}
