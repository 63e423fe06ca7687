package masl.lsp;

import java.io.UncheckedIOException;
import java.nio.file.InvalidPathException;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import masl.grammar.MASLParser;
import masl.runtime.descriptor.AgentPath;
import masl.runtime.descriptor.AgentType;
import masl.runtime.descriptor.DescriptorException;
import masl.runtime.descriptor.DescriptorLoader;
import masl.runtime.descriptor.DescriptorSource;
import masl.translator.diagnostics.Diagnostics;
import masl.translator.parse.ProgramParser;
import masl.translator.source.SourceFile;
import org.antlr.v4.runtime.CommonTokenStream;
import org.antlr.v4.runtime.ParserRuleContext;
import org.antlr.v4.runtime.Token;
import org.antlr.v4.runtime.tree.ParseTree;

/**
 * What the editor features need to know of one version of a program: its agent types with their loaded
 * descriptors, its agents, its {@code Entry} names and its tree of blocks with their declarations, all with
 * the tokens they are written at. Built from the parse tree alone, so that it is there while the program
 * is being typed and does not parse or type-check: ANTLR's recovery keeps the blocks around a syntax error.
 * The diagnostics come from the translator, never from here.
 */
final class ProgramIndex {

    /** The top-level block is also {@code main}, whatever its name (MASL §3). */
    static final String MAIN = "main";

    /**
     * An agent type of the program: {@code import F [as N];} or {@code type N use F;}.
     *
     * @param nameToken the name as written, or null for an import without {@code as}
     * @param descriptor the loaded type, or null when its descriptor cannot be found or has errors
     */
    record TypeDef(String name, Token nameToken, MASLParser.FilePathContext path, String file, AgentType descriptor) {
    }

    /** An agent of the population and the type it is declared with. */
    record AgentDef(String name, Token token, String typeName) {
    }

    enum Kind { VARIABLE, EVENT, LABEL }

    /**
     * A name declared in a block.
     *
     * @param description how it is declared, e.g. {@code shared int}, {@code local event}, {@code SLabel}
     * @param typeName the declared Java or agent type of a variable as written, null for events and labels
     */
    record Declared(Kind kind, String name, Token token, String description, String typeName, Block block) {
    }

    /** An entry block: its name, mode and test as written, its declarations and child blocks. */
    static final class Block {
        final MASLParser.EntryBlockContext tree;
        final String name;
        final Token nameToken;
        final String mode;
        final String test;
        final Block parent;
        final List<Declared> declarations = new ArrayList<>();
        final List<Block> children = new ArrayList<>();

        Block(MASLParser.EntryBlockContext tree, Block parent, String test) {
            this.tree = tree;
            this.name = tree.name == null ? "" : tree.name.getText();
            this.nameToken = tree.name == null ? tree.getStart() : tree.name.getStart();
            this.mode = tree.blockMode() == null ? "" : tree.blockMode().getText();
            this.test = test;
            this.parent = parent;
        }

        /** Whether the code point at {@code index} lies within the block, braces included. */
        boolean contains(int index) {
            Token stop = tree.getStop();
            int end = stop == null || stop.getStopIndex() < tree.getStart().getStartIndex() ? Integer.MAX_VALUE
                    : stop.getType() == Token.EOF ? Integer.MAX_VALUE : stop.getStopIndex();
            return tree.getStart().getStartIndex() <= index && index <= end;
        }
    }

    private final ProgramParser.Parsed parsed;
    /** The parse tree, empty for a program nested too deeply to be parsed (the diagnostics say where). */
    private final MASLParser.ProgramContext tree;
    private final AgentPath agentPath;
    private final Map<String, TypeDef> types = new LinkedHashMap<>();
    private final List<AgentDef> agents = new ArrayList<>();
    private final Map<String, Token> entryDecls = new LinkedHashMap<>();
    private final Map<String, Block> blocksByName = new LinkedHashMap<>();
    private final Block root;
    private List<Token> codeTokens;

