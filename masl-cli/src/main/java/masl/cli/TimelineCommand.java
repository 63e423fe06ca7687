package masl.cli;

import java.io.IOException;
import java.io.PrintStream;
import java.io.Reader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.List;
import masl.cli.timeline.Timeline;
import masl.cli.timeline.TimelineHtml;
import masl.cli.timeline.TraceFormatException;
import masl.cli.timeline.TraceReader;
import masl.cli.timeline.TraceRecord;

/** {@code masl timeline TRACE -o FILE.html}: draws a trace as a page that opens offline. */
final class TimelineCommand {

    private final PrintStream err;

    TimelineCommand(PrintStream err) {
        this.err = err;
    }

    int run(CommandLine line) throws UsageException {
        String traceName = line.singleFile();
        if (line.outputFile == null) {
            throw new UsageException("masl timeline needs -o FILE.html");
        }
        Path trace = path(traceName);
        Path page = path(line.outputFile);
        if (Files.isDirectory(trace)) {
            throw new UsageException(traceName + ": is a folder, not a trace (give the file run --trace wrote)");
        }
        if (!Files.isRegularFile(trace)) {
            throw new UsageException(traceName + ": no such file");
        }
        new CommandInputs().add("the trace", trace).refuseOverwriting("the page", page);
        List<TraceRecord> records;
        try (Reader text = Files.newBufferedReader(trace, StandardCharsets.UTF_8)) {
            records = TraceReader.read(traceName, text);
        } catch (TraceFormatException malformed) {
            err.println(malformed.getMessage());
            return Masl.PROGRAM_ERRORS;
        } catch (IOException unreadable) {
            throw new UsageException(traceName + ": cannot be read (" + unreadable.getMessage() + ")");
        }
        String html = new TimelineHtml(Timeline.of(records), "MASL timeline of " + trace.getFileName()).render();
        try {
            Files.writeString(page, html, StandardCharsets.UTF_8);
        } catch (IOException unwritable) {
            err.println("masl: cannot write the page " + page + ": " + OutputFolder.reason(unwritable));
            return Masl.CANNOT_WRITE;
        }
        return Masl.OK;
    }

    private static Path path(String name) throws UsageException {
        try {
            return Path.of(name);
        } catch (InvalidPathException bad) {
            throw new UsageException("not a file name: " + name);
        }
    }
}
