package masl.translator.analysis;

import java.lang.reflect.Modifier;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import masl.grammar.MASLBaseVisitor;
import masl.grammar.MASLParser;
import masl.grammar.MASLParser.ExpressionContext;
import masl.translator.diagnostics.Suggestions;
import org.antlr.v4.runtime.ParserRuleContext;
import org.antlr.v4.runtime.Token;

/**
 * Resolves the names of expressions and computes their static types (MASL §3), reporting what does not
 * resolve or fit. Each expression node gets its type in {@link Bindings}; an expression already found
 * wrong has type {@link MaslType#ERROR}, which every rule accepts, so a mistake is reported once.
 * The block being checked sets the {@link Scope} names are resolved in.
 */
final class ExpressionTyper extends MASLBaseVisitor<MaslType> {

    private final Bindings bindings;
    private final Errors errors;
    /** The MASL words written like a call, for the hint when one is misspelt (MASL §2). */
    private static final List<String> CALL_KEYWORDS = List.of("emit", "emitWithMessage", "getMessageFromEvent",
            "clearEvents", "setAcceptState", "getAcceptState", "wait", "isFinished", "newAgent", "break", "reelect",
            "exit", "if", "while", "for");

    private final TypeNames typeNames;
    private final MemberTyper members;
    private final NameResolver names;
    private final LabelForms labels;
    private final Assignments assignments;

    ExpressionTyper(Bindings bindings, Errors errors, TypeNames typeNames, EntryNames entryNames, MemberTyper members) {
        this.bindings = bindings;
        this.errors = errors;
        this.typeNames = typeNames;
        this.members = members;
        this.names = new NameResolver(this, bindings, errors, typeNames, entryNames, members);
        this.labels = new LabelForms(names, members, bindings, errors);
        this.assignments = new Assignments(this, names, labels, members, bindings, errors);
    }

    void useScope(Scope current) {
        names.useScope(current);
    }

    /** Whether {@code name} names an event in scope; reports when it does not. */
    Optional<EventDecl> event(MASLParser.IdentifierContext name) {
        return names.event(name);
    }

    MaslType type(ExpressionContext expression) {
        MaslType type = expression.accept(this);
        return bindings.type(expression, type == null ? MaslType.ERROR : type);
    }

    /** An entry test or a condition (§3: boolean or numeric). */
    void checkCondition(ExpressionContext condition, String what) {
        MaslType type = type(condition);
        if (!TypeRules.isCondition(type)) {
            errors.at(condition, what + " must be boolean or numeric, found " + type.describe());
        }
    }

    /** A variable's initialiser, an array initialiser's elements included. */
    void checkInitializer(MaslType target, MASLParser.VariableInitializerContext initializer) {
        if (initializer.expression() != null) {
            checkAssignable(target, initializer.expression());
        } else {
            checkArrayInitializer(target, initializer.arrayInitializer());
        }
    }

    private void checkArrayInitializer(MaslType target, MASLParser.ArrayInitializerContext initializer) {
        if (!(target instanceof MaslType.ArrayOf array)) {
            if (!TypeRules.isError(target)) {
                errors.at(initializer, "an array initializer needs an array type, found " + target.describe());
            }
            return;
        }
        for (MASLParser.VariableInitializerContext element : initializer.variableInitializer()) {
            checkInitializer(array.element(), element);
        }
    }

    void checkAssignable(MaslType target, ExpressionContext value) {
        MaslType type = type(value);
        if (!TypeRules.isAssignable(target, type, true)) {
            errors.at(value, "incompatible types: " + type.describe() + " cannot be converted to " + target.describe());
        }
    }

    // ------------------------------------------------------------------ primaries

    @Override
    public MaslType visitPrimaryExpr(MASLParser.PrimaryExprContext expression) {
        if (expression.primary() instanceof MASLParser.NameExprContext) {
            return names.valueOf(names.receiver(expression), expression);
        }
        return expression.primary().accept(this);
    }

    @Override
    public MaslType visitParenExpr(MASLParser.ParenExprContext paren) {
        return type(paren.expression());
    }

