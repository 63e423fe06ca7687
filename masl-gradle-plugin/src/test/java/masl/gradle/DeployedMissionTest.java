package masl.gradle;

import static masl.gradle.UserBuild.gradle;
import static masl.gradle.UserBuild.write;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.stream.Stream;
import org.gradle.testkit.runner.BuildResult;
import org.gradle.testkit.runner.TaskOutcome;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A mission deployed from users' builds: the sample's agent type and mission in two projects, a
 * robot's, whose {@code maslContainer} hosts the agents, and a base station's, whose {@code maslRun}
 * starts the platform and deploys the team on the robot's container. One build runs both tasks at
 * once ({@code --parallel}), as two machines would run their builds: each waits for the other (the
 * container for the platform, the run for the container) for 30 s.
 */
@Tag("slow")
class DeployedMissionTest {

    private static final Path SAMPLE = Path.of(System.getProperty("masl.samples"), "counter-team");

    @TempDir
    Path build;

    @Test
    void theBaseStationsRunDeploysTheTeamOnTheRobotsContainerAndPrintsTheJournal() throws IOException {
        write(build.resolve("settings.gradle"), UserBuild.SETTINGS + "include 'robot', 'base'\n");
        copySampleTo(build.resolve("robot"));
        copySampleTo(build.resolve("base"));
        // Both tasks start at once: neither waits for the other's compilation.
        gradle(build, "-q", "classes").build();
        int port = freePort();
        Path secret = build.resolve("mission.secret");

        BuildResult result = gradle(build, "--parallel", "--max-workers=2", ":robot:maslContainer", ":base:maslRun",
                "-Pcontainer=c2", "-PmainHost=127.0.0.1", "-PmainPort=" + port, "-Ptimeout=120",
                "-Pplatform=jade", "-Pport=" + port, "-Pdeploy=*=c2", "-PsecretFile=" + secret).build();

        assertEquals(TaskOutcome.SUCCESS, result.task(":robot:maslContainer").getOutcome());
        assertEquals(TaskOutcome.SUCCESS, result.task(":base:maslRun").getOutcome());
        String output = result.getOutput();
        assertTrue(output.contains("total=9"), output);
        // The container ran every agent's program, and says so once the mission ended.
        assertTrue(output.contains("masl-ended hosted a,b,c"), output);
        assertTrue(output.contains("masl: container ready: name=c2"), output);
        assertFalse(Files.exists(secret), "the run deletes the mission's secret at its end");
    }

    @Test
    void aDeploymentWithoutJadeFailsTheRunWithMaslsReason() throws IOException {
        copySampleTo(build);
        write(build.resolve("settings.gradle"), UserBuild.SETTINGS + "rootProject.name = 'counter-team'\n");

        BuildResult result = gradle(build, "maslRun", "-Pdeploy=*=c2").buildAndFail();

        assertTrue(result.getOutput().contains("mission count failed: --place, --deploy"), result.getOutput());
        assertTrue(result.getOutput().contains("(masl exit status 64: masl was called wrongly)"), result.getOutput());
    }

    /** 203.0.113.1 is of TEST-NET-3, never a machine's own address: masl refuses it, and says so. */
    @Test
    void bothTasksListenOnTheAddressAskedWhichMaslChecks() throws IOException {
        copySampleTo(build);
        write(build.resolve("settings.gradle"), UserBuild.SETTINGS + "rootProject.name = 'counter-team'\n");
        String refused = " failed: --local-host 203.0.113.1 is not an address of this machine: give the one the other"
                + " machines reach it at (masl exit status 64: masl was called wrongly)";

        BuildResult run = gradle(build, "maslRun", "-Pplatform=jade", "-PlocalHost=203.0.113.1").buildAndFail();
        assertTrue(run.getOutput().contains("mission count" + refused), run.getOutput());

        BuildResult container = gradle(build, "maslContainer", "-Pcontainer=c2", "-PmainHost=127.0.0.1", "-PmainPort=1099",
                "-PlocalHost=203.0.113.1").buildAndFail();
        assertTrue(container.getOutput().contains("container c2" + refused), container.getOutput());
    }

    @Test
    void aContainerWithoutAPlatformToJoinFailsSayingWhatItNeeds() throws IOException {
        copySampleTo(build);
        write(build.resolve("settings.gradle"), UserBuild.SETTINGS + "rootProject.name = 'counter-team'\n");

        BuildResult unnamed = gradle(build, "maslContainer").buildAndFail();
        assertTrue(unnamed.getOutput().contains("say which container this is with -Pcontainer=NAME"), unnamed.getOutput());

        BuildResult nowhere = gradle(build, "maslContainer", "-Pcontainer=c2").buildAndFail();
        assertTrue(nowhere.getOutput().contains("container c2 failed: masl container needs --main-host, --main-port and --name"
                + " (masl exit status 64: masl was called wrongly)"), nowhere.getOutput());
    }

    private static void copySampleTo(Path project) throws IOException {
        try (Stream<Path> files = Files.walk(SAMPLE)) {
            for (Path file : files.filter(Files::isRegularFile).filter(file -> !SAMPLE.relativize(file).startsWith("build")
                    && !SAMPLE.relativize(file).startsWith(".gradle") && !file.getFileName().toString().equals("settings.gradle"))
                    .toList()) {
                Path target = project.resolve(SAMPLE.relativize(file).toString());
                Files.createDirectories(target.getParent());
                Files.copy(file, target);
            }
        }
    }

    private static int freePort() throws IOException {
        try (ServerSocket socket = new ServerSocket(0, 1, InetAddress.getByName("127.0.0.1"))) {
            return socket.getLocalPort();
        }
    }
}
