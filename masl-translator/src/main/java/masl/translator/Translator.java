package masl.translator;

import java.util.Map;
import masl.runtime.descriptor.AgentPath;
import masl.translator.generate.Generator;
import masl.translator.source.SourceFile;

/**
 * Translates MASL programs to Java: parse, analyse against the agent descriptors found along the
 * agent path, generate (masl-runtime/docs/generated-code-contract.md). Used by the command line and
 * the Gradle plug-in. {@link MissionLoader} compiles a translation in memory and runs it.
 */
public final class Translator {

    private final Frontend frontend;

    public Translator(AgentPath agentPath) {
        this.frontend = new Frontend(agentPath);
    }

    /** Parse, analyse, generate; never throws for errors in the program or descriptors. */
    public Translation translate(SourceFile source) {
        Frontend.Result analysed = frontend.analyse(source);
        if (!analysed.succeeded()) {
            return new Translation(source, analysed.diagnostics(), null, Map.of());
        }
        Generator.Output output = new Generator().generate(analysed.program(), source.name(), analysed.diagnostics());
        if (output == null) {
            return new Translation(source, analysed.diagnostics(), null, Map.of());
        }
        return new Translation(source, analysed.diagnostics(), output.missionClassName(), output.javaSources());
    }
}