    private ProgramIndex(ProgramParser.Parsed parsed, AgentPath agentPath) {
        this.parsed = parsed;
        this.tree = parsed.tree() != null ? parsed.tree() : new MASLParser.ProgramContext(null, -1);
        this.agentPath = agentPath;
        DescriptorLoader loader = new DescriptorLoader(agentPath);
        for (MASLParser.HeaderContext header : tree.header()) {
            if (header.importDecl() != null) {
                addType(header.importDecl().typeName, header.importDecl().filePath(), loader);
            } else if (header.typeDecl() != null) {
                addType(header.typeDecl().typeName, header.typeDecl().filePath(), loader);
            } else if (header.agentsDecl() != null) {
                addAgents(header.agentsDecl());
            } else if (header.entryDecl() != null && header.entryDecl().identifierList() != null) {
                header.entryDecl().identifierList().identifier()
                        .forEach(name -> entryDecls.putIfAbsent(name.getText(), name.getStart()));
            }
        }
        root = tree.entryBlock() == null ? null : block(tree.entryBlock(), null);
    }

    static ProgramIndex of(SourceFile source, AgentPath agentPath) {
        return new ProgramIndex(ProgramParser.parse(source, new Diagnostics()), agentPath);
    }

    CommonTokenStream tokens() {
        return parsed.tokens();
    }

    /** The tokens of the default channel (no white space, no comment), end of file left out. */
    synchronized List<Token> codeTokens() {
        if (codeTokens == null) {
            parsed.tokens().fill();
            codeTokens = parsed.tokens().getTokens().stream()
                    .filter(token -> token.getChannel() == Token.DEFAULT_CHANNEL && token.getType() != Token.EOF)
                    .toList();
        }
        return codeTokens;
    }

    MASLParser.ProgramContext tree() {
        return tree;
    }

    Map<String, TypeDef> types() {
        return types;
    }

    List<AgentDef> agents() {
        return agents;
    }

    Optional<AgentDef> agent(String name) {
        return agents.stream().filter(agent -> agent.name().equals(name)).findFirst();
    }

    Map<String, Token> entryDecls() {
        return entryDecls;
    }

    /** The top-level block, or null. */
    Block root() {
        return root;
    }

    /** The block a jump or an entry member names: {@code main} is the top-level block. */
    Optional<Block> block(String name) {
        if (name.equals(MAIN) && root != null && !blocksByName.containsKey(MAIN)) {
            return Optional.of(root);
        }
        return Optional.ofNullable(blocksByName.get(name));
    }

    List<Block> blocks() {
        return List.copyOf(blocksByName.values());
    }

    /** Whether entry members may be used on that name: {@code main}, the top-level block, or declared with {@code Entry}. */
    boolean hasEntryMembers(String name) {
        return name.equals(MAIN) || root != null && root.name.equals(name) || entryDecls.containsKey(name);
    }

    /** The innermost block holding the code point at {@code index}, or null outside every block. */
    Block blockAt(int index) {
        if (root == null || !root.contains(index)) {
            return null;
        }
        Block inner = root;
        boolean deeper = true;
        while (deeper) {
            deeper = false;
            for (Block child : inner.children) {
                if (child.contains(index)) {
                    inner = child;
                    deeper = true;
                    break;
                }
            }
        }
        return inner;
    }

    /** The declaration a name means inside {@code from}: the innermost block declaring it wins. */
    Optional<Declared> lookup(String name, Block from) {
        for (Block block = from; block != null; block = block.parent) {
            for (Declared declared : block.declarations) {
                if (declared.name().equals(name)) {
                    return Optional.of(declared);
                }
            }
        }
        return Optional.empty();
    }

    /** The imported types' descriptors: what the current agent may be (MASL §4: every type of the program). */
    List<TypeDef> loadedTypes() {
        return types.values().stream().filter(type -> type.descriptor() != null).toList();
    }

    private void addType(MASLParser.IdentifierContext name, MASLParser.FilePathContext path, DescriptorLoader loader) {
        if (path == null) {
            return;
        }
        String file = filePath(path);
        AgentType descriptor = file == null ? null : load(file, loader);
        String typeName = name != null ? name.getText()
                : descriptor != null ? descriptor.shortName() : file == null ? null : fileStem(file);
        if (typeName != null) {
            types.putIfAbsent(typeName, new TypeDef(typeName, name == null ? null : name.getStart(), path, file,
                    descriptor));
        }
    }

