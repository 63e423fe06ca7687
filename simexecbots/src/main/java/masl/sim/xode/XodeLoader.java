package masl.sim.xode;

import java.util.List;
import java.util.concurrent.atomic.AtomicReference;
import masl.runtime.diagnostic.Severity;

/**
 * Loads XODE 1.0r23 documents (xode.md) into ode4j.
 *
 * <p>Loading is all or nothing for the document's content: the file is parsed with a secure StAX
 * parser, checked and read completely first; only a file without errors creates ode4j objects.
 * Every error of the file is reported in one {@link XodeException}. A loader is stateless and may
 * be shared; the target world must not be stepped while a document is loaded into it. The loading
 * runs on a thread of its own with a deep stack, the caller waiting for it.
 */
public final class XodeLoader {

    /**
     * The stack the loading runs on: reading and building recurse into nested elements, and this
     * holds {@link SecureXmlReader#DEEPEST} levels whatever the caller's stack (a default thread's
     * held 1,000 nested bodies, not 2,000). Reserved, and committed only as far as it is used.
     */
    private static final long STACK_BYTES = 128L * 1024 * 1024;

    private final LoadOptions options;

    public XodeLoader() {
        this(LoadOptions.defaults());
    }

    public XodeLoader(LoadOptions options) {
        this.options = options;
    }

    /** Loads a stand-alone document into new worlds, without a name prefix. */
    public LoadedModel load(XodeSource source) throws XodeException {
        return load(source, "", LoadTarget.newWorlds());
    }

    /**
     * Loads a document.
     *
     * @param prefix put in front of every name, and of every body a link names, so one robot file
     *               can be loaded once per agent: {@code "khepera0."} gives {@code khepera0.chassis}
     * @throws XodeException naming file, line, column and element of every error
     */
    public LoadedModel load(XodeSource source, String prefix, LoadTarget target) throws XodeException {
        AtomicReference<LoadedModel> loaded = new AtomicReference<>();
        AtomicReference<Throwable> failure = new AtomicReference<>();
        Thread thread = new Thread(null, () -> {
            try {
                loaded.set(loadHere(source, prefix, target));
            } catch (XodeException | RuntimeException | Error e) {
                failure.set(e);
            }
        }, "xode " + source.name(), STACK_BYTES);
        thread.start();
        joinUninterruptibly(thread);
        if (failure.get() instanceof XodeException refused) {
            throw refused;
        }
        if (failure.get() instanceof RuntimeException bug) {
            throw bug;
        }
        if (failure.get() instanceof Error error) {
            throw error;
        }
        return loaded.get();
    }

    private static void joinUninterruptibly(Thread thread) {
        boolean interrupted = false;
        while (thread.isAlive()) {
            try {
                thread.join();
            } catch (InterruptedException e) {
                // Loading cannot stop halfway; the caller learns of the interrupt once it is done.
                interrupted = true;
            }
        }
        if (interrupted) {
            Thread.currentThread().interrupt();
        }
    }

    /** {@link #load} on this thread, whose stack must be deep. */
    private LoadedModel loadHere(XodeSource source, String prefix, LoadTarget target) throws XodeException {
        OdeRuntime.ensureInitialised();
        String safePrefix = prefix == null ? "" : prefix;
        String text = source.readText();
        XodeElement root = new SecureXmlReader(source.name(), text).read();
        Problems problems = new Problems(options.strict());
        SceneSpec scene;
        try {
            if (!new SchemaChecker(problems).check(root)) {
                problems.throwIfErrors();
            }
            scene = new SceneReader(problems, options, safePrefix, target.placement(), target.takenNames()).read(root);
        } catch (RuntimeException e) {
            // A reader bug must still reach the user as a located message, never as a stack trace.
            throw new XodeException(List.of(new XodeProblem(Severity.ERROR, root.location(), root.name(),
                    "internal error while reading this file: " + e)));
        }
        problems.throwIfErrors();
        try {
            return new SceneBuilder().build(scene, target, source.name(), safePrefix, problems.warnings());
        } catch (RuntimeException e) {
            throw new XodeException(List.of(new XodeProblem(Severity.ERROR, root.location(), root.name(),
                    "ode4j refused the scene: " + e.getMessage())));
        }
    }
}
