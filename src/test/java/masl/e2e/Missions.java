package masl.e2e;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import masl.runtime.MissionOutcome;
import masl.runtime.PoolScheduler;
import masl.runtime.Scheduler;
import masl.runtime.SeededScheduler;
import masl.runtime.ThreadPerAgentScheduler;
import masl.runtime.descriptor.AgentPath;
import masl.translator.MissionLoader;
import masl.translator.Translation;
import masl.translator.Translator;
import masl.translator.source.SourceFile;

/** Translates MASL programs of the test resources once each, and runs them under a chosen scheduler. */
final class Missions {

    /** How the agents are run. */
    enum Driver {
        POOL, THREADS;

        Scheduler scheduler() {
            return this == POOL ? new PoolScheduler() : new ThreadPerAgentScheduler();
        }
    }

    private static final Map<String, MissionLoader> LOADED = new ConcurrentHashMap<>();

    private Missions() {
    }

    /** The program in resource {@code examples/NAME}, translated and compiled (once per test run). */
    static MissionLoader example(String name) {
        return LOADED.computeIfAbsent(name, Missions::load);
    }

    static MissionLoader load(String name) {
        return translate(SourceFile.of(name, resource("/examples/" + name)));
    }

    static MissionLoader translate(SourceFile source) {
        AgentPath agentPath = AgentPath.parse("");
        Translation translation = new Translator(agentPath).translate(source);
        assertTrue(translation.succeeded(), () -> source.name() + ": " + translation.diagnostics().sorted());
        return MissionLoader.load(translation, agentPath);
    }

    /** Runs a new mission of {@code loaded} to its end; fails the test unless it completes. */
    static String journal(MissionLoader loaded, Scheduler scheduler) {
        try {
            MissionOutcome outcome = loaded.newMission().scheduler(scheduler).build().run(Duration.ofSeconds(60));
            return outcome.requireCompleted().journal();
        } catch (InterruptedException interrupted) {
            Thread.currentThread().interrupt();
            throw new AssertionError("interrupted", interrupted);
        }
    }

    static String journal(MissionLoader loaded, Driver driver) {
        return journal(loaded, driver.scheduler());
    }

    static String journalWithSeed(MissionLoader loaded, long seed) {
        return journal(loaded, new SeededScheduler(seed));
    }

    private static String resource(String name) {
        try (InputStream in = Missions.class.getResourceAsStream(name)) {
            if (in == null) {
                throw new IllegalArgumentException("no test resource " + name);
            }
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
