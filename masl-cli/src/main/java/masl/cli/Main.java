package masl.cli;

/** Entry point of the {@code masl} command line. */
public final class Main {

    private Main() {
    }

    public static void main(String[] args) {
        System.exit(new Masl(System.out, System.err).run(args));
    }
}
