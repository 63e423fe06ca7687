package masl.e2e;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.MalformedInputException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * Code, tests and documents cite the manual by section: {@code MASL §6.3} (or {@code language.md §6.3}),
 * {@code xode.md §10.8}, {@code components.md, "Agent path"}. Every such citation in the repository
 * names a section that docs/manual has, so that renumbering a page or renaming a heading cannot
 * leave a reader pointed at nothing.
 */
class ManualCitationsTest {

    private static final Path MANUAL = Path.of("docs/manual");
    private static final Pattern NUMBERED = Pattern.compile("\\b(MASL|MASL\\.md|language\\.md|xode\\.md) §(\\d+(?:\\.\\d+)?)");
    private static final Pattern NAMED = Pattern.compile(
            "\\b(components|agent-types|examples|language|guide|xode)\\.md`?(?:,? +\\(?|,? *\\()\"([^\"]+)\"");
    private static final Set<String> SKIPPED_FOLDERS = Set.of("build", ".git", ".gradle", "node_modules", "out");
    private static final Set<String> TEXT = Set.of("java", "md", "g4", "gradle", "xml", "masl", "kts", "properties");

    @Test
    void everySectionTheRepositoryCitesIsInTheManual() throws IOException {
        List<String> broken = new ArrayList<>();
        for (Path file : textFiles()) {
            List<String> lines = lines(file);
            for (int i = 0; i < lines.size(); i++) {
                for (String citation : brokenCitations(lines.get(i))) {
                    broken.add(file + ":" + (i + 1) + ": " + citation);
                }
            }
        }
        if (!broken.isEmpty()) {
            throw new AssertionError("citations of sections the manual does not have:\n" + String.join("\n", broken));
        }
    }

    @Test
    void aCitationOfAMissingSectionIsFound() {
        if (!brokenCitations("see MASL §6.3 and xode.md §10.8, components.md, \"Agent path\"").isEmpty()) {
            throw new AssertionError("existing sections reported missing");
        }
        // Written in pieces, so that this file cites nothing itself.
        List<String> broken = brokenCitations(
                "MASL " + "§6.9, xode" + ".md §10.18, agent-types" + ".md, \"No such heading\"");
        if (broken.size() != 3) {
            throw new AssertionError("missing sections not all found: " + broken);
        }
    }

    private static List<String> brokenCitations(String line) {
        List<String> broken = new ArrayList<>();
        Matcher numbered = NUMBERED.matcher(line);
        while (numbered.find()) {
            String page = numbered.group(1).startsWith("xode") ? "xode.md" : "language.md";
            if (!Headings.of(page).numbers().contains(numbered.group(2))) {
                broken.add(numbered.group());
            }
        }
        Matcher named = NAMED.matcher(line);
        while (named.find()) {
            String wanted = named.group(2).toLowerCase(Locale.ROOT);
            if (Headings.of(named.group(1) + ".md").titles().stream().noneMatch(title -> title.startsWith(wanted))) {
                broken.add(named.group());
            }
        }
        return broken;
    }

    /** A page's section numbers (headings, and the numbered items of a numbered section: §10.8) and titles. */
    private record Headings(Set<String> numbers, List<String> titles) {

        private static final Pattern HEADING = Pattern.compile("^#+ +(?:(\\d+(?:\\.\\d+)?)\\.? +)?(.*)$");
        private static final Pattern ITEM = Pattern.compile("^(\\d+)\\. ");

        private static final Map<String, Headings> PAGES = new ConcurrentHashMap<>();

        static Headings of(String page) {
            return PAGES.computeIfAbsent(page, Headings::read);
        }

        private static Headings read(String page) {
            Set<String> numbers = new HashSet<>();
            List<String> titles = new ArrayList<>();
            String section = null;
            for (String line : lines(MANUAL.resolve(page))) {
                Matcher heading = HEADING.matcher(line);
                Matcher item = ITEM.matcher(line);
                if (heading.matches()) {
                    section = heading.group(1);
                    if (section != null) {
                        numbers.add(section);
                    }
                    titles.add(heading.group(2).toLowerCase(Locale.ROOT));
                } else if (section != null && item.find()) {
                    numbers.add(section + "." + item.group(1));
                }
            }
            return new Headings(numbers, titles);
        }
    }

    private static List<Path> textFiles() throws IOException {
        try (Stream<Path> files = Files.walk(Path.of("."))) {
            return files.filter(file -> Files.isRegularFile(file) && isText(file) && !inSkippedFolder(file)).toList();
        }
    }

    private static boolean isText(Path file) {
        String name = file.getFileName().toString();
        return TEXT.contains(name.substring(name.lastIndexOf('.') + 1));
    }

    private static boolean inSkippedFolder(Path file) {
        for (Path part : file) {
            if (SKIPPED_FOLDERS.contains(part.toString())) {
                return true;
            }
        }
        return false;
    }

    private static List<String> lines(Path file) {
        try {
            return Files.readAllLines(file);
        } catch (MalformedInputException e) {
            return List.of();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
