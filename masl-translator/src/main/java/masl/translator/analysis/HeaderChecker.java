package masl.translator.analysis;

import java.io.UncheckedIOException;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import masl.grammar.MASLParser;
import masl.runtime.descriptor.AgentType;
import masl.runtime.descriptor.DescriptorException;
import masl.runtime.descriptor.DescriptorLoader;
import masl.runtime.descriptor.DescriptorSource;
import masl.translator.diagnostics.Suggestions;
import masl.translator.parse.Literals;
import org.antlr.v4.runtime.CommonTokenStream;
import org.antlr.v4.runtime.Token;

/**
 * Checks the program's headers (MASL §3, §4): their order, the descriptors they import, the agent types
 * they name and the agents and entry names they declare. Loads each descriptor once.
 */
final class HeaderChecker {

    /** The header kinds in the order §3 prescribes. */
    private enum Kind {
        IMPORT("an import"), TYPE("a type declaration"), AGENTS("an agent declaration"), ENTRY("an Entry declaration");

        final String described;

        Kind(String described) {
            this.described = described;
        }
    }

    private final DescriptorLoader descriptors;
    private final Path programFolder;
    private final CommonTokenStream tokens;
    private final Errors errors;
    private final Map<String, ImportedType> types = new LinkedHashMap<>();
    private final List<AgentDecl> agents = new ArrayList<>();
    /** The agents' names, for the check of a name declared twice in time linear in the team's size. */
    private final Set<String> agentNames = new HashSet<>();
    private final Map<String, Token> declaredEntries = new LinkedHashMap<>();

    HeaderChecker(DescriptorLoader descriptors, Path programFolder, CommonTokenStream tokens, Errors errors) {
        this.descriptors = descriptors;
        this.programFolder = programFolder;
        this.tokens = tokens;
        this.errors = errors;
    }

    Map<String, ImportedType> types() {
        return types;
    }

    List<AgentDecl> agents() {
        return agents;
    }

    /** Each name of an {@code Entry} declaration, with where it is declared. */
    Map<String, Token> declaredEntries() {
        return declaredEntries;
    }

    void check(List<MASLParser.HeaderContext> headers) {
        Kind latest = Kind.IMPORT;
        for (MASLParser.HeaderContext header : headers) {
            Kind kind = kindOf(header);
            if (kind.ordinal() < latest.ordinal()) {
                errors.at(header, capitalised(kind.described) + " must come before " + latest.described
                        + ": the order is imports, types, agents, then Entry declarations");
            } else {
                latest = kind;
            }
            switch (kind) {
                case IMPORT -> checkImport(header.importDecl());
                case TYPE -> checkTypeDecl(header.typeDecl());
                case AGENTS -> checkAgents(header.agentsDecl());
                case ENTRY -> checkEntries(header.entryDecl());
            }
        }
    }

    private static Kind kindOf(MASLParser.HeaderContext header) {
        if (header.importDecl() != null) {
            return Kind.IMPORT;
        }
        if (header.typeDecl() != null) {
            return Kind.TYPE;
        }
        return header.agentsDecl() != null ? Kind.AGENTS : Kind.ENTRY;
    }

    private void checkImport(MASLParser.ImportDeclContext importDecl) {
        Optional<String> file = filePath(importDecl.filePath());
        AgentType descriptor = file.map(name -> load(name, importDecl.filePath())).orElse(null);
        String name;
        if (importDecl.typeName != null) {
            name = importDecl.typeName.getText();
        } else if (descriptor != null) {
            name = descriptor.shortName();
        } else {
            // Unloadable and unnamed: guess the name from the file, so that its uses raise no more errors.
            name = file.map(HeaderChecker::fileStem).orElse(null);
        }
        if (name != null) {
            define(new ImportedType(name, file.orElse(""), descriptor, false), importDecl.getStart());
        }
    }

    private void checkTypeDecl(MASLParser.TypeDeclContext typeDecl) {
        Optional<String> file = filePath(typeDecl.filePath());
        AgentType descriptor = file.map(name -> load(name, typeDecl.filePath())).orElse(null);
        define(new ImportedType(typeDecl.typeName.getText(), file.orElse(""), descriptor, true),
                typeDecl.typeName.getStart());
    }

    /**
     * §3: the same name twice is fine when it names the same file (written alike, or found at the same
     * place: the loader gives one type per location); the first definition stays.
     */
    private void define(ImportedType type, Token where) {
        ImportedType existing = types.get(type.name());
        if (existing == null) {
            types.put(type.name(), type);
            return;
        }
        boolean sameFile = existing.file().equals(type.file())
                || existing.isLoaded() && existing.descriptor() == type.descriptor();
        if (!sameFile) {
            errors.at(where, "agent type " + type.name() + " is already defined by " + existing.file());
        }
    }

