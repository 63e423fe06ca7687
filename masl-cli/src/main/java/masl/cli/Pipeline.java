package masl.cli;

import java.io.PrintStream;
import java.util.Map;
import java.util.Optional;
import masl.runtime.descriptor.AgentPath;
import masl.translator.MissionLoader;
import masl.translator.Translation;
import masl.translator.Translator;
import masl.translator.cache.CompiledMission;
import masl.translator.cache.CompiledMissionCache;
import masl.translator.diagnostics.DiagnosticPrinter;
import masl.translator.source.SourceFile;

/**
 * The one pipeline of {@code masl check}, {@code compile} and {@code run}, so that they report the
 * same errors: translate (parse, analyse against the descriptors, generate, which refuses what it
 * cannot translate yet), print every diagnostic, then compile the generated Java in memory. A
 * program {@code check} accepts is one {@code run} translates and loads; Java that javac rejects is
 * a bug of masl, a {@code GeneratedCodeException} that each command reports alike (exit status 70).
 */
final class Pipeline {

    /** A program without errors: its translation, compiled and loaded. */
    record Loaded(Translation translation, MissionLoader loader) {
    }

    private Pipeline() {
    }

    /** Runs the pipeline on {@code source}, its diagnostics to {@code err}; null when it has errors. */
    static Loaded load(SourceFile source, AgentPath agentPath, PrintStream err) {
        Translation translation = new Translator(agentPath).translate(source);
        err.print(diagnostics(source, translation));
        if (!translation.succeeded()) {
            return null;
        }
        return new Loaded(translation, MissionLoader.load(translation, agentPath));
    }

    /**
     * As {@link #load}, for {@code masl run}: the compiled mission of an earlier run of the same
     * program, descriptors, agent path, masl and JDK comes from {@code cache} (its warnings printed
     * again), without translating or compiling; otherwise the pipeline runs and stores what it
     * compiled. Null when the program has errors.
     */
    static MissionLoader loadForRun(SourceFile source, AgentPath agentPath, PrintStream err, CompiledMissionCache cache) {
        String key = cache.keyOf(source, agentPath);
        Optional<CompiledMission> cached = cache.lookup(key);
        if (cached.isPresent()) {
            err.print(cached.get().diagnostics());
            return MissionLoader.ofCompiled(cached.get().missionClassName(), cached.get().classFiles(), agentPath);
        }
        Translation translation = new Translator(agentPath).translate(source);
        String diagnostics = diagnostics(source, translation);
        err.print(diagnostics);
        if (!translation.succeeded()) {
            return null;
        }
        MissionLoader loader = MissionLoader.load(translation, agentPath);
        // What was read while translating must still be what the key was made of.
        if (key != null && key.equals(cache.keyOf(source, agentPath))) {
            cache.store(key, new CompiledMission(loader.missionClassName(), loader.classFiles(), diagnostics));
        }
        return loader;
    }

    private static String diagnostics(SourceFile source, Translation translation) {
        return new DiagnosticPrinter(Map.of(source.name(), source.text())).report(translation.diagnostics().sorted());
    }
}
