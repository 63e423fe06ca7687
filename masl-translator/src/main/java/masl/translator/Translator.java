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

    /**
     * Parse, analyse, generate, on a thread with a deep stack ({@link DeepStack}); never throws for
     * errors in the program or descriptors.
     */
    public Translation translate(SourceFile source) {
        try {
            return DeepStack.call("masl translate " + source.name(), () -> translateHere(source));
        } catch (DeepStack.TooDeep overflow) {
            return new Translation(source, Frontend.tooDeep(source), null, Map.of());
        }
    }

    private Translation translateHere(SourceFile source) {
        Frontend.Result analysed = frontend.analyseHere(source);
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
