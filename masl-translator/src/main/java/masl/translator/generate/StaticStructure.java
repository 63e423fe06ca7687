package masl.translator.generate;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import masl.translator.analysis.Block;
import masl.translator.analysis.ESequence;
import masl.translator.analysis.EventDecl;
import masl.translator.analysis.MaslType;
import masl.translator.analysis.Reaction;
import masl.translator.analysis.Sharing;
import masl.translator.analysis.Variable;

/**
 * The static structure of a program (generated-code contract §1.1): one {@code EntryDefinition}
 * constant per block, one {@code ESequence} per e-sequence of several blocks, one
 * {@code SharedDeclaration} per shared variable, one {@code Event} per event and one {@code Reaction}
 * per {@code react} (contract §7.1), built in program order in the mission class.
 */
final class StaticStructure {

    /** About 20 bytes of class initialiser each: 1,000 stay far below the 64 KB of a method. */
    static final int DECLARATIONS_PER_CLASS = 1_000;

    private final String sourceName;
    private final JavaNames.Unique names = JavaNames.Unique.besideGeneratedNames();
    private final Map<Block, String> blocks = new IdentityHashMap<>();
    private final Map<ESequence, String> sequences = new IdentityHashMap<>();
    private final Map<Variable, String> shared = new IdentityHashMap<>();
    private final Map<EventDecl, String> events = new HashMap<>();
    private final Map<masl.translator.analysis.Label, String> sharedLabels = new HashMap<>();
    private final Map<Reaction, String> reactions = new HashMap<>();
    private final List<String> declarations = new ArrayList<>();
    private List<List<String>> groups;

    StaticStructure(Block root, String sourceName) {
        this.sourceName = sourceName;
        if (root != null) {
            String name = names.take(JavaNames.constant(root.name()));
            blocks.put(root, name);
            declarations.add("// " + JavaText.comment(sourceName + ":" + line(root) + ": " + root));
            declarations.add("static final EntryDefinition " + name + " = EntryDefinition.main("
                    + JavaText.quote(root.name()) + ", " + mode(root) + ");");
            declareContents(root);
        }
    }

    /** The constant of a block's definition. */
    String block(Block block) {
        return blocks.get(block);
    }

    /** The expression of an e-sequence: its constant, or {@code BLOCK.sequence()} for a block standing alone. */
    String sequence(ESequence sequence) {
        String name = sequences.get(sequence);
        return name != null ? name : block(sequence.blocks().get(0)) + ".sequence()";
    }

    /** The constant of the top-level e-sequence. */
    String topSequence(Block root) {
        return block(root) + ".sequence()";
    }

    /** The constant of a shared variable's declaration. */
    String shared(Variable variable) {
        return shared.get(variable);
    }

    /** The constant of an {@code SLabel}'s declaration: a shared variable holding the wave's label. */
    String sharedLabel(masl.translator.analysis.Label label) {
        return sharedLabels.get(label);
    }

    /** The expression of an event: its constant, or {@code Event.TIMEOUT} and the like for a system event. */
    String event(EventDecl event) {
        if (event.isSystemEvent()) {
            return "Event." + JavaNames.constant(event.name());
        }
        return events.get(event);
    }

    /** The constant of a reaction. */
    String reaction(Reaction reaction) {
        return reactions.get(reaction);
    }

    /**
     * The field declarations, in program order, each with the comment lines before it, in groups of
     * at most {@value #DECLARATIONS_PER_CLASS}: the first group in the mission class, each other one in
     * a holder class of its own ({@link #holders}), since a class initialiser holds at most 64 KB of bytecode.
     */
    List<List<String>> declarationGroups() {
        if (groups == null) {
            groups = grouped();
        }
        return groups;
    }

    private List<List<String>> grouped() {
        List<List<String>> groups = new ArrayList<>();
        List<String> group = new ArrayList<>();
        int count = 0;
        for (String line : declarations) {
            boolean declaration = !line.startsWith("//");
            if (declaration && count == DECLARATIONS_PER_CLASS) {
                groups.add(group);
                group = new ArrayList<>();
                count = 0;
            }
            group.add(line);
            count += declaration ? 1 : 0;
        }
        groups.add(group);
        return groups;
    }

