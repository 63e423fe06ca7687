package masl.cli;

/** Entry point of the {@code masl} command line. */
public final class Main {

    private Main() {
    }

    /** JADE prints some of its faults as stack traces on standard error: each is folded to its first line. */
    public static void main(String[] args) {
        System.setErr(StackTraceFolding.around(System.err));
        System.exit(new Masl(System.out, System.err).run(args));
    }
}
