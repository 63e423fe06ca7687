package masl.translator;

import java.util.stream.Collectors;
import masl.runtime.descriptor.AgentPath;
import masl.runtime.diagnostic.Diagnostic;
import masl.translator.source.SourceFile;

/** The errors {@code masl check} reports for a program, as their headlines, one a line. */
final class FrontendErrors {

    /** Two lines: the type {@code Default} and its agents {@code a} and {@code b}. */
    private static final String HEADER = "import Default.xml as Default;\nDefault a, b = newAgent(Default);\n";

    private FrontendErrors() {
    }

    /** The errors of {@code body} after the two lines of {@link #HEADER}: its first line is line 3. */
    static String errorsOf(String body) {
        Frontend.Result result = new Frontend(AgentPath.parse("")).analyse(SourceFile.of("p.masl", HEADER + body));
        return result.diagnostics().sorted().stream().map(Diagnostic::headline).collect(Collectors.joining("\n"));
    }
}
