package masl.lsp;

import java.util.Optional;
import masl.runtime.descriptor.AgentType;
import org.eclipse.lsp4j.Hover;
import org.eclipse.lsp4j.MarkupContent;
import org.eclipse.lsp4j.MarkupKind;

/**
 * The hover text of what the cursor is on: a primitive's or attribute's description from its descriptor
 * ({@link AgentMemberDocs}), a block's mode and test, how a variable, event, label or agent is declared,
 * where an agent type comes from.
 */
final class Hovers {

    private Hovers() {
    }

    static Optional<Hover> at(Cursor cursor) {
        return Resolved.at(cursor).map(Hovers::markdown)
                .map(text -> new Hover(new MarkupContent(MarkupKind.MARKDOWN, text)));
    }

    /** {@code synchronous entry work}. */
    static String blockHeadline(ProgramIndex.Block block) {
        return block.mode + " entry " + block.name;
    }

    private static String markdown(Resolved resolved) {
        if (resolved instanceof Resolved.PrimitiveRef primitive) {
            return AgentMemberDocs.describe(primitive.primitive(), primitive.owners());
        }
        if (resolved instanceof Resolved.AttributeRef attribute) {
            return AgentMemberDocs.describe(attribute.attribute(), attribute.owners());
        }
        if (resolved instanceof Resolved.EntryMemberRef member) {
            return code(member.member().signature()) + "Entry member of `" + member.entry() + "` (zero duration): "
                    + member.member().description() + "." + (member.block() == null ? "" : "\n\n" + block(member.block()));
        }
        if (resolved instanceof Resolved.LabelMemberRef member) {
            return code(member.member().signature()) + "Member of label `" + member.label().name() + "` ("
                    + member.label().description() + "): " + member.member().description() + ".";
        }
        if (resolved instanceof Resolved.BlockRef block) {
            return block(block.block());
        }
        if (resolved instanceof Resolved.DeclaredRef declared) {
            ProgramIndex.Declared name = declared.declared();
            return code(name.description() + " " + name.name()) + "Declared in block `" + name.block().name + "` ("
                    + name.block().mode + ").";
        }
        if (resolved instanceof Resolved.AgentRef agent) {
            return code(agent.agent().typeName() + " " + agent.agent().name()) + "An agent of type `"
                    + agent.agent().typeName() + "`.";
        }
        if (resolved instanceof Resolved.SystemEventRef event) {
            return code(event.event().signature()) + "System event: " + event.event().description() + ".";
        }
        if (resolved instanceof Resolved.TypeRef type) {
            return type(type.type());
        }
        return type(((Resolved.DescriptorRef) resolved).type());
    }

    private static String block(ProgramIndex.Block block) {
        StringBuilder text = new StringBuilder(code(blockHeadline(block) + " (" + block.test + ")"));
        text.append("Mode: **").append(block.mode).append("** (").append(modeMeaning(block.mode)).append(").\n\n");
        text.append("Test: `").append(block.test).append("`");
        text.append(block.parent == null ? "; the top-level block (also `main`)." : "; inside `" + block.parent.name + "`.");
        return text.toString();
    }

    private static String modeMeaning(String mode) {
        return switch (mode) {
            case "scalar" -> "one agent among those that pass the test runs it, once per wave of its parent";
            case "synchronous" -> "its members run it in lock-step, instruction by instruction";
            case "asynchronous" -> "its members run it independently";
            default -> "unknown mode";
        };
    }

    private static String type(ProgramIndex.TypeDef type) {
        StringBuilder text = new StringBuilder(code("agent type " + type.name()));
        AgentType descriptor = type.descriptor();
        if (descriptor == null) {
            return text.append("Descriptor `").append(type.file())
                    .append("`: not found or with errors (see the diagnostics).").toString();
        }
        text.append("Descriptor `").append(descriptor.source().displayName()).append("`: implemented by `")
                .append(descriptor.fullClassName()).append('`');
        if (descriptor.supertype() != null) {
            text.append(", extends `").append(descriptor.supertype().shortName()).append('`');
        }
        text.append(".\n\n").append(descriptor.primitives().size()).append(" primitives, ")
                .append(descriptor.attributes().size()).append(" attributes");
        if (!descriptor.states().isEmpty()) {
            text.append("; permeability states: ").append(String.join(", ",
                    descriptor.states().stream().map(state -> state.name()).toList()));
        }
        return text.append('.').toString();
    }

    private static String code(String line) {
        return "```masl\n" + line + "\n```\n\n";
    }
}