    @Override
    public MaslType visitLiteralExpr(MASLParser.LiteralExprContext literalExpr) {
        MASLParser.LiteralContext literal = literalExpr.literal();
        String text = literal.getText();
        if (literal.IntegerLiteral() != null) {
            return text.endsWith("l") || text.endsWith("L") ? MaslType.LONG : MaslType.INT;
        }
        if (literal.FloatingPointLiteral() != null) {
            return text.endsWith("f") || text.endsWith("F") ? MaslType.FLOAT : MaslType.DOUBLE;
        }
        if (literal.CharacterLiteral() != null) {
            return MaslType.CHAR;
        }
        if (literal.StringLiteral() != null) {
            return MaslType.STRING;
        }
        return literal.NULL() != null ? MaslType.NULL : MaslType.BOOLEAN;
    }

    @Override
    public MaslType visitThisExpr(MASLParser.ThisExprContext self) {
        return MaslType.ANY_AGENT;
    }

    @Override
    public MaslType visitSelfInvocation(MASLParser.SelfInvocationContext call) {
        List<ExpressionContext> arguments = arguments(call.arguments());
        return members.primitive(null, call.identifier().getStart(), types(arguments), arguments, expressionOf(call));
    }

    @Override
    public MaslType visitSelfAttribute(MASLParser.SelfAttributeContext attribute) {
        return members.attribute(null, attribute.identifier().getStart(), false, expressionOf(attribute));
    }

    /** Only {@code isFinished(l)} is a call without a receiver (§10). */
    @Override
    public MaslType visitPlainCall(MASLParser.PlainCallContext call) {
        String name = call.identifier().getText();
        List<ExpressionContext> arguments = arguments(call.arguments());
        if (name.equals("isFinished") && arguments.size() == 1) {
            Optional<Label> label = names.labelNamed(arguments.get(0));
            if (label.isPresent()) {
                return members.labelMember(label.get(), call.identifier().getStart(), List.of(), expressionOf(call));
            }
            names.notALabel(arguments.get(0), "isFinished needs a label, found " + arguments.get(0).getText());
            return MaslType.BOOLEAN;
        }
        types(arguments);
        Optional<String> keyword = Suggestions.closest(name, CALL_KEYWORDS);
        errors.at(call.identifier(), "cannot find symbol " + name + keyword.map(k -> "; did you mean `" + k + "`?")
                .orElse(": a primitive is invoked as ." + name + "(…)"));
        return MaslType.ERROR;
    }

    @Override
    public MaslType visitGetAcceptStateExpr(MASLParser.GetAcceptStateExprContext call) {
        if (call.agent != null) {
            MaslType agent = type(call.agent);
            if (!TypeRules.isOpen(agent) && !(agent instanceof MaslType.AgentRef)) {
                errors.at(call.agent, "getAcceptState needs an agent, found " + agent.describe());
            }
        }
        return MaslType.STRING;
    }

    @Override
    public MaslType visitGetMessageExpr(MASLParser.GetMessageExprContext call) {
        names.event(call.event);
        return MaslType.STRING;
    }

    @Override
    public MaslType visitPrimitiveClassLiteral(MASLParser.PrimitiveClassLiteralContext literal) {
        if (!literal.identifier().getText().equals("class")) {
            errors.at(literal.identifier(), "a primitive type has no member " + literal.identifier().getText());
            return MaslType.ERROR;
        }
        return new MaslType.JavaClass(Class.class);
    }

    @Override
    public MaslType visitNewExpr(MASLParser.NewExprContext creation) {
        return creation.creator().accept(this);
    }

