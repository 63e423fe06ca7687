package masl.e2e;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Set;
import java.util.stream.Stream;
import javax.tools.JavaCompiler;
import javax.tools.ToolProvider;
import masl.e2e.ManualPage.CodeBlock;

/**
 * The checks of one manual page, by the convention of docs/manual/README.md: every block of MASL is
 * checked or run, with the {@code masl} command in this process and the shipped agent types, against
 * the journal or the errors shown under it. The files a page shows with {@code file=} (descriptors,
 * Java classes) are written into the page's folder first, its Java compiled there, and that folder
 * is the agent path of the page's programs.
 */
final class ManualExamples {

    /** One check: where it is in the manual (page:line) and what it verifies. */
    record Check(String where, Runnable verify) {
    }

    /** The seeds each program also runs under, besides the pool: a journal shown must not hold by luck. */
    static final List<Long> SEEDS = List.of(1L, 2L, 3L);

    static final String PROGRAM = "program.masl";
    static final String FRAGMENT_HEADER = """
            import Default.xml as Default;
            Default a, b, c = newAgent(Default);
            asynchronous entry main (true) {
            """;

    private static final Set<String> EXPECTATIONS = Set.of("journal", "error", "failure");
    private static final String TIMEOUT_SECONDS = "60";

    private final ManualPage page;
    private final Path folder;

    private ManualExamples(ManualPage page, Path folder) {
        this.page = page;
        this.folder = folder;
    }

    /** The checks of {@code page}, which will work in {@code folder} (made afresh). */
    static List<Check> of(ManualPage page, Path folder) {
        return new ManualExamples(page, folder).checks();
    }

    private List<Check> checks() {
        List<Check> checks = new ArrayList<>();
        List<CodeBlock> blocks = page.blocks();
        checks.add(new Check(page.name() + ": its files", this::writeFiles));
        for (int i = 0; i < blocks.size(); i++) {
            CodeBlock block = blocks.get(i);
            CodeBlock next = i + 1 < blocks.size() ? blocks.get(i + 1) : null;
            if (block.language().isEmpty()) {
                checks.add(failure(block, "a code block without a language: mark it (```masl, ```sh, ```text, …)"));
            } else if (block.is("masl", "fragment")) {
                checks.add(fragment(block, next));
            } else if (block.language().equals("masl")) {
                checks.add(program(block, next));
                if (next != null && EXPECTATIONS.contains(next.language())) {
                    i++;
                }
            } else if (EXPECTATIONS.contains(block.language())) {
                checks.add(failure(block, "a " + block.language() + " block under no MASL program"));
            }
        }
        return checks;
    }

    private static Check failure(CodeBlock block, String message) {
        return new Check(block.where(), () -> {
            throw new AssertionError(block.where() + ": " + message);
        });
    }

    private Check fragment(CodeBlock block, CodeBlock next) {
        if (next != null && EXPECTATIONS.contains(next.language())) {
            return failure(next, "a " + next.language() + " block under a fragment: show a whole program instead");
        }
        return new Check(block.where(), () -> {
            Path program = programFile(block, FRAGMENT_HEADER + block.text() + "}\n");
            MaslCommand check = MaslCommand.run("check", program.toString(), "--agent-path", folder.toString());
            if (check.status() != 0) {
                throw new AssertionError(block.where() + ": the fragment, inside\n" + FRAGMENT_HEADER + "…\n}\ndoes not check:\n"
                        + check);
            }
        });
    }

    private Check program(CodeBlock block, CodeBlock next) {
        if (next == null || !EXPECTATIONS.contains(next.language())) {
            return failure(block, "a MASL program with no ```journal, ```error or ```failure block under it");
        }
        String source = block.attributes().get("source");
        if (source != null && !block.text().equals(read(Path.of(source)))) {
            return failure(block, "the program differs from " + source + ", which it says it is");
        }
        if (next.language().equals("error")) {
            return new Check(block.where(), () -> expectErrors(block, next));
        }
        if (next.language().equals("failure")) {
            return new Check(block.where(), () -> expectFailure(block, next));
        }
        return new Check(block.where(), () -> expectJournal(block, next));
    }

    private void expectErrors(CodeBlock block, CodeBlock errors) {
        expectStandardError(block, errors, 1, "errors", "check");
    }

    private void expectFailure(CodeBlock block, CodeBlock failure) {
        expectStandardError(block, failure, 2, "report", "run", "--timeout", TIMEOUT_SECONDS);
    }

