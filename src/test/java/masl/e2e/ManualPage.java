package masl.e2e;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * A page of the manual (docs/manual/*.md) as its fenced code blocks, in page order, each with its info
 * string read as a language, words and {@code key=value} attributes (```` ```masl fragment file=x.masl ````).
 */
record ManualPage(String name, List<ManualPage.CodeBlock> blocks) {

    /** One fenced block: where it starts (1-based line of its opening fence), its info string, its text. */
    record CodeBlock(String page, int line, String language, List<String> words, Map<String, String> attributes,
            String text) {

        boolean is(String language, String word) {
            return this.language.equals(language) && words.contains(word);
        }

        String where() {
            return page + ":" + line;
        }
    }

    static ManualPage read(Path file) {
        try {
            return parse(file.getFileName().toString(), Files.readString(file));
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    static ManualPage parse(String name, String markdown) {
        List<CodeBlock> blocks = new ArrayList<>();
        String[] lines = markdown.split("\n", -1);
        for (int i = 0; i < lines.length; i++) {
            String opening = lines[i].stripLeading();
            if (!opening.startsWith("```")) {
                continue;
            }
            String indent = lines[i].substring(0, lines[i].length() - opening.length());
            String fence = opening.substring(0, runOfBackticks(opening));
            int start = i;
            StringBuilder text = new StringBuilder();
            for (i++; i < lines.length && !lines[i].strip().equals(fence); i++) {
                String line = lines[i].startsWith(indent) ? lines[i].substring(indent.length()) : lines[i].stripLeading();
                text.append(line).append('\n');
            }
            if (i == lines.length) {
                throw new AssertionError(name + ":" + (start + 1) + ": a code block that is never closed");
            }
            blocks.add(block(name, start + 1, opening.substring(fence.length()).strip(), text.toString()));
        }
        return new ManualPage(name, List.copyOf(blocks));
    }

    private static int runOfBackticks(String line) {
        int n = 0;
        while (n < line.length() && line.charAt(n) == '`') {
            n++;
        }
        return n;
    }

    private static CodeBlock block(String page, int line, String info, String text) {
        String[] parts = info.isEmpty() ? new String[0] : info.split("\\s+");
        String language = parts.length == 0 ? "" : parts[0];
        List<String> words = new ArrayList<>();
        Map<String, String> attributes = new LinkedHashMap<>();
        for (int i = 1; i < parts.length; i++) {
            int equals = parts[i].indexOf('=');
            if (equals < 0) {
                words.add(parts[i]);
            } else {
                attributes.put(parts[i].substring(0, equals), parts[i].substring(equals + 1));
            }
        }
        return new CodeBlock(page, line, language, List.copyOf(words), Map.copyOf(attributes), text);
    }
}
