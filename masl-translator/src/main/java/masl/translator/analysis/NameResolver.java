package masl.translator.analysis;

import java.util.HashSet;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import masl.grammar.MASLParser;
import masl.grammar.MASLParser.ExpressionContext;
import masl.translator.diagnostics.Suggestions;
import org.antlr.v4.runtime.ParserRuleContext;
import org.antlr.v4.runtime.Token;

/**
 * Resolves names in expressions (MASL §3: from the innermost block outwards): variables, agents, labels
 * and events in the current {@link Scope}, then entry names, then type names. Resolves what stands before
 * a {@code .} into a {@link Receiver} and types member reads. An unknown name is reported at its first use.
 */
final class NameResolver {

    private final ExpressionTyper typer;
    private final Bindings bindings;
    private final Errors errors;
    private final TypeNames typeNames;
    private final EntryNames entryNames;
    private final MemberTyper members;
    private final Set<String> unresolvedNames = new HashSet<>();
    private Scope scope;

    NameResolver(ExpressionTyper typer, Bindings bindings, Errors errors, TypeNames typeNames, EntryNames entryNames,
            MemberTyper members) {
        this.typer = typer;
        this.bindings = bindings;
        this.errors = errors;
        this.typeNames = typeNames;
        this.entryNames = entryNames;
        this.members = members;
    }

    void useScope(Scope current) {
        scope = current;
    }

    Optional<Symbol> resolve(String name) {
        return scope.resolve(name);
    }

    /** Whether {@code name} names an event in scope; reports when it does not. */
    Optional<EventDecl> event(MASLParser.IdentifierContext name) {
        Optional<Symbol> symbol = scope.resolve(name.getText());
        if (symbol.isEmpty()) {
            if (unresolvedNames.add(name.getText())) {
                errors.at(name, "cannot find event " + name.getText() + Suggestions.hint(name.getText(), eventNames()));
            }
            return Optional.empty();
        }
        if (!(symbol.get() instanceof EventDecl event)) {
            errors.at(name, name.getText() + " is not an event");
            return Optional.empty();
        }
        bindings.bind(name, event);
        return Optional.of(event);
    }

    /** The label a bare name denotes, bound to it; empty when the expression is not a label's name. */
    Optional<Label> labelNamed(ExpressionContext expression) {
        if (expression instanceof MASLParser.PrimaryExprContext primary
                && primary.primary() instanceof MASLParser.NameExprContext name
                && scope.resolve(name.getText()).orElse(null) instanceof Label label) {
            bindings.bind(expression, label);
            return Optional.of(label);
        }
        return Optional.empty();
    }

    /** Reports an expression where a label should be; an undeclared name is reported as such, once. */
    void notALabel(ExpressionContext expression, String message) {
        if (expression instanceof MASLParser.PrimaryExprContext primary
                && primary.primary() instanceof MASLParser.NameExprContext name
                && scope.resolve(name.getText()).isEmpty()) {
            reportUnresolved(name.getStart());
        } else {
            errors.at(expression, message);
        }
    }

    /** Resolves what stands before a {@code .}: a value, a label, an entry, a type or a package name. */
    Receiver receiver(ExpressionContext expression) {
        if (expression instanceof MASLParser.PrimaryExprContext primary
                && primary.primary() instanceof MASLParser.NameExprContext nameExpr) {
            return named(nameExpr.identifier().getStart(), expression);
        }
        if (expression instanceof MASLParser.FieldAccessContext access) {
            Receiver owner = receiver(access.expression());
            Token name = access.identifier().getStart();
            if (owner instanceof Receiver.PackagePrefix prefix) {
                String qualified = prefix.prefix() + "." + name.getText();
                Optional<MaslType> type = typeNames.resolve(qualified);
                if (type.isPresent()) {
                    bindings.bind(access, new TypeRef(type.get()));
                    return new Receiver.OfType(type.get());
                }
                return new Receiver.PackagePrefix(qualified, prefix.first());
            }
            return new Receiver.Value(bindings.type(access, member(owner, name, access)));
        }
        return new Receiver.Value(typer.type(expression));
    }

    Receiver named(Token name, ExpressionContext expression) {
        Optional<Symbol> symbol = scope.resolve(name.getText());
        if (symbol.isPresent()) {
            bindings.bind(expression, symbol.get());
            if (symbol.get() instanceof Label label) {
                return new Receiver.OfLabel(label);
            }
            if (symbol.get() instanceof Variable variable) {
                return new Receiver.Value(bindings.type(expression, variable.type()));
            }
            if (symbol.get() instanceof AgentDecl agent) {
                return new Receiver.Value(bindings.type(expression, new MaslType.AgentRef(agent.declaredType())));
            }
            errors.at(name, name.getText() + " is an event, not a value");
            return new Receiver.Value(MaslType.ERROR);
        }
        Optional<EntryRef> entry = entryNames.receiver(name);
        if (entry.isPresent()) {
            bindings.bind(expression, entry.get());
            return new Receiver.OfEntry(entry.get());
        }
        Optional<MaslType> type = typeNames.resolve(name.getText());
        if (type.isPresent()) {
            bindings.bind(expression, new TypeRef(type.get()));
            return new Receiver.OfType(type.get());
        }
        return new Receiver.PackagePrefix(name.getText(), name);
    }

