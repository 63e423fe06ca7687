package masl.testing;

import java.time.Duration;
import java.util.Optional;
import masl.runtime.descriptor.AgentPath;
import masl.translator.MissionLoader;

/**
 * A mission's program as a {@link MissionPlatform} is given it: translated and compiled once, from
 * which each run makes fresh agents.
 *
 * @param loader      the compiled program: its agents, their implementations, a new in-process mission
 * @param descriptors where its agent types' descriptors are found: the program's folder, then its agent path
 * @param callTimeout the bound of every primitive call, if the test set one
 */
public record TranslatedMission(MissionLoader loader, AgentPath descriptors, Optional<Duration> callTimeout) {
}
