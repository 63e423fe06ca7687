package masl.translator.generate;

import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.Map;
import java.util.Set;
import masl.grammar.MASLParser;
import masl.translator.analysis.AgentDecl;
import masl.translator.analysis.AnalyzedProgram;
import masl.translator.analysis.Block;
import masl.translator.analysis.EntryRef;
import masl.translator.analysis.ImportedType;
import masl.translator.diagnostics.Diagnostics;
import masl.translator.parse.NumberLiterals;
import org.antlr.v4.runtime.ParserRuleContext;
import org.antlr.v4.runtime.tree.ParseTree;
import org.antlr.v4.runtime.tree.TerminalNode;

/**
 * Generates the Java sources of an analysed MASL program (masl-runtime/docs/generated-code-contract.md):
 * in package {@code masl.generated.<id>} ({@code <id>} from the file's base name), the mission class
 * {@code <Id>Mission} and one {@code <Type>Program} per agent type instantiated by the program.
 * Constructs it cannot translate yet are reported as positioned errors; then no source is returned.
 */
public final class Generator {

    /** The generated sources: the mission class's full name and every class's text, by full name. */
    public record Output(String missionClassName, Map<String, String> javaSources) {
        public Output {
            javaSources = Collections.unmodifiableMap(new LinkedHashMap<>(javaSources));
        }
    }

    /** The package of the generated code of a program file: {@code hello.masl} → {@code masl.generated.hello}. */
    public static String packageOf(String fileName) {
        return "masl.generated." + JavaNames.missionId(fileName);
    }

    /**
     * Generates {@code program}, which the analysis accepted. Reports unsupported constructs to
     * {@code diagnostics}, and returns null if it did.
     */
    public Output generate(AnalyzedProgram program, String fileName, Diagnostics diagnostics) {
        String id = JavaNames.missionId(fileName);
        String packageName = "masl.generated." + id;
        String missionClass = JavaNames.missionClass(id);
        Unsupported unsupported = new Unsupported(fileName, diagnostics);
        // Comments name the file as the user knows it best, by its own name: `// hello.masl:4`.
        String shortName = java.nio.file.Path.of(fileName).getFileName().toString();
        StaticStructure structure = new StaticStructure(program.root(), shortName);
        Set<Block> kept = keptOnReelect(program);

        JavaNames.Unique classNames = JavaNames.Unique.besideGeneratedNames(missionClass);
        Map<String, String> programClasses = new LinkedHashMap<>();
        Map<String, String> programSources = new LinkedHashMap<>();
        ProgramClassWriter writer = new ProgramClassWriter(program, structure, unsupported, shortName, kept);
        for (AgentDecl agent : program.agents()) {
            ImportedType type = agent.instantiatedType();
            if (!programClasses.containsKey(type.name())) {
                String className = classNames.take(JavaNames.programClass(type.name()));
                programClasses.put(type.name(), className);
                programSources.put(packageName + "." + className,
                        writer.write(packageName, className, missionClass, type));
            }
        }
        if (diagnostics.hasErrors()) {
            return null;
        }
        Map<String, String> sources = new LinkedHashMap<>();
        sources.put(packageName + "." + missionClass,
                MissionClassWriter.write(packageName, missionClass, shortName, program, structure, programClasses));
        sources.putAll(programSources);
        return new Output(packageName + "." + missionClass, sources);
    }

    /** The blocks some {@code reelect} names: they keep their locals for an agent that enters again. */
    private static Set<Block> keptOnReelect(AnalyzedProgram program) {
        Set<Block> kept = new LinkedHashSet<>();
        if (program.root() != null) {
            collectReelects(program.root().tree(), program, blocksByTree(program.root(), new LinkedHashMap<>()), kept);
        }
        return kept;
    }

    private static Map<ParserRuleContext, Block> blocksByTree(Block block, Map<ParserRuleContext, Block> into) {
        into.put(block.tree(), block);
        block.children().forEach(child -> blocksByTree(child, into));
        return into;
    }

    private static void collectReelects(ParseTree tree, AnalyzedProgram program, Map<ParserRuleContext, Block> blocks,
            Set<Block> kept) {
        if (tree instanceof TerminalNode || tree instanceof MASLParser.ExpressionContext) {
            return; // no statement is inside an expression: most of the tree is not looked at
        }
        if (tree instanceof MASLParser.ReelectStmtContext reelect) {
            Block target = null;
            MASLParser.JumpTargetContext jump = reelect.jumpTarget();
            if (jump != null && jump.identifier() != null) {
                if (program.symbolOf(jump.identifier()).orElse(null) instanceof EntryRef entry) {
                    target = entry.block();
                }
            } else {
                int levels = jump == null ? 1 : NumberLiterals.count(jump.IntegerLiteral().getText());
                ParserRuleContext node = reelect;
                while (node != null && target == null) {
                    if (node instanceof MASLParser.EntryBlockContext && --levels == 0) {
                        target = blocks.get(node);
                    }
                    node = node.getParent();
                }
            }
            if (target != null) {
                kept.add(target);
            }
        }
        for (int i = 0; i < tree.getChildCount(); i++) {
            collectReelects(tree.getChild(i), program, blocks, kept);
        }
    }
}
