package masl.testing;

import java.time.Duration;
import masl.runtime.MissionOutcome;
import masl.runtime.trace.Trace;

/**
 * Where a mission under test runs ({@link MaslMission#runOn}): in this JVM under a {@link Schedule},
 * or on an agent platform, as {@code masl-testing-jade}'s {@code InJade} runs it inside a JADE
 * container. A platform that deploys a mission over several containers or machines is one more
 * implementation: it is given the translated program, its descriptors and its options, and returns
 * how the mission ended.
 */
public interface MissionPlatform {

    /**
     * Runs a fresh mission of {@code mission}'s program until it ends or {@code timeout} elapses.
     *
     * @param trace receives every membership change, barrier trip and wave of the run
     * @return how it ended, with its journal
     * @throws InterruptedException if the test's thread is interrupted meanwhile
     */
    MissionOutcome run(TranslatedMission mission, Trace trace, Duration timeout) throws InterruptedException;

    /**
     * How a failure names the run's place, after the mission's name: {@code under seed 7}, {@code in
     * JADE (container Main-Container)}.
     */
    @Override
    String toString();
}
