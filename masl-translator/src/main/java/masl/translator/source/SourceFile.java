package masl.translator.source;

import java.io.IOException;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.nio.ByteBuffer;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * A MASL program's text and where it came from.
 *
 * @param name the file as the user named it: the name every diagnostic carries
 * @param folder the folder descriptors are looked up in first (MASL §4), or null for a program given as a string
 * @param text the program text
 */
public record SourceFile(String name, Path folder, String text) {

    /** The byte order mark some editors put at the start of a UTF-8 file: not part of the program. */
    private static final char BYTE_ORDER_MARK = '\uFEFF';

    /**
     * Reads a program file as UTF-8, without the byte order mark it may start with; bytes that are
     * not UTF-8 are read as Latin-1 rather than rejected, so the parser reports the offending
     * characters with their position.
     */
    public static SourceFile read(Path file) throws IOException {
        byte[] bytes = Files.readAllBytes(file);
        String text;
        try {
            text = StandardCharsets.UTF_8.newDecoder()
                    .onMalformedInput(CodingErrorAction.REPORT)
                    .decode(ByteBuffer.wrap(bytes))
                    .toString();
        } catch (CharacterCodingException notUtf8) {
            text = new String(bytes, StandardCharsets.ISO_8859_1);
        }
        if (!text.isEmpty() && text.charAt(0) == BYTE_ORDER_MARK) {
            text = text.substring(1);
        }
        Path folder = file.toAbsolutePath().getParent();
        return new SourceFile(file.toString(), folder, text);
    }

    public static SourceFile of(String name, String text) {
        return new SourceFile(name, null, text);
    }
}