    private void checkAgents(MASLParser.AgentsDeclContext agentsDecl) {
        ImportedType declared = agentType(agentsDecl.typeName);
        ImportedType instantiated = declared;
        boolean namesAnotherType = agentsDecl.instanceType != null
                && !agentsDecl.instanceType.getText().equals(agentsDecl.typeName.getText());
        if (namesAnotherType) {
            instantiated = agentType(agentsDecl.instanceType);
            if (!instantiated.isSubtypeOf(declared) && declared.isLoaded() && instantiated.isLoaded()) {
                errors.at(agentsDecl.instanceType, instantiated.name() + " is not a subtype of " + declared.name()
                        + ": agents declared " + declared.name() + " cannot be created as " + instantiated.name());
            }
        }
        for (MASLParser.IdentifierContext agentName : agentsDecl.identifierList().identifier()) {
            String name = agentName.getText();
            if (!agentNames.add(name)) {
                errors.at(agentName, "agent " + name + " is already declared");
            } else {
                agents.add(new AgentDecl(name, declared, instantiated, agents.size()));
            }
        }
    }

    /**
     * The type of that name. An unknown one is reported and then defined as a type whose descriptor is
     * unknown, so that its agents exist and their uses raise no more errors.
     */
    private ImportedType agentType(MASLParser.IdentifierContext name) {
        ImportedType type = types.get(name.getText());
        if (type == null) {
            String hint = Suggestions.hint(name.getText(), types.keySet());
            errors.at(name, "cannot find agent type " + name.getText() + (hint.isEmpty() ? ": import its descriptor first" : hint));
            type = new ImportedType(name.getText(), "", null, false);
            types.put(type.name(), type);
        }
        return type;
    }

    private void checkEntries(MASLParser.EntryDeclContext entryDecl) {
        for (MASLParser.IdentifierContext entryName : entryDecl.identifierList().identifier()) {
            if (declaredEntries.putIfAbsent(entryName.getText(), entryName.getStart()) != null) {
                errors.at(entryName, "Entry " + entryName.getText() + " is already declared");
            }
        }
    }

    /**
     * The descriptor path as written: a quoted path unquoted, an unquoted one from its first to its last
     * token. White space or a comment inside an unquoted path is an error (the grammar cannot see it).
     */
    private Optional<String> filePath(MASLParser.FilePathContext path) {
        if (path.StringLiteral() != null) {
            try {
                return Optional.of(Literals.string(path.StringLiteral().getText()));
            } catch (Literals.Problem checkedByTheParser) {
                throw new IllegalStateException(checkedByTheParser);
            }
        }
        StringBuilder visible = new StringBuilder();
        for (MASLParser.PathElementContext element : path.pathElement()) {
            visible.append(element.getText());
        }
        String written = tokens.getText(path.getStart(), path.getStop());
        if (!written.equals(visible.toString())) {
            errors.at(path, "a descriptor path with white space must be quoted: \"" + written.strip() + "\"");
            return Optional.empty();
        }
        return Optional.of(written);
    }

    /** The descriptor's type, or null after reporting why there is none. */
    private AgentType load(String file, MASLParser.FilePathContext where) {
        try {
            Optional<DescriptorSource> source = descriptors.agentPath().find(file, programFolder);
            if (source.isEmpty()) {
                errors.at(where, "cannot find descriptor " + file + ": looked in "
                        + descriptors.agentPath().describeLookup(programFolder)
                        + descriptorHint(file, descriptors.agentPath().descriptorNames(file, programFolder)));
                return null;
            }
            return descriptors.load(source.get());
        } catch (DescriptorException invalid) {
            invalid.problems().forEach(errors.diagnostics()::add);
            errors.at(where, "descriptor " + file + " has errors");
            return null;
        } catch (InvalidPathException impossiblePath) {
            errors.at(where, "cannot find descriptor " + file);
            return null;
        } catch (UncheckedIOException unreadable) {
            errors.at(where, "cannot read descriptor " + file + ": " + unreadable.getCause().getMessage());
            return null;
        }
    }

    /** The hint compares file names without their folder and {@code .xml}, which all candidates share. */
    private static String descriptorHint(String file, Set<String> candidates) {
        Map<String, String> byStem = new LinkedHashMap<>();
        candidates.forEach(candidate -> byStem.putIfAbsent(fileStem(candidate), candidate));
        return Suggestions.closest(fileStem(file), byStem.keySet())
                .map(stem -> "; did you mean `" + byStem.get(stem) + "`?").orElse("");
    }

    private static String fileStem(String file) {
        String name = file.substring(file.lastIndexOf('/') + 1);
        return name.endsWith(".xml") ? name.substring(0, name.length() - 4) : name;
    }

    private static String capitalised(String text) {
        return Character.toUpperCase(text.charAt(0)) + text.substring(1);
    }
}