    @Override
    public MaslType visitObjectCreator(MASLParser.ObjectCreatorContext creator) {
        MaslType created = createdType(creator.createdName());
        List<ExpressionContext> arguments = arguments(creator.arguments());
        List<MaslType> argumentTypes = types(arguments);
        if (created instanceof MaslType.AgentRef) {
            errors.at(creator, "agents cannot be created with new: declare them with newAgent before the blocks");
            return MaslType.ERROR;
        }
        if (!(created instanceof MaslType.JavaClass javaClass)) {
            if (!TypeRules.isError(created)) {
                errors.at(creator, "cannot create an object of type " + created.describe() + " with new");
            }
            return MaslType.ERROR;
        }
        Class<?> type = javaClass.type();
        if (type.isInterface() || Modifier.isAbstract(type.getModifiers())) {
            errors.at(creator, created.describe() + " is abstract and cannot be instantiated");
            return created;
        }
        if (JavaMembers.constructor(type, argumentTypes) instanceof JavaMembers.Lookup.Found found) {
            bindings.bind(expressionOf(creator),
                    new Member(Member.Kind.JAVA_METHOD, "new", List.of(), found.member()));
        } else {
            errors.at(creator, "no constructor of " + created.describe() + " accepts "
                    + MemberTyper.describe(argumentTypes));
        }
        return created;
    }

    @Override
    public MaslType visitArrayCreator(MASLParser.ArrayCreatorContext creator) {
        MaslType element = createdType(creator.createdName());
        for (ExpressionContext size : creator.expression()) {
            checkIndex(size, "an array size");
        }
        int dimensions = creator.expression().size() + (creator.dims() == null ? 0 : creator.dims().LBRACK().size());
        return TypeRules.isError(element) ? element : TypeNames.arrayOf(element, dimensions);
    }

    @Override
    public MaslType visitArrayLiteralCreator(MASLParser.ArrayLiteralCreatorContext creator) {
        MaslType element = createdType(creator.createdName());
        MaslType array = TypeRules.isError(element) ? element
                : TypeNames.arrayOf(element, creator.dims().LBRACK().size());
        checkArrayInitializer(array, creator.arrayInitializer());
        return array;
    }

    private MaslType createdType(MASLParser.CreatedNameContext name) {
        if (name.primitiveType() != null) {
            return typeNames.resolve(name.primitiveType().getText()).orElseThrow();
        }
        Optional<MaslType> type = typeNames.resolve(name.qualifiedName().getText());
        if (type.isEmpty()) {
            errors.at(name, "cannot find type " + name.qualifiedName().getText() + typeNames.hint(name.qualifiedName().getText()));
            return MaslType.ERROR;
        }
        return type.get();
    }

    // ------------------------------------------------------------------ members, labels, entries

    @Override
    public MaslType visitFieldAccess(MASLParser.FieldAccessContext access) {
        return names.valueOf(names.receiver(access), access);
    }

    @Override
    public MaslType visitLabelSelf(MASLParser.LabelSelfContext labelSelf) {
        errors.at(labelSelf,
                labelSelf.getText() + " must be followed by a primitive invocation or an attribute assignment");
        return MaslType.ERROR;
    }