    /** The holder classes of the declarations after the first group, in order: {@code Structure2}, .... */
    List<String> holders() {
        List<String> holders = new ArrayList<>();
        for (int i = 2; i <= declarationGroups().size(); i++) {
            holders.add("Structure" + i);
        }
        return holders;
    }

    private void declareContents(Block block) {
        String owner = blocks.get(block);
        for (Variable variable : block.variables()) {
            if (variable.sharing() == Sharing.SHARED) {
                String name = names.take(owner + "_" + JavaNames.constant(variable.name()));
                shared.put(variable, name);
                // An array's type says what a deployed agent's copy of it is made of (SharedElementWriter).
                String declared = variable.type() instanceof MaslType.ArrayOf
                        ? ".declareSharedArray(" + JavaText.quote(variable.name()) + ", " + JavaTypes.name(variable.type()) + ".class);"
                        : ".declareShared(" + JavaText.quote(variable.name()) + ", " + JavaTypes.defaultValue(variable.type()) + ");";
                declarations.add("static final SharedDeclaration<" + JavaTypes.boxed(variable.type()) + "> " + name
                        + " = " + owner + declared);
            }
        }
        for (masl.translator.analysis.Label label : block.labels()) {
            if (label.sharing() == Sharing.SHARED) {
                String name = names.take(owner + "_" + JavaNames.constant(label.name()));
                sharedLabels.put(label, name);
                declarations.add("static final SharedDeclaration<Label> " + name + " = " + owner + ".declareShared("
                        + JavaText.quote(label.name()) + ", null);");
            }
        }
        for (EventDecl event : block.events()) {
            String name = names.take(owner + "_" + JavaNames.constant(event.name()));
            events.put(event, name);
            declarations.add("static final Event " + name + " = " + owner + (event.sharing() == Sharing.SHARED
                    ? ".declareSharedEvent(" : ".declareLocalEvent(") + JavaText.quote(event.name()) + ");");
        }
        // In the order they are written: their priority (MASL 8).
        for (Reaction reaction : block.reactions()) {
            String name = names.take(owner + "_REACT_" + (reaction.isDefault() ? "DEFAULT"
                    : JavaNames.constant(reaction.event().name())));
            reactions.put(reaction, name);
            declarations.add("static final Reaction " + name + " = " + owner + (reaction.isDefault()
                    ? ".reactToDefault();" : ".react(" + event(reaction.event()) + ");"));
        }
        for (ESequence sequence : block.sequences()) {
            List<Block> members = sequence.blocks();
            if (members.size() == 1) {
                Block child = members.get(0);
                declareBlock(child, owner + ".child(");
            } else {
                String name = names.take(String.join("_", members.stream().map(b -> JavaNames.constant(b.name()))
                        .toList()) + "_SEQUENCE");
                sequences.put(sequence, name);
                declarations.add("// " + JavaText.comment(sourceName + ":" + line(members.get(0)) + ": the e-sequence "
                        + members.stream().map(Block::name).toList()));
                declarations.add("static final ESequence " + name + " = " + owner + ".newSequence();");
                for (Block child : members) {
                    declareBlock(child, name + ".block(");
                }
            }
        }
    }

    private void declareBlock(Block child, String factory) {
        String name = names.take(JavaNames.constant(child.name()));
        blocks.put(child, name);
        declarations.add("// " + JavaText.comment(sourceName + ":" + line(child) + ": " + child));
        declarations.add("static final EntryDefinition " + name + " = " + factory + JavaText.quote(child.name())
                + ", " + mode(child) + ");");
        declareContents(child);
    }

    private static String mode(Block block) {
        return "Mode." + block.mode().name();
    }

    private static int line(Block block) {
        return block.tree().getStart().getLine();
    }
}
