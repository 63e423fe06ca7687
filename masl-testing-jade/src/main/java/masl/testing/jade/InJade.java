package masl.testing.jade;

import java.time.Duration;
import masl.jade.JadeLauncher;
import masl.jade.platform.JadePlatform;
import masl.runtime.MissionOutcome;
import masl.runtime.descriptor.DescriptorLoader;
import masl.runtime.trace.Trace;
import masl.testing.MissionPlatform;
import masl.testing.TranslatedMission;

/**
 * Runs missions under test inside an open JADE container, as {@code masl run --platform jade} runs
 * them: one JADE agent per MASL agent, registered with the DF, each program in a behaviour of its
 * agent. Plain JADE agents of the platform (started by the test, in this JVM or another) are found
 * by the mission's {@code <Fipa>} types, and can find and call the mission's agents in turn.
 *
 * <pre>{@code
 * @RegisterExtension
 * static final JadePlatformExtension JADE = new JadePlatformExtension();
 *
 * @Test
 * void theTeamAsksTheCalculator() throws Exception {
 *     JADE.platform().container().acceptNewAgent("calculator", new CalculatorAgent()).start();
 *     MaslMission.fromFile(Path.of("src/test/masl/team.masl")).runOn(JADE.missionPlatform()).assertJournal("12 / 4 = 3\n");
 * }
 * }</pre>
 *
 * <p>The container is the test's: the mission's agents are gone from it when a run returns, the
 * container stays open.
 */
public final class InJade implements MissionPlatform {

    private final JadePlatform platform;

    private InJade(JadePlatform platform) {
        this.platform = platform;
    }

    /** Missions run in {@code platform}'s container, which the caller opened and closes. */
    public static InJade on(JadePlatform platform) {
        return new InJade(platform);
    }

    @Override
    public MissionOutcome run(TranslatedMission mission, Trace trace, Duration timeout) throws InterruptedException {
        DescriptorLoader descriptors = new DescriptorLoader(mission.descriptors());
        JadeLauncher launcher = JadeLauncher.of(mission.loader().program())
                .types(spec -> descriptors.loadByClassName(spec.typeClassName()))
                .implementations(mission.loader()::newImplementation)
                .trace(trace);
        mission.callTimeout().ifPresent(launcher::callTimeout);
        return launcher.run(platform, timeout);
    }

    @Override
    public String toString() {
        return "in JADE (container " + platform.containerName() + ")";
    }
}