    @Override
    public MaslType visitMethodCall(MASLParser.MethodCallContext call) {
        Token name = call.identifier().getStart();
        List<ExpressionContext> arguments = arguments(call.arguments());
        Optional<LabelForms.Addressee> addressee = labels.addressee(call.expression());
        if (addressee.isPresent()) {
            List<MaslType> argumentTypes = types(arguments);
            return addressee.get().isKnown()
                    ? members.primitive(addressee.get().type(), name, argumentTypes, arguments, call)
                    : MaslType.ERROR;
        }
        Receiver receiver = names.receiver(call.expression());
        List<MaslType> argumentTypes = types(arguments);
        if (isConsolePrint(receiver, call)) {
            errors.at(call.expression(), call.expression().getText() + "." + name.getText() + " writes past the"
                    + " mission's journal: use `.logln(…)` (`.log(…)` without the line break)");
            return MaslType.ERROR;
        }
        if (receiver instanceof Receiver.OfLabel ofLabel) {
            return MemberTyper.isLabelMember(name.getText())
                    ? members.labelMember(ofLabel.label(), name, argumentTypes, call)
                    : members.primitive(null, name, argumentTypes, arguments, call);
        }
        if (receiver instanceof Receiver.OfEntry ofEntry) {
            return members.entryMember(ofEntry.entry(), name, argumentTypes, call);
        }
        if (receiver instanceof Receiver.OfType ofType) {
            if (ofType.type() instanceof MaslType.AgentRef agentType) {
                return members.primitive(agentType.type(), name, argumentTypes, arguments, call);
            }
            if (ofType.type() instanceof MaslType.JavaClass javaClass) {
                return members.javaMethod(javaClass.type(), true, name, argumentTypes, call);
            }
            errors.at(call.expression(), ofType.type().describe() + " has no methods");
            return MaslType.ERROR;
        }
        if (receiver instanceof Receiver.PackagePrefix prefix) {
            names.reportUnresolved(prefix.first());
            return MaslType.ERROR;
        }
        MaslType type = ((Receiver.Value) receiver).type();
        if (TypeRules.isError(type)) {
            return MaslType.ERROR;
        }
        if (type instanceof MaslType.AgentRef agent) {
            return members.primitive(agent.type(), name, argumentTypes, arguments, call);
        }
        if (MaslType.OBJECT.equals(type)) {
            return members.dynamic(name, call);
        }
        if (type instanceof MaslType.ArrayOf && name.getText().equals("clone") && arguments.isEmpty()) {
            return type;
        }
        if (type instanceof MaslType.ArrayOf) {
            return members.javaMethod(Object.class, false, name, argumentTypes, call);
        }
        if (type instanceof MaslType.JavaClass javaClass) {
            // `s = "x"` then `.logln(s);` on the next line: a primitive no Java object has, after a `;` left out.
            boolean primitiveOfAnAgent = members.isPrimitive(name.getText())
                    && JavaMembers.method(javaClass.type(), name.getText(), argumentTypes, false)
                            instanceof JavaMembers.Lookup.Missing;
            if (primitiveOfAnAgent && errors.missingSemicolonBefore(call.DOT().getSymbol(), call.expression())) {
                return MaslType.ERROR;
            }
            return members.javaMethod(javaClass.type(), false, name, argumentTypes, call);
        }
        if (!errors.missingSemicolonBefore(call.DOT().getSymbol(), call.expression())) {
            errors.at(call.expression(), type.describe() + " cannot be dereferenced");
        }
        return MaslType.ERROR;
    }

    /**
     * {@code System.out.println(…)}: an agent's output is its journal, which {@code masl run} writes on
     * standard output in order; Java's console would mix into it unordered.
     */
    private static boolean isConsolePrint(Receiver receiver, MASLParser.MethodCallContext call) {
        String console = call.expression().getText();
        return receiver instanceof Receiver.Value value
                && value.type().equals(new MaslType.JavaClass(java.io.PrintStream.class))
                && (console.equals("System.out") || console.equals("System.err")
                        || console.equals("java.lang.System.out") || console.equals("java.lang.System.err"))
                && call.identifier().getText().startsWith("print");
    }

    // ------------------------------------------------------------------ assignments

    @Override
    public MaslType visitAssignExpr(MASLParser.AssignExprContext assignment) {
        return assignments.assign(assignment);
    }

    @Override
    public MaslType visitPostfixExpr(MASLParser.PostfixExprContext increment) {
        return assignments.incrementOrDecrement(increment.op, increment.expression());
    }

    @Override
    public MaslType visitPrefixExpr(MASLParser.PrefixExprContext prefix) {
        String operator = prefix.op.getText();
        if (operator.equals("++") || operator.equals("--")) {
            return assignments.incrementOrDecrement(prefix.op, prefix.expression());
        }
        return unary(prefix.op, prefix.expression());
    }

    // ------------------------------------------------------------------ operators

    @Override
    public MaslType visitNotExpr(MASLParser.NotExprContext not) {
        return unary(not.op, not.expression());
    }

    private MaslType unary(Token operator, ExpressionContext operand) {
        MaslType type = type(operand);
        Optional<MaslType> result = OperatorTyper.unary(operator.getText(), type);
        if (result.isEmpty()) {
            errors.at(operator, "bad operand type " + type.describe() + " for " + operator.getText());
            return MaslType.ERROR;
        }
        return result.get();
    }

