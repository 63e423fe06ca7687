package masl.cli;

import java.io.BufferedWriter;
import java.io.IOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.Optional;
import masl.runtime.trace.JsonLinesTrace;
import masl.runtime.trace.Trace;

/**
 * The file of {@code masl run --trace FILE}, cut at {@code --trace-limit}. A trace that cannot be
 * written (a full disk, {@code /dev/full}), while the mission runs or when the file is closed, is
 * lost as a journal is: the mission is stopped and the run fails. Without {@code --trace}, nothing.
 */
final class TraceOutput {

    /** Why a mission whose trace cannot be written was stopped, as standard error says. */
    static final String TRACE_LOST = "the trace cannot be written";

    private final String file;
    private final Writer writer;
    private final JsonLinesTrace trace;
    private final long limit;
    private Runnable onFailure = () -> { };
    private IOException closeFailure;

    private TraceOutput(String file, Writer writer, long limit) {
        this.file = file;
        this.writer = writer;
        this.limit = limit;
        this.trace = writer == null ? null : new JsonLinesTrace(writer, limit);
        if (trace != null) {
            trace.whenFailed(failed -> failed());
        }
    }

    /** The trace to {@code file}, cut at {@code limit} bytes; none if {@code file} is null. */
    static TraceOutput open(String file, long limit) throws UsageException, Unwritable {
        if (file == null) {
            return new TraceOutput(null, null, limit);
        }
        Path path;
        try {
            path = Path.of(file);
        } catch (InvalidPathException notAName) {
            throw new UsageException("cannot write the trace to " + file + ": " + notAName.getMessage());
        }
        if (Files.isDirectory(path)) {
            throw new Unwritable("cannot write the trace to " + file + ": it is a folder");
        }
        try {
            return new TraceOutput(file, new BufferedWriter(Files.newBufferedWriter(path, StandardCharsets.UTF_8)), limit);
        } catch (IOException cannotWrite) {
            throw new Unwritable("cannot write the trace to " + file + ": " + cannotWrite.getMessage());
        }
    }

    /** The trace cannot be opened for writing: a failed run, exit status 2, as a trace lost later is (§15). */
    static final class Unwritable extends Exception {
        Unwritable(String message) {
            super(message);
        }
    }

    /** What the mission records into. */
    Trace trace() {
        return trace == null ? Trace.NONE : trace;
    }

    /** What to do when a write fails: stop the mission, whose trace is lost (at once if it is). */
    void whenFailed(Runnable action) {
        synchronized (this) {
            onFailure = action;
        }
        if (trace != null && trace.failure().isPresent()) {
            action.run();
        }
    }

    private void failed() {
        Runnable action;
        synchronized (this) {
            action = onFailure;
        }
        action.run();
    }

    /** Writes what is buffered and closes the file; a failure then loses the trace too. */
    void close() {
        if (writer == null) {
            return;
        }
        try {
            writer.close();
        } catch (IOException cannotWrite) {
            closeFailure = cannotWrite;
        }
    }

    /** Why the trace is lost, if it is: the first write that failed, during the run or at its close. */
    Optional<String> lost() {
        if (trace == null) {
            return Optional.empty();
        }
        return trace.failure().or(() -> Optional.ofNullable(closeFailure))
                .map(failure -> "cannot write the trace to " + file + ": " + OutputFolder.reason(failure));
    }

    /** What standard error says of a trace cut at its limit, if it was. */
    Optional<String> cut() {
        return trace != null && trace.wasCut() ? Optional.of(cutAt(file, limit)) : Optional.empty();
    }

    /** What standard error says of the trace {@code file} cut at {@code limit} bytes: a plain run's, or a simulation's {@code trace.jsonl}. */
    static String cutAt(Object file, long limit) {
        return "the trace " + file + " was cut at its limit of " + limit + " bytes (--trace-limit)";
    }
}
