package masl.jade.deployment;

import java.util.List;
import masl.runtime.DeployedPrograms;
import masl.runtime.ESequence;
import masl.runtime.EntryDefinition;
import masl.runtime.Event;
import masl.runtime.SharedDeclaration;

/**
 * Names for a program's blocks, e-sequences, shared variables and events that mean the same in every
 * JVM that translated the same program: a block is the path of child indexes from the top-level block
 * ({@code "0.1"}: the second child of {@code main}), an e-sequence the name of its first block, a shared
 * variable its block and index, an event its block and name. Never a Java class or field name.
 */
final class Blocks {

    private final EntryDefinition main;

    Blocks(EntryDefinition main) {
        this.main = main;
    }

    static String name(EntryDefinition block) {
        EntryDefinition parent = block.parent();
        return parent == null ? "0" : name(parent) + "." + parent.children().indexOf(block);
    }

    EntryDefinition block(String name) {
        String[] steps = name.split("\\.");
        if (main == null || !steps[0].equals("0")) {
            throw new IllegalArgumentException("no block " + name);
        }
        EntryDefinition block = main;
        for (int i = 1; i < steps.length; i++) {
            List<EntryDefinition> children = block.children();
            int index = Integer.parseInt(steps[i]);
            if (index < 0 || index >= children.size()) {
                throw new IllegalArgumentException("no block " + name);
            }
            block = children.get(index);
        }
        return block;
    }

    static String name(ESequence sequence) {
        return name(sequence.blocks().get(0));
    }

    ESequence sequence(String name) {
        return block(name).sequence();
    }

    static String name(SharedDeclaration<?> declaration) {
        return name(declaration.block()) + ":" + declaration.index();
    }

    SharedDeclaration<?> shared(String name) {
        int colon = name.lastIndexOf(':');
        return block(name.substring(0, colon)).sharedDeclarations().get(Integer.parseInt(name.substring(colon + 1)));
    }

    /** {@code "0.1:go"}, or {@code ":timeout"} for a system event. */
    static String name(Event event) {
        return (event.block() == null ? "" : name(event.block())) + ":" + event.name();
    }

    Event event(String name) {
        int colon = name.indexOf(':');
        EntryDefinition block = colon == 0 ? null : block(name.substring(0, colon));
        Event event = DeployedPrograms.event(block, name.substring(colon + 1));
        if (event == null) {
            throw new IllegalArgumentException("no event " + name);
        }
        return event;
    }
}
