package masl.translator.analysis;

import java.util.Optional;
import masl.grammar.MASLParser;
import masl.grammar.MASLParser.ExpressionContext;
import org.antlr.v4.runtime.Token;

/**
 * Recognises the label forms of MASL §10 in expressions: launches {@code l.a.m(…)} and {@code l.this.m(…)}
 * and the targets of label assignments {@code l.x = …}, {@code l.a.x = …} and {@code l.this.x = …}.
 * ({@code l.m(…)}, {@code l.isFinished()} and {@code l.free()} are calls on a label receiver, see
 * {@link Receiver.OfLabel}.)
 */
final class LabelForms {

    /**
     * The agent a label form addresses: an agent's declared type, the current agent ({@link #SELF}), or
     * one already reported as wrong ({@link #UNKNOWN}).
     */
    record Addressee(ImportedType type, boolean isKnown) {
        static final Addressee SELF = new Addressee(null, true);
        static final Addressee UNKNOWN = new Addressee(null, false);
    }

    private final NameResolver names;
    private final MemberTyper members;
    private final Bindings bindings;
    private final Errors errors;

    LabelForms(NameResolver names, MemberTyper members, Bindings bindings, Errors errors) {
        this.names = names;
        this.members = members;
        this.bindings = bindings;
        this.errors = errors;
    }

    /** Whom {@code receiver} addresses when it is {@code l.this} or {@code l.a}; empty when it is neither. */
    Optional<Addressee> addressee(ExpressionContext receiver) {
        if (receiver instanceof MASLParser.LabelSelfContext labelSelf) {
            if (names.labelNamed(labelSelf.expression()).isEmpty()) {
                names.notALabel(labelSelf.expression(), labelSelf.expression().getText() + " is not a label");
            }
            return Optional.of(Addressee.SELF);
        }
        if (receiver instanceof MASLParser.FieldAccessContext access
                && names.labelNamed(access.expression()).isPresent()) {
            Symbol target = names.resolve(access.identifier().getText()).orElse(null);
            if (target instanceof AgentDecl agent) {
                bindings.bind(access, agent);
                bindings.type(access, new MaslType.AgentRef(agent.declaredType()));
                return Optional.of(new Addressee(agent.declaredType(), true));
            }
            // A variable holding an agent (an element of an entry list, say) addresses that agent.
            if (target instanceof Variable variable && variable.type() instanceof MaslType.AgentRef agentType) {
                bindings.bind(access, variable);
                bindings.type(access, agentType);
                return Optional.of(new Addressee(agentType.type(), true));
            }
            errors.at(access.identifier(), "in " + access.getText() + ".…, " + access.identifier().getText()
                    + " must be an agent or this");
            return Optional.of(Addressee.UNKNOWN);
        }
        return Optional.empty();
    }

    /**
     * The type of what a label assignment stores into ({@link MaslType#ERROR} after reporting a wrong
     * target); empty when {@code target} is not of a label form.
     */
    Optional<MaslType> assignmentTarget(ExpressionContext target) {
        if (!(target instanceof MASLParser.FieldAccessContext access)) {
            return Optional.empty();
        }
        Token name = access.identifier().getStart();
        if (names.labelNamed(access.expression()).isPresent()) {
            Optional<Symbol> symbol = names.resolve(name.getText());
            if (symbol.isPresent() && symbol.get() instanceof Variable variable) {
                bindings.bind(access, variable);
                Assignments.checkNotFinal(variable, name, errors);
                return Optional.of(bindings.type(access, variable.type()));
            }
            errors.at(name, "in " + access.getText() + " = …, " + name.getText() + " must be a variable in scope");
            return Optional.of(MaslType.ERROR);
        }
        return addressee(access.expression()).map(addressee -> addressee.isKnown()
                ? bindings.type(access, members.attribute(addressee.type(), name, true, access))
                : MaslType.ERROR);
    }

    /** §10: a label assignment stores the result of an invocation, {@code .m(…)} or {@code a.m(…)}. */
    static boolean isInvocation(ExpressionContext value) {
        return value instanceof MASLParser.MethodCallContext
                || value instanceof MASLParser.PrimaryExprContext primary
                        && primary.primary() instanceof MASLParser.SelfInvocationContext;
    }
}
