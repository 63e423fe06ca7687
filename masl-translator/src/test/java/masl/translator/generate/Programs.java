package masl.translator.generate;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.URISyntaxException;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.List;
import masl.runtime.MissionOutcome;
import masl.runtime.descriptor.AgentPath;
import masl.runtime.scheduling.PoolScheduler;
import masl.runtime.scheduling.Scheduler;
import masl.runtime.scheduling.SeededScheduler;
import masl.translator.MissionLoader;
import masl.translator.Translation;
import masl.translator.Translator;
import masl.translator.source.SourceFile;

/** Translates MASL programs given as text and runs them, for the generator's tests. */
final class Programs {

    /** The folder the fixture descriptors are found from ({@code robots/Khepera.xml}). */
    static final Path FIXTURES = fixtures();

    private Programs() {
    }

    static Translation translate(String fileName, String text) {
        return new Translator(AgentPath.parse("")).translate(new SourceFile(fileName, FIXTURES, text));
    }

    static MissionLoader load(String text) {
        Translation translation = translate("test.masl", text);
        assertTrue(translation.succeeded(), () -> translation.diagnostics().sorted().toString());
        return MissionLoader.load(translation, AgentPath.parse(""));
    }

    /** The outcome of one run of {@code loaded}, which must complete. */
    static String journal(MissionLoader loaded, Scheduler scheduler) {
        try {
            MissionOutcome outcome = loaded.newMission().scheduler(scheduler).build().run(Duration.ofSeconds(60));
            return outcome.requireCompleted().journal();
        } catch (InterruptedException interrupted) {
            Thread.currentThread().interrupt();
            throw new AssertionError(interrupted);
        }
    }

    /**
     * The journals of {@code text} run on the pool and over several seeds: one list per run, so a
     * test can assert on each.
     */
    static List<String> journals(String text, int runs) {
        MissionLoader loaded = load(text);
        List<String> journals = new ArrayList<>();
        for (int run = 0; run < runs; run++) {
            journals.add(journal(loaded, new PoolScheduler()));
            journals.add(journal(loaded, new SeededScheduler(run)));
        }
        return journals;
    }

    static List<String> sortedLines(String journal) {
        List<String> lines = new ArrayList<>(Arrays.asList(journal.split("\n")));
        Collections.sort(lines);
        return lines;
    }

    private static Path fixtures() {
        try {
            return Path.of(Programs.class.getResource("/analysis/robots/Khepera.xml").toURI()).getParent().getParent();
        } catch (URISyntaxException impossible) {
            throw new IllegalStateException(impossible);
        }
    }
}