    /** A member read without parentheses: {@code a.x}, {@code e.count}, {@code s.length}, {@code X.class}. */
    MaslType member(Receiver owner, Token name, ParserRuleContext access) {
        if (owner instanceof Receiver.OfEntry ofEntry) {
            return members.entryMember(ofEntry.entry(), name, null, access);
        }
        if (owner instanceof Receiver.OfLabel ofLabel) {
            errors.at(name, "label " + ofLabel.label().name() + " has no member " + name.getText()
                    + "; a label is used as l.x = .m(…), l.a.m(…), l.isFinished(), l.getRemainingInvocations() or l.free()");
            return MaslType.ERROR;
        }
        if (owner instanceof Receiver.OfType ofType) {
            return staticMember(ofType.type(), name, false, access);
        }
        if (owner instanceof Receiver.PackagePrefix prefix) {
            reportUnresolved(prefix.first());
            return MaslType.ERROR;
        }
        return instanceMember(((Receiver.Value) owner).type(), name, false, access);
    }

    MaslType staticMember(MaslType type, Token name, boolean isWrite, ParserRuleContext access) {
        if (name.getText().equals("class") && !isWrite) {
            bindings.bind(access, new Member(Member.Kind.JAVA_FIELD, "class", List.of(), null));
            return new MaslType.JavaClass(Class.class);
        }
        if (type instanceof MaslType.AgentRef agentType) {
            return members.staticAttribute(agentType.type(), name, isWrite, access);
        }
        if (type instanceof MaslType.JavaClass javaClass) {
            return members.javaField(javaClass.type(), true, name, isWrite, access);
        }
        errors.at(name, type.describe() + " has no member " + name.getText());
        return MaslType.ERROR;
    }

    MaslType instanceMember(MaslType type, Token name, boolean isWrite, ParserRuleContext access) {
        if (TypeRules.isError(type)) {
            return MaslType.ERROR;
        }
        if (type instanceof MaslType.AgentRef agent) {
            return members.attribute(agent.type(), name, isWrite, access);
        }
        if (MaslType.OBJECT.equals(type)) {
            return members.dynamic(name, access);
        }
        if (type instanceof MaslType.ArrayOf && name.getText().equals("length")) {
            if (isWrite) {
                errors.at(name, "cannot assign a value to the length of an array");
            }
            bindings.bind(access, new Member(Member.Kind.JAVA_FIELD, "length", List.of(), null));
            return MaslType.INT;
        }
        if (type instanceof MaslType.JavaClass javaClass) {
            return members.javaField(javaClass.type(), false, name, isWrite, access);
        }
        if (!(access instanceof MASLParser.FieldAccessContext field
                && errors.missingSemicolonBefore(field.DOT().getSymbol(), field.expression()))) {
            errors.at(name, type.describe() + " has no member " + name.getText());
        }
        return MaslType.ERROR;
    }

    MaslType valueOf(Receiver receiver, ExpressionContext expression) {
        if (receiver instanceof Receiver.Value value) {
            return value.type();
        }
        if (receiver instanceof Receiver.OfLabel ofLabel) {
            String label = ofLabel.label().name();
            errors.at(expression, "label " + label + " is not a value; use " + label + ".isFinished() or isFinished("
                    + label + ")");
        } else if (receiver instanceof Receiver.OfEntry ofEntry) {
            errors.at(expression, "entry " + ofEntry.entry().name() + " is not a value; use its members, such as "
                    + ofEntry.entry().name() + ".count");
        } else if (receiver instanceof Receiver.OfType ofType) {
            errors.at(expression, "type " + ofType.type().describe() + " is not a value");
        } else {
            reportUnresolved(((Receiver.PackagePrefix) receiver).first());
        }
        return MaslType.ERROR;
    }

    /** An unknown name is one mistake however often it is used: reported at its first use only (events included). */
    void reportUnresolved(Token name) {
        if (unresolvedNames.add(name.getText())) {
            Set<String> known = new LinkedHashSet<>(scope.visibleNames());
            known.addAll(entryNames.names());
            known.addAll(typeNames.agentTypeNames());
            errors.at(name, "cannot find symbol " + name.getText() + Suggestions.hint(name.getText(), known));
        }
    }

    /** The events in scope, for hints. */
    private Set<String> eventNames() {
        Set<String> events = new LinkedHashSet<>();
        for (String visible : scope.visibleNames()) {
            if (scope.resolve(visible).orElse(null) instanceof EventDecl) {
                events.add(visible);
            }
        }
        return events;
    }
}
