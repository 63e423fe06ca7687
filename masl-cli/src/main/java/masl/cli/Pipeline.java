package masl.cli;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.Map;
import java.util.Optional;
import masl.runtime.descriptor.AgentPath;
import masl.runtime.diagnostic.DiagnosticPrinter;
import masl.translator.MissionLoader;
import masl.translator.Translation;
import masl.translator.Translator;
import masl.translator.cache.CompiledMission;
import masl.translator.cache.CompiledMissionCache;
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

    /**
     * Runs the pipeline on {@code source}, its diagnostics to {@code err}; null when it has errors.
     * Translating and compiling each say so through {@code progress} when they take long.
     */
    static Loaded load(SourceFile source, AgentPath agentPath, PrintStream err, Progress progress) {
        Translation translation;
        progress.begin(elapsed -> "masl: translating " + source.name() + " (" + Progress.seconds(elapsed) + ")");
        try {
            translation = new Translator(agentPath).translate(source);
        } finally {
            progress.end();
        }
        new DiagnosticPrinter(Map.of(source.name(), source.text())).print(translation.diagnostics().sorted(), err);
        if (!translation.succeeded()) {
            return null;
        }
        int classes = translation.javaSources().size();
        progress.begin(elapsed -> "masl: compiling the Java generated for " + source.name() + " (" + classes
                + (classes == 1 ? " class, " : " classes, ") + Progress.seconds(elapsed) + ")");
        try {
            return new Loaded(translation, MissionLoader.load(translation, agentPath));
        } finally {
            progress.end();
        }
    }

    /**
     * As {@link #load}, for {@code masl run} and {@code masl check}: the compiled mission of an
     * earlier run or check of the same program, descriptors, agent path, masl and JDK comes from
     * {@code cache} (its warnings printed again), without translating or compiling; otherwise the
     * pipeline runs and stores what it compiled. Null when the program has errors.
     */
    static MissionLoader loadThroughCache(SourceFile source, AgentPath agentPath, PrintStream err, Progress progress,
            CompiledMissionCache cache) {
        cache.unusable().ifPresent(reason -> err.println("masl: not using the cache of compiled missions: " + reason));
        String key = cache.keyOf(source, agentPath);
        Optional<CompiledMission> cached = cache.lookup(key);
        if (cached.isPresent()) {
            err.print(cached.get().diagnostics());
            return MissionLoader.ofCompiled(cached.get().missionClassName(), cached.get().classFiles(), agentPath);
        }
        ByteArrayOutputStream printed = new ByteArrayOutputStream();
        Loaded loaded;
        try {
            loaded = load(source, agentPath, new PrintStream(printed, true, StandardCharsets.UTF_8), progress);
        } finally {
            err.print(printed.toString(StandardCharsets.UTF_8));
        }
        if (loaded == null) {
            return null;
        }
        // What was read while translating must still be what the key was made of.
        if (key != null && key.equals(cache.keyOf(source, agentPath))) {
            cache.store(key, new CompiledMission(loaded.loader().missionClassName(), loaded.loader().classFiles(),
                    printed.toString(StandardCharsets.UTF_8)));
        }
        return loaded.loader();
    }
}
