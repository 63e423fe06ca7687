package masl.lsp;

import java.util.ArrayList;
import java.util.List;
import masl.grammar.MASLParser;
import org.antlr.v4.runtime.ParserRuleContext;
import org.antlr.v4.runtime.Token;
import org.eclipse.lsp4j.DocumentSymbol;
import org.eclipse.lsp4j.Range;
import org.eclipse.lsp4j.SymbolKind;

/**
 * The outline of a program: its agent types and agents, then the tree of its blocks, each with its
 * declarations and its reactions, as the editor's document symbols.
 */
final class Outline {

    private final ProgramIndex index;
    private final TextDocument document;

    private Outline(ProgramIndex index, TextDocument document) {
        this.index = index;
        this.document = document;
    }

    static List<DocumentSymbol> of(ProgramIndex index, TextDocument document) {
        return new Outline(index, document).symbols();
    }

    private List<DocumentSymbol> symbols() {
        List<DocumentSymbol> symbols = new ArrayList<>();
        for (ProgramIndex.TypeDef type : index.types().values()) {
            ParserRuleContext header = (ParserRuleContext) type.path().getParent();
            Token name = type.nameToken() != null ? type.nameToken() : type.path().getStart();
            symbols.add(symbol(type.name(), type.file(), SymbolKind.Class, header, name));
        }
        for (MASLParser.HeaderContext header : index.tree().header()) {
            if (header.agentsDecl() != null && header.agentsDecl().identifierList() != null) {
                for (MASLParser.IdentifierContext agent : header.agentsDecl().identifierList().identifier()) {
                    symbols.add(symbol(agent.getText(), "agent " + header.agentsDecl().typeName.getText(),
                            SymbolKind.Object, header, agent.getStart()));
                }
            }
        }
        if (index.root() != null) {
            symbols.add(block(index.root()));
        }
        return symbols;
    }

    private DocumentSymbol block(ProgramIndex.Block block) {
        DocumentSymbol symbol = symbol(block.name, block.mode + " (" + block.test + ")", SymbolKind.Module, block.tree,
                block.nameToken);
        List<DocumentSymbol> children = new ArrayList<>();
        for (ProgramIndex.Declared declared : block.declarations) {
            SymbolKind kind = switch (declared.kind()) {
                case VARIABLE -> SymbolKind.Variable;
                case EVENT -> SymbolKind.Event;
                case LABEL -> SymbolKind.Field;
            };
            children.add(symbol(declared.name(), declared.description(), kind, null, declared.token()));
        }
        for (MASLParser.BlockItemContext item : block.tree.blockItem()) {
            MASLParser.ReactionContext reaction = item.reaction();
            if (reaction != null) {
                String event = reaction.event != null ? reaction.event.getText() : "default";
                children.add(symbol("react(" + event + ")", null, SymbolKind.Function, reaction, reaction.getStart()));
            }
        }
        block.children.forEach(child -> children.add(block(child)));
        children.sort((a, b) -> compare(a.getRange(), b.getRange()));
        symbol.setChildren(children);
        return symbol;
    }

    /** A symbol spanning {@code extent} (its name alone when null), selected at {@code name}. */
    private DocumentSymbol symbol(String label, String detail, SymbolKind kind, ParserRuleContext extent, Token name) {
        Range selection = Definitions.range(document, name);
        Range range = selection;
        if (extent != null && extent.getStop() != null && extent.getStop().getType() != Token.EOF
                && extent.getStop().getStopIndex() >= extent.getStart().getStartIndex()) {
            Token stop = extent.getStop();
            range = new Range(Definitions.range(document, extent.getStart()).getStart(),
                    Definitions.range(document, stop).getEnd());
        } else if (extent != null) {
            // A block whose closing brace is still to be typed runs to the end of the document.
            range = new Range(Definitions.range(document, extent.getStart()).getStart(),
                    document.position(document.text().length()));
        }
        DocumentSymbol symbol = new DocumentSymbol(label.isEmpty() ? "(unnamed)" : label, kind, range, selection, detail);
        symbol.setChildren(List.of());
        return symbol;
    }

    private static int compare(Range a, Range b) {
        int byLine = Integer.compare(a.getStart().getLine(), b.getStart().getLine());
        return byLine != 0 ? byLine : Integer.compare(a.getStart().getCharacter(), b.getStart().getCharacter());
    }
}
