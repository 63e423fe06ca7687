package masl.cli;

import java.io.IOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;

/** A folder a command writes its output to, checked before the work that fills it starts. */
final class OutputFolder {

    private OutputFolder() {
    }

    /**
     * Creates {@code folder} if missing and writes a file in it (then deletes it).
     *
     * @return null if it can be written, else why not, in words
     */
    static String cannotWrite(Path folder) {
        try {
            Files.createDirectories(folder);
            Files.delete(Files.createTempFile(folder, ".masl-", ".tmp"));
            return null;
        } catch (IOException | SecurityException | UnsupportedOperationException failed) {
            return reason(failed);
        }
    }

    /** An I/O failure in words: Java's own messages are often just the path. */
    static String reason(Exception failed) {
        if (failed instanceof AccessDeniedException denied) {
            return "permission denied (" + denied.getFile() + ")";
        }
        if (failed instanceof FileAlreadyExistsException exists) {
            return exists.getFile() + " exists and is not a folder";
        }
        if (failed instanceof NoSuchFileException missing) {
            return "cannot create " + missing.getFile();
        }
        if (failed instanceof FileSystemException other && other.getReason() != null) {
            return other.getReason() + " (" + other.getFile() + ")";
        }
        return String.valueOf(failed.getMessage());
    }
}