    private void addAgents(MASLParser.AgentsDeclContext declaration) {
        if (declaration.identifierList() == null || declaration.typeName == null) {
            return;
        }
        for (MASLParser.IdentifierContext name : declaration.identifierList().identifier()) {
            agents.add(new AgentDef(name.getText(), name.getStart(), declaration.typeName.getText()));
        }
    }

    private Block block(MASLParser.EntryBlockContext tree, Block parent) {
        String test = tree.test == null ? "" : parsed.tokens().getText(tree.test.getStart(), tree.test.getStop());
        Block block = new Block(tree, parent, test);
        if (parent != null) {
            parent.children.add(block);
        }
        if (!block.name.isEmpty()) {
            blocksByName.putIfAbsent(block.name, block);
        }
        for (MASLParser.BlockItemContext item : tree.blockItem()) {
            if (item.declaration() != null) {
                declare(item.declaration(), block);
            } else {
                collectChildBlocks(item, block);
            }
        }
        return block;
    }

    /** Child blocks may stand anywhere among the statements: in an {@code if}, a loop, a reaction. */
    private void collectChildBlocks(ParseTree tree, Block parent) {
        if (tree instanceof MASLParser.EntryBlockContext child) {
            block(child, parent);
            return;
        }
        for (int i = 0; i < tree.getChildCount(); i++) {
            collectChildBlocks(tree.getChild(i), parent);
        }
    }

    private void declare(MASLParser.DeclarationContext declaration, Block block) {
        if (declaration instanceof MASLParser.VariableDeclContext variable && variable.identifierList() != null) {
            String type = variable.javaType() == null ? "" : text(variable.javaType());
            String description = variable.scope.getText() + (variable.FINAL() != null ? " final " : " ") + type
                    + (variable.limitedTo() != null ? " " + text(variable.limitedTo()) : "");
            variable.identifierList().identifier().forEach(name ->
                    block.declarations.add(new Declared(Kind.VARIABLE, name.getText(), name.getStart(), description,
                            type, block)));
        } else if (declaration instanceof MASLParser.EventDeclContext event && event.identifierList() != null) {
            event.identifierList().identifier().forEach(name ->
                    block.declarations.add(new Declared(Kind.EVENT, name.getText(), name.getStart(),
                            event.scope.getText() + " event", null, block)));
        } else if (declaration instanceof MASLParser.LabelDeclContext label && label.identifierList() != null) {
            label.identifierList().identifier().forEach(name ->
                    block.declarations.add(new Declared(Kind.LABEL, name.getText(), name.getStart(),
                            label.kind.getText(), null, block)));
        }
    }

    /** The source text of a node, spaces as written. */
    String text(ParserRuleContext tree) {
        return tree.getStop() == null ? tree.getText() : parsed.tokens().getText(tree.getStart(), tree.getStop());
    }

    /** The descriptor path as the translator reads it: a quoted path unquoted, else the tokens' text. */
    private String filePath(MASLParser.FilePathContext path) {
        if (path.StringLiteral() != null) {
            String quoted = path.StringLiteral().getText();
            return quoted.substring(1, quoted.length() - 1).replace("\\\"", "\"").replace("\\\\", "\\");
        }
        return path.getStop() == null || path.pathElement().isEmpty() ? null : text(path).strip();
    }

    private AgentType load(String file, DescriptorLoader loader) {
        try {
            Optional<DescriptorSource> source = loader.agentPath().find(file, parsed.source().folder());
            return source.map(loader::load).orElse(null);
        } catch (DescriptorException | InvalidPathException | UncheckedIOException unusable) {
            return null;
        }
    }

    /** Where the descriptor of an import is, when it can be found (even if it has errors). */
    Optional<DescriptorSource> descriptorSource(TypeDef type) {
        if (type.descriptor() != null) {
            return Optional.of(type.descriptor().source());
        }
        try {
            return type.file() == null ? Optional.empty() : agentPath.find(type.file(), parsed.source().folder());
        } catch (InvalidPathException | UncheckedIOException unusable) {
            return Optional.empty();
        }
    }

    private static String fileStem(String file) {
        String name = file.substring(file.lastIndexOf('/') + 1);
        return name.endsWith(".xml") ? name.substring(0, name.length() - 4) : name;
    }
}
