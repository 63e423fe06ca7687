package masl.translator.analysis;

import java.lang.reflect.Modifier;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import masl.grammar.MASLBaseVisitor;
import masl.grammar.MASLParser;
import masl.grammar.MASLParser.ExpressionContext;
import org.antlr.v4.runtime.ParserRuleContext;
import org.antlr.v4.runtime.Token;

/**
 * Resolves the names of expressions and computes their static types (MASL §3), reporting what does not
 * resolve or fit. Each expression node gets its type in {@link Bindings}; an expression already found
 * wrong has type {@link MaslType#ERROR}, which every rule accepts, so a mistake is reported once.
 * The block being checked sets the {@link Scope} names are resolved in.
 */
final class ExpressionTyper extends MASLBaseVisitor<MaslType> {

    /** What the receiver of a member ({@code receiver.member}) turned out to be. */
    private sealed interface Receiver {
        /** A value: a variable, an agent, {@code this}, any expression. */
        record Value(MaslType type) implements Receiver { }

        record OfLabel(Label label) implements Receiver { }

        record OfEntry(EntryRef entry) implements Receiver { }

        /** A class or an agent type, for its static members. */
        record OfType(MaslType type) implements Receiver { }

        /** Names that may begin a qualified class name ({@code java.util}); {@code first} is reported if not. */
        record PackagePrefix(String prefix, Token first) implements Receiver { }
    }

    private final Bindings bindings;
    private final Errors errors;
    private final TypeNames typeNames;
    private final EntryNames entryNames;
    private final MemberTyper members;
    private final Set<String> unresolvedNames = new HashSet<>();
    private Scope scope;

    ExpressionTyper(Bindings bindings, Errors errors, TypeNames typeNames, EntryNames entryNames, MemberTyper members) {
        this.bindings = bindings;
        this.errors = errors;
        this.typeNames = typeNames;
        this.entryNames = entryNames;
        this.members = members;
    }

