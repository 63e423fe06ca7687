package masl.lsp;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import masl.grammar.MASLLexer;
import masl.runtime.descriptor.AgentType;
import masl.runtime.descriptor.Attribute;
import masl.runtime.descriptor.Primitive;
import org.eclipse.lsp4j.CompletionItem;
import org.eclipse.lsp4j.CompletionItemKind;
import org.eclipse.lsp4j.CompletionItemLabelDetails;
import org.eclipse.lsp4j.InsertTextFormat;
import org.eclipse.lsp4j.MarkupContent;
import org.eclipse.lsp4j.MarkupKind;

/**
 * What may be written at the cursor: after a {@code .} the members of what stands before it (an agent's
 * primitives and attributes with their signatures, an entry's or a label's members); inside
 * {@code break(}/{@code reelect(} the blocks around the cursor; inside {@code emit(}, {@code react(}, … the
 * events in scope; elsewhere the variables, events and labels in scope, the agents, entry and type names,
 * and the keywords. The editor filters them by the word typed so far.
 */
final class Completions {

    private final Cursor cursor;
    private final boolean snippets;
    private final List<CompletionItem> items = new ArrayList<>();
    private final Set<String> offered = new LinkedHashSet<>();

    private Completions(Cursor cursor, boolean snippets) {
        this.cursor = cursor;
        this.snippets = snippets;
    }

    /** @param snippets whether the client accepts snippets ({@code log($1)} leaves the cursor between the parentheses) */
    static List<CompletionItem> at(Cursor cursor, boolean snippets) {
        Completions completions = new Completions(cursor, snippets);
        if (!cursor.inCommentOrString()) {
            completions.collect();
        }
        return completions.items;
    }

    private void collect() {
        int previous = cursor.lastBefore(wordStart());
        int type = cursor.typeAt(previous);
        int beforeThat = cursor.typeAt(previous - 1);
        if (type == MASLLexer.DOT) {
            members(Receiver.before(cursor.tokens, previous, cursor.index, cursor.scope));
        } else if (type == MASLLexer.LPAREN && (beforeThat == MASLLexer.BREAK || beforeThat == MASLLexer.REELECT)) {
            enclosingBlocks();
        } else if (type == MASLLexer.LPAREN && isEventStatement(beforeThat) || type == MASLLexer.EMIT) {
            events();
            if (beforeThat == MASLLexer.REACT) {
                add("default", CompletionItemKind.Keyword, "react(default)", "reacts to any event without a reaction of its own");
            }
        } else if (type == MASLLexer.LPAREN && (beforeThat == MASLLexer.NEWAGENT || beforeThat == MASLLexer.LIMITED)) {
            typeNames();
        } else if (cursor.scope == null) {
            typeNames();
            Vocabulary.HEADER_KEYWORDS.forEach(this::keyword);
        } else {
            namesInScope();
            Vocabulary.KEYWORDS.forEach(this::keyword);
        }
    }

    /** The code point index where the word being typed starts (the cursor, when none is). */
    private int wordStart() {
        String text = cursor.document.text();
        int offset = cursor.document.offsetOfCodePoint(cursor.point);
        int start = offset;
        while (start > 0 && Character.isJavaIdentifierPart(text.charAt(start - 1))) {
            start--;
        }
        return cursor.point - (offset - start);
    }

    private static boolean isEventStatement(int type) {
        return type == MASLLexer.EMIT || type == MASLLexer.EMITWITHMESSAGE || type == MASLLexer.GETMESSAGEFROMEVENT
                || type == MASLLexer.REACT;
    }

    private void members(Receiver receiver) {
        if (receiver instanceof Receiver.Entry entry) {
            // Members of a block not declared with Entry are an error (MASL §6.7): not offered.
            if (cursor.index.hasEntryMembers(entry.name())) {
                Vocabulary.ENTRY_MEMBERS.forEach(member -> fixed(member, CompletionItemKind.Property));
            }
            return;
        }
        if (receiver instanceof Receiver.Label) {
            Vocabulary.LABEL_MEMBERS.forEach(member -> fixed(member, CompletionItemKind.Method));
            add("this", CompletionItemKind.Keyword, "the current agent", "l.this.m(…) launches m on the current agent");
            cursor.index.agents().forEach(agent ->
                    add(agent.name(), CompletionItemKind.Variable, "agent " + agent.typeName(), null));
        }
        agentMembers(Receiver.agentTypes(receiver, cursor.index));
    }

