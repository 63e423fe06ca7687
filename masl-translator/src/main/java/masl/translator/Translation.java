package masl.translator;

import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.Map;
import masl.translator.diagnostics.Diagnostics;
import masl.translator.source.SourceFile;

/**
 * The result of translating one MASL program.
 *
 * @param source the program translated
 * @param diagnostics every error found in the program, its descriptors, or constructs not translated yet
 * @param missionClassName the fully qualified name of the generated mission class (a
 *        {@code masl.runtime.MissionProgram}), null when there are errors
 * @param javaSources the generated compilation units, fully qualified class name to source text, the
 *        mission class first; empty when there are errors
 */
public record Translation(SourceFile source, Diagnostics diagnostics, String missionClassName,
        Map<String, String> javaSources) {

    public Translation {
        javaSources = Collections.unmodifiableMap(new LinkedHashMap<>(javaSources));
    }

    /** Whether the program translated without error: then the sources are complete. */
    public boolean succeeded() {
        return !diagnostics.hasErrors() && missionClassName != null;
    }
}