    /** {@code masl COMMAND program --agent-path folder OPTIONS…} exits with {@code status}, its standard error {@code shown}. */
    private void expectStandardError(CodeBlock block, CodeBlock shown, int status, String what, String command,
            String... options) {
        Path program = programFile(block, block.text());
        List<String> arguments = new ArrayList<>(List.of(command, program.toString(), "--agent-path", folder.toString()));
        arguments.addAll(List.of(options));
        MaslCommand masl = MaslCommand.run(arguments.toArray(String[]::new));
        String err = withoutFolders(masl.err(), program);
        if (masl.status() != status || !err.equals(shown.text())) {
            throw new AssertionError(block.where() + ": masl " + command + " gives status " + masl.status()
                    + " and, instead of the " + what + " shown at " + shown.where() + ":\n" + shown.text()
                    + "this:\n" + err);
        }
    }

    /** Messages as a user who ran the command in the program's folder, next to the page's files, reads them. */
    private String withoutFolders(String messages, Path program) {
        return messages.replace(program.getParent() + "/", "").replace(folder + "/", "");
    }

    private void expectJournal(CodeBlock block, CodeBlock journal) {
        Path program = programFile(block, block.text());
        boolean anyOrder = journal.words().contains("any-order");
        List<List<String>> schedules = new ArrayList<>();
        schedules.add(List.of());
        SEEDS.forEach(seed -> schedules.add(List.of("--seed", seed.toString())));
        for (List<String> schedule : schedules) {
            List<String> arguments = new ArrayList<>(List.of("run", program.toString(), "--agent-path", folder.toString(),
                    "--timeout", TIMEOUT_SECONDS));
            arguments.addAll(schedule);
            MaslCommand run = MaslCommand.run(arguments.toArray(String[]::new));
            String how = schedule.isEmpty() ? "on the pool" : "with " + String.join(" ", schedule);
            if (run.status() != 0) {
                throw new AssertionError(block.where() + ": masl run " + how + " failed:\n" + run);
            }
            if (!sameJournal(run.out(), journal.text(), anyOrder)) {
                throw new AssertionError(block.where() + ": masl run " + how + " wrote, instead of the journal shown at "
                        + journal.where() + (anyOrder ? " (in any order)" : "") + ":\n" + journal.text() + "this:\n"
                        + run.out());
            }
        }
    }

    static boolean sameJournal(String actual, String shown, boolean anyOrder) {
        if (!anyOrder) {
            return actual.equals(shown);
        }
        return actual.endsWith("\n") && actual.lines().sorted().toList().equals(shown.lines().sorted().toList());
    }

    /** The program of {@code block} in a folder of its own, named by its {@code file=} or {@value #PROGRAM}. */
    private Path programFile(CodeBlock block, String text) {
        Path program = folder.resolve("line-" + block.line()).resolve(block.attributes().getOrDefault("file", PROGRAM));
        write(program, text);
        return program;
    }

    /** The page's files ({@code file=} on a block other than MASL), its Java compiled into the folder. */
    private void writeFiles() {
        deleteFolder();
        List<String> javaSources = new ArrayList<>();
        for (CodeBlock block : page.blocks()) {
            String name = block.attributes().get("file");
            if (name == null || block.language().equals("masl")) {
                continue;
            }
            Path file = folder.resolve(name);
            write(file, block.text());
            if (block.language().equals("java")) {
                javaSources.add(file.toString());
            }
        }
        if (!javaSources.isEmpty()) {
            compile(javaSources);
        }
    }

    private void compile(List<String> sources) {
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        List<String> arguments = new ArrayList<>(List.of("--release", "17", "-classpath",
                System.getProperty("java.class.path"), "-d", folder.toString()));
        arguments.addAll(sources);
        int status = javac.run(null, System.out, System.err, arguments.toArray(String[]::new));
        if (status != 0) {
            throw new AssertionError(page.name() + ": its Java does not compile: " + sources);
        }
    }

    private void deleteFolder() {
        if (!Files.exists(folder)) {
            return;
        }
        try (Stream<Path> files = Files.walk(folder)) {
            for (Path file : files.sorted(Comparator.reverseOrder()).toList()) {
                Files.delete(file);
            }
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    private static String read(Path file) {
        try {
            return Files.readString(file);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    private static void write(Path file, String text) {
        try {
            Files.createDirectories(file.getParent());
            Files.writeString(file, text);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