    void useScope(Scope current) {
        scope = current;
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

    /** Whether {@code name} names an event in scope; reports when it does not. */
    Optional<EventDecl> event(MASLParser.IdentifierContext name) {
        Optional<Symbol> symbol = scope.resolve(name.getText());
        if (symbol.isEmpty()) {
            if (unresolvedNames.add(name.getText())) {
                errors.at(name, "cannot find event " + name.getText());
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

    private void checkAssignable(MaslType target, ExpressionContext value) {
        MaslType type = type(value);
        if (!TypeRules.isAssignable(target, type, true)) {
            errors.at(value, "incompatible types: " + type.describe() + " cannot be converted to " + target.describe());
        }
    }

    // ------------------------------------------------------------------ primaries

    @Override
    public MaslType visitPrimaryExpr(MASLParser.PrimaryExprContext expression) {
        if (expression.primary() instanceof MASLParser.NameExprContext) {
            return valueOf(receiver(expression), expression);
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
            Optional<Label> label = labelNamed(arguments.get(0));
            if (label.isPresent()) {
                return members.labelMember(label.get(), call.identifier().getStart(), List.of(), expressionOf(call));
            }
            notALabel(arguments.get(0), "isFinished needs a label, found " + arguments.get(0).getText());
            return MaslType.BOOLEAN;
        }
        types(arguments);
        errors.at(call.identifier(), "cannot find symbol " + name + ": a primitive is invoked as ." + name + "(…)");
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
        event(call.event);
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
            errors.at(name, "cannot find type " + name.qualifiedName().getText());
            return MaslType.ERROR;
        }
        return type.get();
    }

    // ------------------------------------------------------------------ members, labels, entries

    @Override
    public MaslType visitFieldAccess(MASLParser.FieldAccessContext access) {
        return valueOf(receiver(access), access);
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
        Optional<ImportedType> launchedOn = labelLaunchTarget(call.expression());
        if (launchedOn != null) {
            List<MaslType> argumentTypes = types(arguments);
            return launchedOn.isPresent() || isLabelThis(call.expression())
                    ? members.primitive(launchedOn.orElse(null), name, argumentTypes, arguments, call)
                    : MaslType.ERROR;
        }
        Receiver receiver = receiver(call.expression());
        List<MaslType> argumentTypes = types(arguments);
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
            reportUnresolved(prefix.first());
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
            return members.javaMethod(javaClass.type(), false, name, argumentTypes, call);
        }
        errors.at(call.expression(), type.describe() + " cannot be dereferenced");
        return MaslType.ERROR;
    }

    /**
     * The target agent's type of a label launch (§10): {@code l.a.m()} gives {@code a}'s type,
     * {@code l.this.m()} an empty Optional; null when {@code receiver} is not of these forms. A target that
     * is not an agent is reported.
     */
    private Optional<ImportedType> labelLaunchTarget(ExpressionContext receiver) {
        if (receiver instanceof MASLParser.LabelSelfContext labelSelf) {
            if (labelNamed(labelSelf.expression()).isEmpty()) {
                notALabel(labelSelf.expression(), labelSelf.expression().getText() + " is not a label");
            }
            return Optional.empty();
        }
        if (receiver instanceof MASLParser.FieldAccessContext access && labelNamed(access.expression()).isPresent()) {
            Optional<Symbol> target = scope.resolve(access.identifier().getText());
            if (target.isPresent() && target.get() instanceof AgentDecl agent) {
                bindings.bind(access, agent);
                bindings.type(access, new MaslType.AgentRef(agent.declaredType()));
                return Optional.of(agent.declaredType());
            }
            errors.at(access.identifier(), "in " + access.getText() + ".…, " + access.identifier().getText()
                    + " must be an agent or this");
            return Optional.empty();
        }
        return null;
    }

    private static boolean isLabelThis(ExpressionContext receiver) {
        return receiver instanceof MASLParser.LabelSelfContext;
    }

    /** The label a bare name denotes, bound to it; empty when the expression is not a label's name. */
    private Optional<Label> labelNamed(ExpressionContext expression) {
        if (expression instanceof MASLParser.PrimaryExprContext primary
                && primary.primary() instanceof MASLParser.NameExprContext name
                && scope.resolve(name.getText()).orElse(null) instanceof Label label) {
            bindings.bind(expression, label);
            bindings.type(expression, MaslType.VOID);
            return Optional.of(label);
        }
        return Optional.empty();
    }

    /** Reports an expression where a label should be; an undeclared name is reported as such, once. */
    private void notALabel(ExpressionContext expression, String message) {
        if (expression instanceof MASLParser.PrimaryExprContext primary
                && primary.primary() instanceof MASLParser.NameExprContext name
                && scope.resolve(name.getText()).isEmpty()) {
            reportUnresolved(name.getStart());
        } else {
            errors.at(expression, message);
        }
    }

    /** Resolves what stands before a {@code .}: a value, a label, an entry, a type or a package name. */
    private Receiver receiver(ExpressionContext expression) {
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
        return new Receiver.Value(type(expression));
    }

    private Receiver named(Token name, ExpressionContext expression) {
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
    private MaslType member(Receiver owner, Token name, ParserRuleContext access) {
        if (owner instanceof Receiver.OfEntry ofEntry) {
            return members.entryMember(ofEntry.entry(), name, null, access);
        }
        if (owner instanceof Receiver.OfLabel ofLabel) {
            errors.at(name, "label " + ofLabel.label().name() + " has no member " + name.getText()
                    + "; a label is used as l.x = .m(…), l.a.m(…), l.isFinished() or l.free()");
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

    private MaslType staticMember(MaslType type, Token name, boolean isWrite, ParserRuleContext access) {
        if (name.getText().equals("class") && !isWrite) {
            bindings.bind(access, new Member(Member.Kind.JAVA_FIELD, "class", List.of(), null));
            return new MaslType.JavaClass(Class.class);
        }
        if (type instanceof MaslType.AgentRef agentType) {
            return members.attribute(agentType.type(), name, isWrite, access);
        }
        if (type instanceof MaslType.JavaClass javaClass) {
            return members.javaField(javaClass.type(), true, name, isWrite, access);
        }
        errors.at(name, type.describe() + " has no member " + name.getText());
        return MaslType.ERROR;
    }

    private MaslType instanceMember(MaslType type, Token name, boolean isWrite, ParserRuleContext access) {
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
        errors.at(name, type.describe() + " has no member " + name.getText());
        return MaslType.ERROR;
    }

    private MaslType valueOf(Receiver receiver, ExpressionContext expression) {
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

    // ------------------------------------------------------------------ assignments

    @Override
    public MaslType visitAssignExpr(MASLParser.AssignExprContext assignment) {
        String operator = assignment.op.getText();
        Optional<MaslType> labelTarget = labelAssignmentTarget(assignment.target);
        if (labelTarget != null) {
            if (!operator.equals("=")) {
                errors.at(assignment.op, "a label assignment is written l.x = .m(…), not with " + operator);
            }
            if (!isInvocation(assignment.value)) {
                errors.at(assignment.value, "a label assignment stores the result of a primitive invocation, "
                        + "such as .m(…) or a.m(…)");
            }
            labelTarget.ifPresentOrElse(target -> checkAssignable(target, assignment.value),
                    () -> type(assignment.value));
            return MaslType.VOID;
        }
        MaslType target = assignable(assignment.target);
        if (operator.equals("=")) {
            checkAssignable(target, assignment.value);
        } else {
            MaslType value = type(assignment.value);
            if (!OperatorTyper.compound(operator, target, value)) {
                errors.at(assignment.op, "bad operand types for " + operator + ": " + target.describe() + " and "
                        + value.describe());
            }
        }
        return target;
    }

    /**
     * The type of the variable or attribute a label assignment stores into (§10: {@code l.x = …},
     * {@code l.a.x = …}, {@code l.this.x = …}); an empty Optional after an error; null when the target is
     * not of a label form.
     */
    private Optional<MaslType> labelAssignmentTarget(ExpressionContext target) {
        if (!(target instanceof MASLParser.FieldAccessContext access)) {
            return null;
        }
        Token name = access.identifier().getStart();
        if (labelNamed(access.expression()).isPresent()) {
            Optional<Symbol> symbol = scope.resolve(name.getText());
            if (symbol.isPresent() && symbol.get() instanceof Variable variable) {
                bindings.bind(access, variable);
                checkNotFinal(variable, name);
                return Optional.of(bindings.type(access, variable.type()));
            }
            errors.at(name, "in " + access.getText() + " = …, " + name.getText() + " must be a variable in scope");
            return Optional.empty();
        }
        Optional<ImportedType> agent = labelLaunchTarget(access.expression());
        if (agent == null) {
            return null;
        }
        boolean validTarget = agent.isPresent() || isLabelThis(access.expression());
        if (!validTarget) {
            return Optional.empty();
        }
        return Optional.of(bindings.type(access, members.attribute(agent.orElse(null), name, true, access)));
    }

    private static boolean isInvocation(ExpressionContext value) {
        return value instanceof MASLParser.MethodCallContext
                || value instanceof MASLParser.PrimaryExprContext primary
                        && primary.primary() instanceof MASLParser.SelfInvocationContext;
    }

    /** The type of what is assigned to (by {@code =}, {@code op=}, {@code ++}, {@code --}); reports what cannot be. */
    private MaslType assignable(ExpressionContext target) {
        MaslType type;
        if (target instanceof MASLParser.PrimaryExprContext primary
                && primary.primary() instanceof MASLParser.NameExprContext nameExpr) {
            type = assignableName(nameExpr.identifier().getStart(), target);
        } else if (target instanceof MASLParser.PrimaryExprContext primary
                && primary.primary() instanceof MASLParser.SelfAttributeContext attribute) {
            type = members.attribute(null, attribute.identifier().getStart(), true, target);
        } else if (target instanceof MASLParser.FieldAccessContext access) {
            Receiver owner = receiver(access.expression());
            Token name = access.identifier().getStart();
            if (owner instanceof Receiver.OfType ofType) {
                type = staticMember(ofType.type(), name, true, access);
            } else if (owner instanceof Receiver.Value value) {
                type = instanceMember(value.type(), name, true, access);
            } else {
                type = member(owner, name, access);
            }
        } else if (target instanceof MASLParser.ArrayAccessContext) {
            type = type(target);
        } else {
            type(target);
            errors.at(target, "cannot assign a value to " + target.getText());
            type = MaslType.ERROR;
        }
        return bindings.type(target, type);
    }

    private MaslType assignableName(Token name, ExpressionContext target) {
        Receiver receiver = named(name, target);
        if (receiver instanceof Receiver.Value value) {
            Symbol symbol = bindings.symbolOf(target).orElse(null);
            if (symbol instanceof Variable variable) {
                checkNotFinal(variable, name);
            } else if (symbol instanceof AgentDecl) {
                errors.at(name, "cannot assign a value to agent " + name.getText());
            }
            return value.type();
        }
        return valueOf(receiver, target);
    }

    private void checkNotFinal(Variable variable, Token name) {
        if (variable.isFinal()) {
            errors.at(name, "cannot assign a value to final variable " + name.getText());
        }
    }

    @Override
    public MaslType visitPostfixExpr(MASLParser.PostfixExprContext increment) {
        return incrementOrDecrement(increment.op, increment.expression());
    }

    @Override
    public MaslType visitPrefixExpr(MASLParser.PrefixExprContext prefix) {
        String operator = prefix.op.getText();
        if (operator.equals("++") || operator.equals("--")) {
            return incrementOrDecrement(prefix.op, prefix.expression());
        }
        return unary(prefix.op, prefix.expression());
    }

    private MaslType incrementOrDecrement(Token operator, ExpressionContext operand) {
        MaslType type = assignable(operand);
        if (!TypeRules.isOpen(type) && !TypeRules.isNumeric(type)) {
            errors.at(operator, "bad operand type " + type.describe() + " for " + operator.getText());
        }
        return type;
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
        typeNames.resolve(test.javaType(), errors);
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

    /** An unknown name is one mistake however often it is used: reported at its first use only (events included). */
    private void reportUnresolved(Token name) {
        if (unresolvedNames.add(name.getText())) {
            errors.at(name, "cannot find symbol " + name.getText());
        }
    }

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
