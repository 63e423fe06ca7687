package masl.translator;

import java.util.concurrent.atomic.AtomicReference;
import java.util.function.Supplier;

/**
 * Runs translation work on a thread with a deep stack: ANTLR's parser, the analysis, the generator
 * and javac recurse into nested constructs, and a program nested thousands of levels deep (brackets,
 * a chain of operators, {@code else if}s) overflows the default stack of a thread (about 1 MB).
 * {@value #STACK_BYTES} bytes hold {@link masl.translator.parse.Nesting#DEEPEST} levels of any
 * construct several times over; the memory is reserved, and only the part used is committed.
 */
final class DeepStack {

    static final long STACK_BYTES = 256L * 1024 * 1024;

    /** The work overflowed even this stack. */
    static final class TooDeep extends RuntimeException {
        private static final long serialVersionUID = 1L;

        TooDeep(StackOverflowError cause) {
            super("nested too deeply", cause);
        }
    }

    private DeepStack() {
    }

    /**
     * {@code work}'s result, computed on a thread of its own with a deep stack; what it throws is
     * thrown here.
     *
     * @throws TooDeep if it overflowed that stack
     */
    static <T> T call(String name, Supplier<T> work) {
        AtomicReference<T> result = new AtomicReference<>();
        AtomicReference<Throwable> failure = new AtomicReference<>();
        Thread thread = new Thread(null, () -> {
            try {
                result.set(work.get());
            } catch (StackOverflowError overflow) {
                failure.set(new TooDeep(overflow));
            } catch (RuntimeException | Error e) {
                failure.set(e);
            }
        }, name, STACK_BYTES);
        thread.setDaemon(true);
        thread.start();
        boolean interrupted = false;
        while (true) {
            try {
                thread.join();
                break;
            } catch (InterruptedException e) {
                // The work cannot be stopped halfway; the caller learns of the interrupt once it is done.
                interrupted = true;
            }
        }
        if (interrupted) {
            Thread.currentThread().interrupt();
        }
        Throwable thrown = failure.get();
        if (thrown instanceof RuntimeException runtime) {
            throw runtime;
        }
        if (thrown instanceof Error error) {
            throw error;
        }
        return result.get();
    }
}
