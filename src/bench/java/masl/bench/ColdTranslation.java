package masl.bench;

import java.io.File;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * The first translation in a fresh JVM, what {@code masl run} pays every time its
 * cache has not got the program. {@link #main} is that JVM: it translates the benchmark's program once
 * and prints lines per second of the translating thread's CPU time. {@link #measure} starts it as the
 * installed command starts its JVM: masl's jars on the class path, in the command's order, and the
 * class-data archive installing made.
 */
final class ColdTranslation {

    private ColdTranslation() {
    }

    public static void main(String[] args) throws Exception {
        System.out.println(MaslTranslation.prepare(Integer.parseInt(args[0]), true).call());
    }

    /** Lines per CPU second of one fresh JVM's first translation of a {@code lines}-line program. */
    static double measure(int lines, boolean archive) throws Exception {
        String output = runFresh(archive, ColdTranslation.class, String.valueOf(lines));
        return Double.parseDouble(output.substring(output.lastIndexOf('\n') + 1));
    }

    /** The output of {@code main} run in a fresh JVM started as the command starts its own, with its archive. */
    static String runFresh(Class<?> main, String... args) throws Exception {
        return runFresh(true, main, args);
    }

    private static String runFresh(boolean archive, Class<?> main, String... args) throws Exception {
        Path lib = Path.of(System.getProperty("masl.bench.home", ".")).toAbsolutePath()
                .resolve("masl-cli/build/install/masl/lib");
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString()));
        if (archive && Files.isRegularFile(lib.resolve("masl.jsa"))) {
            command.addAll(List.of("-XX:SharedArchiveFile=" + lib.resolve("masl.jsa"), "-Xlog:cds=off", "-Xlog:cds+dynamic=off"));
        }
        // The command's class path first (the archive holds classes from it, in its order), then the bench's own.
        command.addAll(List.of("-cp", installedClassPath(lib) + File.pathSeparator + System.getProperty("java.class.path"),
                main.getName()));
        command.addAll(List.of(args));
        Process process = new ProcessBuilder(command).redirectErrorStream(true).start();
        String output = new String(process.getInputStream().readAllBytes()).strip();
        if (process.waitFor() != 0) {
            throw new IllegalStateException(main.getSimpleName() + " failed in a fresh JVM: " + output);
        }
        return output;
    }

    /** The class path of the installed start script, in its order. */
    private static String installedClassPath(Path lib) throws Exception {
        String script = Files.readString(lib.resolveSibling("bin").resolve("masl"));
        int start = script.indexOf("CLASSPATH=$APP_HOME/lib/");
        String line = script.substring(start + "CLASSPATH=".length(), script.indexOf('\n', start));
        return line.replace("$APP_HOME/lib", lib.toString());
    }
}
