package masl.lsp;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import masl.runtime.descriptor.AgentType;
import org.antlr.v4.runtime.Token;
import org.eclipse.lsp4j.Location;
import org.eclipse.lsp4j.Position;
import org.eclipse.lsp4j.Range;

/**
 * Go to definition: a block name to its {@code entry}, an entry member to its block, a variable, event,
 * label or agent to its declaration, an agent type to its {@code import}, an import (its path or its name) to
 * the descriptor's {@code <Agent>} line, a primitive or attribute to its element in the descriptor that
 * declares it.
 */
final class Definitions {

    private Definitions() {
    }

    static List<Location> at(Cursor cursor) {
        Optional<Resolved> resolved = Resolved.at(cursor);
        if (resolved.isEmpty()) {
            return List.of();
        }
        TextDocument document = cursor.document;
        Resolved target = resolved.get();
        if (target instanceof Resolved.BlockRef block) {
            return List.of(in(document, block.block().nameToken));
        }
        if (target instanceof Resolved.EntryMemberRef member && member.block() != null) {
            return List.of(in(document, member.block().nameToken));
        }
        if (target instanceof Resolved.DeclaredRef declared) {
            return List.of(in(document, declared.declared().token()));
        }
        if (target instanceof Resolved.AgentRef agent) {
            return List.of(in(document, agent.agent().token()));
        }
        if (target instanceof Resolved.TypeRef type) {
            Token at = type.type().nameToken() != null ? type.type().nameToken() : type.type().path().getStart();
            return List.of(in(document, at));
        }
        if (target instanceof Resolved.DescriptorRef type) {
            int line = type.type().descriptor() == null ? 1 : type.type().descriptor().line();
            return cursor.index.descriptorSource(type.type())
                    .flatMap(source -> DescriptorFiles.location(source, line, 0)).stream().toList();
        }
        if (target instanceof Resolved.PrimitiveRef primitive) {
            Set<Location> found = new LinkedHashSet<>();
            for (AgentType owner : primitive.owners().values()) {
                AgentType declaring = AgentMemberDocs.declaringType(owner, primitive.primitive());
                DescriptorFiles.location(declaring.source(), primitive.primitive().line(), primitive.primitive().column())
                        .ifPresent(found::add);
            }
            return new ArrayList<>(found);
        }
        if (target instanceof Resolved.AttributeRef attribute) {
            Set<Location> found = new LinkedHashSet<>();
            for (AgentType owner : attribute.owners().values()) {
                AgentType declaring = AgentMemberDocs.declaringType(owner, attribute.attribute());
                DescriptorFiles.location(declaring.source(), attribute.attribute().line(), attribute.attribute().column())
                        .ifPresent(found::add);
            }
            return new ArrayList<>(found);
        }
        return List.of();
    }

    /** A token of the program as a location. */
    static Location in(TextDocument document, Token token) {
        return new Location(document.uri(), range(document, token));
    }

    static Range range(TextDocument document, Token token) {
        Position start = document.positionOf(token.getLine(), token.getCharPositionInLine());
        int length = token.getText().codePointCount(0, token.getText().length());
        return new Range(start, document.positionOf(token.getLine(), token.getCharPositionInLine() + length));
    }
}
