package masl.lsp;

import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Optional;
import masl.grammar.MASLLexer;
import masl.runtime.descriptor.AgentType;
import masl.runtime.descriptor.Attribute;
import masl.runtime.descriptor.Primitive;
import org.antlr.v4.runtime.Token;

/**
 * What the word under the cursor stands for, for hover and go to definition. Names are resolved as the
 * analysis resolves them (MASL §3): the innermost declaring block first, then the agents, the system events,
 * entry names and agent types; a member after a {@code .} by what stands before it ({@link Receiver}).
 */
sealed interface Resolved {

    /** A primitive; {@code owners} are the program's types that have it, by MASL name. */
    record PrimitiveRef(Primitive primitive, Map<String, AgentType> owners) implements Resolved { }

    record AttributeRef(Attribute attribute, Map<String, AgentType> owners) implements Resolved { }

    /** An entry member; {@code block} is null when the name before it names no block. */
    record EntryMemberRef(Vocabulary.FixedMember member, String entry, ProgramIndex.Block block) implements Resolved { }

    record LabelMemberRef(Vocabulary.FixedMember member, ProgramIndex.Declared label) implements Resolved { }

    record BlockRef(ProgramIndex.Block block) implements Resolved { }

    record DeclaredRef(ProgramIndex.Declared declared) implements Resolved { }

    record AgentRef(ProgramIndex.AgentDef agent) implements Resolved { }

    record SystemEventRef(Vocabulary.FixedMember event) implements Resolved { }

    /** An agent type's name: it leads to its import. */
    record TypeRef(ProgramIndex.TypeDef type) implements Resolved { }

    /** The path of an import, or the name it gives: it leads to the descriptor. */
    record DescriptorRef(ProgramIndex.TypeDef type) implements Resolved { }

    static Optional<Resolved> at(Cursor cursor) {
        int at = cursor.tokenAt();
        if (at < 0) {
            return Optional.empty();
        }
        Token token = cursor.tokens.get(at);
        ProgramIndex index = cursor.index;
        for (ProgramIndex.TypeDef type : index.types().values()) {
            boolean inPath = type.path().getStart().getTokenIndex() <= token.getTokenIndex()
                    && type.path().getStop() != null && token.getTokenIndex() <= type.path().getStop().getTokenIndex();
            if (inPath || type.nameToken() == token) {
                return Optional.of(new DescriptorRef(type));
            }
        }
        if (!Receiver.isName(token)) {
            return Optional.empty();
        }
        String name = token.getText();
        int previous = cursor.typeAt(at - 1);
        if (previous == MASLLexer.DOT) {
            return member(Receiver.before(cursor.tokens, at - 1, index, cursor.scope), name, index);
        }
        if (previous == MASLLexer.ENTRY) {
            return index.blocks().stream().filter(block -> block.nameToken == token).findFirst()
                    .<Resolved>map(BlockRef::new).or(() -> index.block(name).map(BlockRef::new));
        }
        int jump = cursor.typeAt(at - 2);
        if (previous == MASLLexer.LPAREN && (jump == MASLLexer.BREAK || jump == MASLLexer.REELECT)) {
            for (ProgramIndex.Block block = cursor.scope; block != null; block = block.parent) {
                if (block.name.equals(name)) {
                    return Optional.of(new BlockRef(block));
                }
            }
        }
        return name(name, cursor);
    }

    private static Optional<Resolved> member(Receiver receiver, String name, ProgramIndex index) {
        if (receiver instanceof Receiver.Entry entry) {
            return fixed(Vocabulary.ENTRY_MEMBERS, name)
                    .map(member -> new EntryMemberRef(member, entry.name(), index.block(entry.name()).orElse(null)));
        }
        if (receiver instanceof Receiver.Label label) {
            Optional<Resolved> labelMember = fixed(Vocabulary.LABEL_MEMBERS, name)
                    .map(member -> new LabelMemberRef(member, label.label()));
            if (labelMember.isPresent()) {
                return labelMember;
            }
            Optional<ProgramIndex.AgentDef> agent = index.agent(name);
            if (agent.isPresent()) {
                return Optional.of(new AgentRef(agent.get()));
            }
        }
        Map<String, AgentType> types = Receiver.agentTypes(receiver, index);
        Map<String, AgentType> owners = new LinkedHashMap<>();
        Primitive primitive = null;
        for (Map.Entry<String, AgentType> type : types.entrySet()) {
            Optional<Primitive> found = type.getValue().findPrimitive(name);
            if (found.isPresent()) {
                primitive = primitive == null ? found.get() : primitive;
                owners.put(type.getKey(), type.getValue());
            }
        }
        if (primitive != null) {
            return Optional.of(new PrimitiveRef(primitive, owners));
        }
        Attribute attribute = null;
        for (Map.Entry<String, AgentType> type : types.entrySet()) {
            Optional<Attribute> found = type.getValue().findAttribute(name);
            if (found.isPresent()) {
                attribute = attribute == null ? found.get() : attribute;
                owners.put(type.getKey(), type.getValue());
            }
        }
        return attribute == null ? Optional.empty() : Optional.of(new AttributeRef(attribute, owners));
    }

    private static Optional<Resolved> name(String name, Cursor cursor) {
        ProgramIndex index = cursor.index;
        Optional<ProgramIndex.Declared> declared = index.lookup(name, cursor.scope);
        if (declared.isPresent()) {
            return Optional.of(new DeclaredRef(declared.get()));
        }
        Optional<ProgramIndex.AgentDef> agent = index.agent(name);
        if (agent.isPresent()) {
            return Optional.of(new AgentRef(agent.get()));
        }
        Optional<Vocabulary.FixedMember> event = fixed(Vocabulary.SYSTEM_EVENTS, name);
        if (event.isPresent()) {
            return Optional.of(new SystemEventRef(event.get()));
        }
        Optional<ProgramIndex.Block> block = index.block(name);
        if (block.isPresent()) {
            return Optional.of(new BlockRef(block.get()));
        }
        return Optional.ofNullable(index.types().get(name)).map(TypeRef::new);
    }

    private static Optional<Vocabulary.FixedMember> fixed(java.util.List<Vocabulary.FixedMember> members, String name) {
        return members.stream().filter(member -> member.name().equals(name)).findFirst();
    }
}
