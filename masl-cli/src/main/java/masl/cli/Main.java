package masl.cli;

import masl.runtime.MemoryReserve;

/** Entry point of the {@code masl} command line. */
public final class Main {

    private Main() {
    }

    /**
     * JADE prints some of its faults as stack traces on standard error: each is folded to its first
     * line. A thread that runs out of memory outside an agent's slice fails the mission as an agent
     * would ({@link MemoryReserve}), which masl reports: no stack trace of its own. The command ends
     * with its status even if a shutdown hook hangs ({@link ExitGuard}).
     */
    public static void main(String[] args) {
        System.setErr(StackTraceFolding.around(System.err));
        Thread.setDefaultUncaughtExceptionHandler((thread, uncaught) -> {
            if (uncaught instanceof OutOfMemoryError) {
                MemoryReserve.exhausted();
                return;
            }
            System.err.print("Exception in thread \"" + thread.getName() + "\" ");
            uncaught.printStackTrace();
        });
        ExitGuard.exit(new Masl(System.out, System.err).run(args));
    }
}
