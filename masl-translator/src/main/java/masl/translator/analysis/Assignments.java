package masl.translator.analysis;

import java.util.Optional;
import masl.grammar.MASLParser;
import masl.grammar.MASLParser.ExpressionContext;
import org.antlr.v4.runtime.Token;

/**
 * Types assignments ({@code =}, {@code op=}), increments and decrements (MASL §3, §7): what is assigned
 * to must be a variable, an attribute, a field or an array element, and not {@code final}; label
 * assignments (§10) store the result of an invocation.
 */
final class Assignments {

    private final ExpressionTyper typer;
    private final NameResolver names;
    private final LabelForms labels;
    private final MemberTyper members;
    private final Bindings bindings;
    private final Errors errors;

    Assignments(ExpressionTyper typer, NameResolver names, LabelForms labels, MemberTyper members, Bindings bindings,
            Errors errors) {
        this.typer = typer;
        this.names = names;
        this.labels = labels;
        this.members = members;
        this.bindings = bindings;
        this.errors = errors;
    }

    static void checkNotFinal(Variable variable, Token name, Errors errors) {
        if (variable.isFinal()) {
            errors.at(name, "cannot assign a value to final variable " + name.getText());
        }
    }

    MaslType assign(MASLParser.AssignExprContext assignment) {
        String operator = assignment.op.getText();
        Optional<MaslType> labelTarget = labels.assignmentTarget(assignment.target);
        if (labelTarget.isPresent()) {
            if (!operator.equals("=")) {
                errors.at(assignment.op, "a label assignment is written l.x = .m(…), not with " + operator);
            }
            if (!LabelForms.isInvocation(assignment.value)) {
                errors.at(assignment.value, "a label assignment stores the result of a primitive invocation, "
                        + "such as .m(…) or a.m(…)");
            }
            typer.checkAssignable(labelTarget.get(), assignment.value);
            return MaslType.VOID;
        }
        MaslType target = assignable(assignment.target);
        if (operator.equals("=")) {
            typer.checkAssignable(target, assignment.value);
        } else {
            MaslType value = typer.type(assignment.value);
            if (!OperatorTyper.compound(operator, target, value)) {
                errors.at(assignment.op, "bad operand types for " + operator + ": " + target.describe() + " and "
                        + value.describe());
            }
        }
        return target;
    }

    MaslType incrementOrDecrement(Token operator, ExpressionContext operand) {
        MaslType type = assignable(operand);
        if (!TypeRules.isOpen(type) && !TypeRules.isNumeric(type)) {
            errors.at(operator, "bad operand type " + type.describe() + " for " + operator.getText());
        }
        return type;
    }

    /** The type of what is assigned to; reports what cannot be assigned. */
    private MaslType assignable(ExpressionContext target) {
        MaslType type;
        if (target instanceof MASLParser.PrimaryExprContext primary
                && primary.primary() instanceof MASLParser.NameExprContext nameExpr) {
            type = assignableName(nameExpr.identifier().getStart(), target);
        } else if (target instanceof MASLParser.PrimaryExprContext primary
                && primary.primary() instanceof MASLParser.SelfAttributeContext attribute) {
            type = members.attribute(null, attribute.identifier().getStart(), true, target);
        } else if (target instanceof MASLParser.FieldAccessContext access) {
            Receiver owner = names.receiver(access.expression());
            Token name = access.identifier().getStart();
            if (owner instanceof Receiver.OfType ofType) {
                type = names.staticMember(ofType.type(), name, true, access);
            } else if (owner instanceof Receiver.Value value) {
                type = names.instanceMember(value.type(), name, true, access);
            } else {
                type = names.member(owner, name, access);
            }
        } else if (target instanceof MASLParser.ArrayAccessContext) {
            type = typer.type(target);
        } else {
            typer.type(target);
            errors.at(target, "cannot assign a value to " + target.getText());
            type = MaslType.ERROR;
        }
        return bindings.type(target, type);
    }

    private MaslType assignableName(Token name, ExpressionContext target) {
        Receiver receiver = names.named(name, target);
        if (receiver instanceof Receiver.Value value) {
            Symbol symbol = bindings.symbolOf(target).orElse(null);
            if (symbol instanceof Variable variable) {
                checkNotFinal(variable, name, errors);
            } else if (symbol instanceof AgentDecl) {
                errors.at(name, "cannot assign a value to agent " + name.getText());
            }
            return value.type();
        }
        return names.valueOf(receiver, target);
    }
}
