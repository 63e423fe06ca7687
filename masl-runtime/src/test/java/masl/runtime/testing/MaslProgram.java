package masl.runtime.testing;

import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Supplier;
import java.util.stream.Collectors;
import java.util.stream.IntStream;
import masl.runtime.AgentImplementation;
import masl.runtime.Mission;
import masl.runtime.MissionOutcome;
import masl.runtime.MissionProgram;
import masl.runtime.descriptor.AgentPath;
import masl.runtime.scheduling.Scheduler;
import masl.runtime.trace.Trace;
import masl.translator.MaslClassPath;
import masl.translator.MissionLoader;
import masl.translator.Translation;
import masl.translator.Translator;
import masl.translator.cache.CompiledMission;
import masl.translator.cache.CompiledMissionCache;
import masl.translator.source.SourceFile;

/**
 * A test program written in MASL and translated by masl's own translator, so that what the runtime
 * is tested with is what the translator emits. Its agents are {@link TestAgent}s, of the type
 * {@code agents/Default.xml}: a program begins with {@link #header(int)}. Each text is translated and
 * compiled once per test JVM, or taken from the cache of compiled missions; each run is a fresh mission of it.
 */
public final class MaslProgram {

    private static final Duration TIMEOUT = Duration.ofSeconds(20);
    private static final Map<String, MaslProgram> TRANSLATED = new ConcurrentHashMap<>();

    private final MissionLoader loaded;

    private MaslProgram(MissionLoader loaded) {
        this.loaded = loaded;
    }

    /**
     * The import of the tests' root type and {@code agents} agents of it, {@code a0}, {@code a1}, …
     * (proxy ids 0, 1, …, as {@link Missions} names them).
     */
    public static String header(int agents) {
        return "import Default.xml as Default;\n"
                + IntStream.range(0, agents).mapToObj(i -> "a" + i).collect(Collectors.joining(", ", "Default ", ""))
                + " = newAgent(Default);\n";
    }

    /** {@code text} translated and compiled (once); {@code name} is its file name in diagnostics and trace. */
    public static MaslProgram of(String name, String text) {
        return TRANSLATED.computeIfAbsent(name + "\n" + text, key -> translate(name, text));
    }

    /** {@code body} after {@link #header(int) header(agents)}, translated and compiled (once). */
    public static MaslProgram of(String name, int agents, String body) {
        return of(name, header(agents) + body);
    }

    private static MaslProgram translate(String name, String text) {
        Path agents = TestTypes.folder();
        Path testClasses = Path.of(MaslClassPath.locationOf(TestAgent.class).orElseThrow());
        AgentPath path = AgentPath.of(List.of(agents, testClasses), MaslProgram.class.getClassLoader());
        SourceFile source = new SourceFile(name, agents, text);
        // masl run's cache of compiled missions ($MASL_CACHE_DIR: the build folder in this build's tests):
        // a program, descriptors, test classes and masl unchanged since the last run skip javac.
        CompiledMissionCache cache = new CompiledMissionCache(CompiledMissionCache.defaultFolder(System.getenv()));
        String key = cache.keyOf(source, path);
        Optional<CompiledMission> compiled = cache.lookup(key);
        if (compiled.isPresent()) {
            return new MaslProgram(MissionLoader.ofCompiled(compiled.get().missionClassName(), compiled.get().classFiles(), path));
        }
        Translation translation = new Translator(path).translate(source);
        if (!translation.succeeded()) {
            throw new AssertionError(name + " does not translate:\n" + translation.diagnostics().sorted());
        }
        MissionLoader loaded = MissionLoader.load(translation, path);
        cache.store(key, new CompiledMission(loaded.missionClassName(), loaded.classFiles(), ""));
        return new MaslProgram(loaded);
    }

    /** Agents made by {@code make}, each also added to {@code made}, in proxy id order: the test keeps them. */
    public static <T extends TestAgent> Supplier<T> recording(Supplier<T> make, List<? super T> made) {
        return () -> {
            T agent = make.get();
            made.add(agent);
            return agent;
        };
    }

    /** A run on {@code driver}'s scheduler, which must complete. */
    public MissionOutcome run(Driver driver) {
        return run(driver.newScheduler(), Trace.NONE);
    }

    /** A run under {@code scheduler} recording into {@code trace}, which must complete. */
    public MissionOutcome run(Scheduler scheduler, Trace trace) {
        return run(scheduler, trace, TestAgent::new);
    }

    /** As {@link #run(Scheduler, Trace)}, each agent's implementation made by {@code agents}. */
    public MissionOutcome run(Scheduler scheduler, Trace trace, Supplier<? extends TestAgent> agents) {
        return completed(newMission(agents), scheduler, trace);
    }

    /**
     * A run under {@code scheduler} recording into {@code trace}, which must complete; each agent is
     * made of the class its type names (a {@link TestRobot} for a program's {@code TestRobot}s), by
     * its no-argument constructor, as {@code masl run} makes them.
     */
    public MissionOutcome runOfDeclaredClasses(Scheduler scheduler, Trace trace) {
        MissionProgram program = loaded.program();
        return completed(program.configure(Mission.builder(), spec -> (AgentImplementation) Class
                .forName(spec.typeClassName()).getConstructor().newInstance()), scheduler, trace);
    }

    private static MissionOutcome completed(Mission.Builder mission, Scheduler scheduler, Trace trace) {
        try {
            return mission.scheduler(scheduler).trace(trace).build().run(TIMEOUT).requireCompleted();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new AssertionError("interrupted", e);
        }
    }

    /** A builder holding the program's agents, each made by {@code agents}; the caller adds the rest. */
    public Mission.Builder newMission(Supplier<? extends TestAgent> agents) {
        MissionProgram program = loaded.program();
        return program.configure(Mission.builder(), spec -> (AgentImplementation) agents.get());
    }
}
