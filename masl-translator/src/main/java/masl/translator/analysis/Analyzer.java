package masl.translator.analysis;

import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import masl.grammar.MASLParser;
import masl.runtime.descriptor.DescriptorLoader;
import masl.translator.diagnostics.Diagnostics;
import masl.translator.parse.ConstantLimits;
import masl.translator.parse.ProgramParser;
import org.antlr.v4.runtime.Token;

/**
 * Name resolution and type checking of a parsed MASL program: reports every semantic error of the file
 * and builds the {@link AnalyzedProgram} the code generator works from.
 *
 * <p>A tree repaired after a syntax error by a guess ({@link ProgramParser.Parsed#repaired}) is not
 * analysed: its repaired parts would produce errors about text the user did not write. Such a program gets an empty model and no further error,
 * the syntax errors already being reported.
 */
public final class Analyzer {

    private Analyzer() {
    }

    public static AnalyzedProgram analyze(ProgramParser.Parsed parsed, DescriptorLoader descriptors,
            Diagnostics diagnostics) {
        MASLParser.ProgramContext tree = parsed.tree();
        if (parsed.repaired()) {
            return new AnalyzedProgram(parsed, Map.of(), List.of(), new LinkedHashSet<>(), null, new Bindings(0));
        }
        Errors errors = new Errors(parsed.source().name(), diagnostics);
        for (ConstantLimits.Problem problem : parsed.constantProblems()) {
            if (problem.node() != null) {
                errors.at(problem.node(), problem.message());
            } else {
                errors.at(problem.token(), problem.message());
            }
        }
        HeaderChecker headers = new HeaderChecker(descriptors, parsed.source().folder(), parsed.tokens(), errors);
        headers.check(tree.header());

        BlockTreeBuilder blockTree = new BlockTreeBuilder(errors);
        Block root = tree.entryBlock() == null ? null : blockTree.build(tree.entryBlock());
        for (Map.Entry<String, Token> entry : headers.declaredEntries().entrySet()) {
            if (!blockTree.blocksByName().containsKey(entry.getKey()) && !entry.getKey().equals(EntryNames.MAIN)) {
                errors.at(entry.getValue(), "Entry " + entry.getKey() + " names no entry block");
            }
        }

        Bindings bindings = new Bindings(parsed.nodes());
        TypeNames typeNames = new TypeNames(headers.types(), descriptors.implementationClasses());
        EntryNames entryNames = new EntryNames(root, blockTree.blocksByName(), headers.declaredEntries().keySet(),
                errors);
        MemberTyper members = new MemberTyper(bindings, errors, new AgentMembers(headers.types().values()), typeNames);
        ExpressionTyper typer = new ExpressionTyper(bindings, errors, typeNames, entryNames, members);
        if (root != null) {
            new BlockChecker(errors, blockTree.blocks(), typeNames, entryNames, typer, bindings)
                    .check(tree.entryBlock(), programScope(headers));
        }
        return new AnalyzedProgram(parsed, headers.types(), headers.agents(),
                new LinkedHashSet<>(headers.declaredEntries().keySet()), root, bindings);
    }

    /** The names visible everywhere: the agents and the system events (§8). */
    private static Scope programScope(HeaderChecker headers) {
        Scope scope = new Scope(null);
        for (AgentDecl agent : headers.agents()) {
            scope.declare(agent.name(), agent);
        }
        for (EventDecl event : EventDecl.SYSTEM_EVENTS) {
            scope.declare(event.name(), event);
        }
        return scope;
    }
}
