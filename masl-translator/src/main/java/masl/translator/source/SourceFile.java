package masl.translator.source;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.CharBuffer;
import java.nio.charset.CharsetDecoder;
import java.nio.charset.CoderResult;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
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
     * Reads a program file as UTF-8, without the byte order mark it may start with.
     *
     * @throws NotUtf8 if some bytes are not UTF-8: the program is refused at the first of them, since
     *         read in another encoding it would not be the text its author sees
     */
    public static SourceFile read(Path file) throws IOException {
        byte[] bytes = Files.readAllBytes(file);
        CharsetDecoder decoder = StandardCharsets.UTF_8.newDecoder()
                .onMalformedInput(CodingErrorAction.REPORT)
                .onUnmappableCharacter(CodingErrorAction.REPORT);
        ByteBuffer in = ByteBuffer.wrap(bytes);
        // UTF-8 never decodes to more chars than it has bytes.
        CharBuffer decoded = CharBuffer.allocate(bytes.length);
        CoderResult result = decoder.decode(in, decoded, true);
        if (!result.isError()) {
            result = decoder.flush(decoded);
        }
        String text = decoded.flip().toString();
        if (!text.isEmpty() && text.charAt(0) == BYTE_ORDER_MARK) {
            text = text.substring(1);
        }
        if (result.isError()) {
            throw new NotUtf8(file.toString(), text, bytes[in.position()]);
        }
        Path folder = file.toAbsolutePath().getParent();
        return new SourceFile(file.toString(), folder, text);
    }

    /** A program file whose bytes are not all UTF-8, positioned at the first byte that is not. */
    public static final class NotUtf8 extends IOException {
        private static final long serialVersionUID = 1L;

        /** @param before the text up to the byte, decoded */
        NotUtf8(String name, String before, byte first) {
            super(String.format("%s:%d:%d: error: byte 0x%02X is not UTF-8: MASL programs are UTF-8 (save the file as UTF-8)",
                    name, before.chars().filter(c -> c == '\n').count() + 1,
                    before.codePointCount(before.lastIndexOf('\n') + 1, before.length()) + 1, first & 0xff));
        }
    }

    public static SourceFile of(String name, String text) {
        return new SourceFile(name, null, text);
    }
}
