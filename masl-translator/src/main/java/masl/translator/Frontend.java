package masl.translator;

import masl.runtime.descriptor.AgentPath;
import masl.runtime.descriptor.DescriptorLoader;
import masl.translator.analysis.AnalyzedProgram;
import masl.translator.analysis.Analyzer;
import masl.translator.diagnostics.Diagnostics;
import masl.translator.parse.Nesting;
import masl.translator.parse.ProgramParser;
import masl.translator.source.SourceFile;

/**
 * The front half of the {@link Translator}'s pipeline: parse, then analyse against the descriptors.
 * A program whose syntax errors were all repaired as the user meant is analysed too, so that its
 * other errors are reported in the same run; any other repair stops it before the analysis, whose
 * messages would mostly be echoes of the syntax errors.
 */
public final class Frontend {

    /** The analysed program, or null when {@code diagnostics} holds errors. */
    public record Result(SourceFile source, AnalyzedProgram program, Diagnostics diagnostics) {
        public boolean succeeded() {
            return !diagnostics.hasErrors();
        }
    }

    private final AgentPath agentPath;

    public Frontend(AgentPath agentPath) {
        this.agentPath = agentPath;
    }

    /** Parses and analyses {@code source} on a thread with a deep stack ({@link DeepStack}). */
    public Result analyse(SourceFile source) {
        try {
            return DeepStack.call("masl check " + source.name(), () -> analyseHere(source));
        } catch (DeepStack.TooDeep overflow) {
            return new Result(source, null, tooDeep(source));
        }
    }

    /** The diagnostics of a program that nests too deeply even for the deep stack. */
    static Diagnostics tooDeep(SourceFile source) {
        Diagnostics diagnostics = new Diagnostics();
        Nesting.reportTooDeep(source, diagnostics);
        return diagnostics;
    }

    /** {@link #analyse} on this thread, whose stack must be deep. */
    Result analyseHere(SourceFile source) {
        Diagnostics diagnostics = new Diagnostics();
        ProgramParser.Parsed parsed = ProgramParser.parse(source, diagnostics);
        if (parsed.repaired()) {
            return new Result(source, null, diagnostics);
        }
        AnalyzedProgram program = Analyzer.analyze(parsed, new DescriptorLoader(agentPath), diagnostics);
        return new Result(source, diagnostics.hasErrors() ? null : program, diagnostics);
    }
}