    @Override
    public MaslType visitBinaryExpr(MASLParser.BinaryExprContext binary) {
        return binary(binary.op.getText(), binary.op, binary.left, binary.right);
    }

    @Override
    public MaslType visitShiftExpr(MASLParser.ShiftExprContext shift) {
        return binary(shift.shiftOperator().getText(), shift.shiftOperator().getStart(), shift.left, shift.right);
    }

    private MaslType binary(String operator, Token where, ExpressionContext left, ExpressionContext right) {
        MaslType leftType = type(left);
        MaslType rightType = type(right);
        Optional<MaslType> result = OperatorTyper.binary(operator, leftType, rightType);
        if (result.isEmpty()) {
            errors.at(where, "bad operand types for " + operator + ": " + leftType.describe() + " and "
                    + rightType.describe());
            return MaslType.ERROR;
        }
        return result.get();
    }

    @Override
    public MaslType visitCastExpr(MASLParser.CastExprContext cast) {
        MaslType target = typeNames.resolve(cast.javaType(), errors);
        MaslType source = type(cast.expression());
        if (!TypeRules.isCastable(target, source)) {
            errors.at(cast, "cannot cast " + source.describe() + " to " + target.describe());
        }
        return target;
    }

    @Override
    public MaslType visitInstanceofExpr(MASLParser.InstanceofExprContext test) {
        type(test.expression());
        // Recorded on the type's node for the generator, which spells it in Java.
        bindings.type(test.javaType(), typeNames.resolve(test.javaType(), errors));
        return MaslType.BOOLEAN;
    }

    @Override
    public MaslType visitConditionalExpr(MASLParser.ConditionalExprContext conditional) {
        checkCondition(conditional.condition, "the condition of ?:");
        MaslType whenTrue = type(conditional.whenTrue);
        MaslType whenFalse = type(conditional.whenFalse);
        if (TypeRules.isError(whenTrue) || whenTrue.equals(whenFalse) || whenFalse == MaslType.NULL) {
            return whenTrue;
        }
        if (TypeRules.isError(whenFalse) || whenTrue == MaslType.NULL) {
            return whenFalse;
        }
        if (TypeRules.isNumeric(whenTrue) && TypeRules.isNumeric(whenFalse)) {
            return TypeRules.promote(whenTrue, whenFalse);
        }
        if (TypeRules.isAssignable(whenTrue, whenFalse, false)) {
            return whenTrue;
        }
        return TypeRules.isAssignable(whenFalse, whenTrue, false) ? whenFalse : MaslType.OBJECT;
    }

    @Override
    public MaslType visitArrayAccess(MASLParser.ArrayAccessContext access) {
        MaslType array = type(access.expression(0));
        checkIndex(access.index, "an array index");
        if (array instanceof MaslType.ArrayOf arrayOf) {
            return arrayOf.element();
        }
        if (!TypeRules.isOpen(array)) {
            errors.at(access.expression(0), "array required, but " + array.describe() + " found");
            return MaslType.ERROR;
        }
        return array;
    }

    private void checkIndex(ExpressionContext index, String what) {
        MaslType type = type(index);
        if (!TypeRules.isOpen(type) && !TypeRules.isIntegral(type)) {
            errors.at(index, what + " must be an integer, found " + type.describe());
        }
    }

    // ------------------------------------------------------------------ helpers

    private static List<ExpressionContext> arguments(MASLParser.ArgumentsContext arguments) {
        return arguments.expressionList() == null ? List.of() : arguments.expressionList().expression();
    }

    private List<MaslType> types(List<ExpressionContext> expressions) {
        List<MaslType> types = new ArrayList<>();
        for (ExpressionContext expression : expressions) {
            types.add(type(expression));
        }
        return types;
    }

    /** The expression node a primary belongs to: symbols and types are recorded on expression nodes. */
    private static ParserRuleContext expressionOf(ParserRuleContext node) {
        ParserRuleContext current = node;
        while (!(current instanceof ExpressionContext) && current.getParent() != null) {
            current = current.getParent();
        }
        return current;
    }
}