    /** Primitives then attributes; a member several types have is offered once, with the types named. */
    private void agentMembers(Map<String, AgentType> types) {
        Map<String, Map<String, AgentType>> primitiveOwners = new LinkedHashMap<>();
        Map<String, Primitive> primitives = new LinkedHashMap<>();
        Map<String, Map<String, AgentType>> attributeOwners = new LinkedHashMap<>();
        Map<String, Attribute> attributes = new LinkedHashMap<>();
        types.forEach((typeName, type) -> {
            for (Primitive primitive : type.primitives()) {
                String key = AgentMemberDocs.signature(primitive);
                primitives.putIfAbsent(key, primitive);
                primitiveOwners.computeIfAbsent(key, k -> new LinkedHashMap<>()).put(typeName, type);
            }
            for (Attribute attribute : type.attributes()) {
                String key = AgentMemberDocs.signature(attribute);
                attributes.putIfAbsent(key, attribute);
                attributeOwners.computeIfAbsent(key, k -> new LinkedHashMap<>()).put(typeName, type);
            }
        });
        primitives.forEach((signature, primitive) -> {
            Map<String, AgentType> owners = primitiveOwners.get(signature);
            CompletionItem item = item(primitive.name(), CompletionItemKind.Method, signature,
                    AgentMemberDocs.describe(primitive, owners));
            item.setLabelDetails(labelDetails(signature.substring(signature.indexOf('(')), owners));
            callSnippet(item, primitive.name(), !primitive.parameters().isEmpty());
        });
        attributes.forEach((signature, attribute) -> {
            Map<String, AgentType> owners = attributeOwners.get(signature);
            CompletionItem item = item(attribute.name(), CompletionItemKind.Field, signature,
                    AgentMemberDocs.describe(attribute, owners));
            item.setLabelDetails(labelDetails(null, owners));
        });
    }

    private static CompletionItemLabelDetails labelDetails(String parameters, Map<String, AgentType> owners) {
        CompletionItemLabelDetails details = new CompletionItemLabelDetails();
        details.setDetail(parameters);
        details.setDescription(String.join(", ", owners.keySet()));
        return details;
    }

    private void enclosingBlocks() {
        for (ProgramIndex.Block block = cursor.scope; block != null; block = block.parent) {
            add(block.name, CompletionItemKind.Module, Hovers.blockHeadline(block), "test: " + block.test);
        }
        if (cursor.scope != null && !cursor.index.root().name.equals(ProgramIndex.MAIN)) {
            add(ProgramIndex.MAIN, CompletionItemKind.Module, "the top-level block", "break(main) ends the agent's mission");
        }
    }

    private void events() {
        for (ProgramIndex.Block block = cursor.scope; block != null; block = block.parent) {
            block.declarations.stream().filter(declared -> declared.kind() == ProgramIndex.Kind.EVENT)
                    .forEach(event -> add(event.name(), CompletionItemKind.Event,
                            event.description() + " " + event.name(), null));
        }
        Vocabulary.SYSTEM_EVENTS.forEach(event -> add(event.name(), CompletionItemKind.Event, event.signature(),
                event.description()));
    }

    private void typeNames() {
        cursor.index.types().values().forEach(type -> add(type.name(), CompletionItemKind.Class,
                "agent type" + (type.file() == null ? "" : " from " + type.file()),
                type.descriptor() == null ? null : type.descriptor().fullClassName()));
    }

    private void namesInScope() {
        for (ProgramIndex.Block block = cursor.scope; block != null; block = block.parent) {
            for (ProgramIndex.Declared declared : block.declarations) {
                CompletionItemKind kind = switch (declared.kind()) {
                    case VARIABLE -> CompletionItemKind.Variable;
                    case EVENT -> CompletionItemKind.Event;
                    case LABEL -> CompletionItemKind.Reference;
                };
                add(declared.name(), kind, declared.description() + " " + declared.name(),
                        "declared in block " + block.name);
            }
        }
        cursor.index.agents().forEach(agent -> add(agent.name(), CompletionItemKind.Variable,
                "agent " + agent.typeName(), null));
        if (cursor.index.root() != null) {
            add(ProgramIndex.MAIN, CompletionItemKind.Module, "the top-level block", "entry members: main.count, …");
        }
        cursor.index.entryDecls().keySet().forEach(name -> cursor.index.block(name).ifPresent(block ->
                add(name, CompletionItemKind.Module, Hovers.blockHeadline(block), "test: " + block.test)));
        Vocabulary.SYSTEM_EVENTS.forEach(event -> add(event.name(), CompletionItemKind.Event, event.signature(),
                event.description()));
        typeNames();
    }

    private void fixed(Vocabulary.FixedMember member, CompletionItemKind kind) {
        CompletionItem item = item(member.name(), kind, member.signature(), member.description());
        if (member.isCall()) {
            callSnippet(item, member.name(), member.name().equals("release"));
        }
    }

    private void keyword(String word) {
        add(word, CompletionItemKind.Keyword, "keyword", null);
    }

    private void add(String label, CompletionItemKind kind, String detail, String documentation) {
        if (!label.isEmpty()) {
            item(label, kind, detail, documentation);
        }
    }

    /** A new item; it is offered unless an item with that label and detail already is. */
    private CompletionItem item(String label, CompletionItemKind kind, String detail, String documentation) {
        CompletionItem item = new CompletionItem(label);
        item.setKind(kind);
        item.setDetail(detail);
        if (documentation != null) {
            item.setDocumentation(new MarkupContent(MarkupKind.MARKDOWN, documentation));
        }
        item.setSortText(String.format("%04d", items.size()));
        if (offered.add(label + "\u0000" + detail)) {
            items.add(item);
        }
        return item;
    }

    private void callSnippet(CompletionItem item, String name, boolean hasParameters) {
        if (snippets) {
            item.setInsertText(name + (hasParameters ? "($1)" : "()") + "$0");
            item.setInsertTextFormat(InsertTextFormat.Snippet);
        } else {
            item.setInsertText(name);
        }
    }
}
