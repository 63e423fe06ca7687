package masl.runtime.descriptor;

import java.lang.reflect.Field;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;

/**
 * Checks a type against its Java implementation: the class exists, is public, concrete, has a public
 * no-argument constructor and extends the supertype's class; each member the descriptor declares
 * exists with its signature (a public method with the parameter types and return type; a public field
 * of the type; {@code static} and, for fields, {@code final} as declared); utility and exception
 * classes exist. Inherited members are checked with the supertype, whose class this one extends.
 */
final class ImplementationChecker {

    private final Declaration declaration;
    private final ClassLoader classes;
    private final Problems problems;

    private ImplementationChecker(Declaration declaration, ClassLoader classes, Problems problems) {
        this.declaration = declaration;
        this.classes = classes;
        this.problems = problems;
    }

    static void check(Declaration declaration, AgentType supertype, ClassLoader classes, Problems problems) {
        new ImplementationChecker(declaration, classes, problems).check(supertype);
    }

    private void check(AgentType supertype) {
        XmlElement agent = declaration.agent();
        for (Declaration.UtilityClass utility : declaration.utilityClasses()) {
            if (JavaTypes.resolve(utility.name(), classes).isEmpty()) {
                problems.at(utility.element(), "utility class '" + utility.name() + "' not found");
            }
        }
        Optional<Class<?>> found = JavaTypes.resolve(declaration.fullClassName(), classes);
        if (found.isEmpty()) {
            problems.at(agent, "implementation class '" + declaration.fullClassName()
                    + "' not found on the agent path or the class path");
            return;
        }
        Class<?> implementation = found.get();
        checkInstantiable(implementation);
        if (supertype != null) {
            JavaTypes.resolve(supertype.fullClassName(), classes)
                    .filter(superclass -> !superclass.isAssignableFrom(implementation))
                    .ifPresent(superclass -> problems.at(agent, "implementation class '" + implementation.getName()
                            + "' does not extend '" + superclass.getName() + "', the class of supertype "
                            + supertype.shortName()));
        }
        declaration.primitives().forEach(primitive -> checkMethod(implementation, primitive));
        declaration.attributes().forEach(attribute -> checkField(implementation, attribute));
    }

    private void checkInstantiable(Class<?> implementation) {
        XmlElement agent = declaration.agent();
        if (!Modifier.isPublic(implementation.getModifiers()) || implementation.isInterface()
                || Modifier.isAbstract(implementation.getModifiers())) {
            problems.at(agent, "implementation class '" + implementation.getName()
                    + "' must be a public, non-abstract class");
            return;
        }
        try {
            implementation.getConstructor();
        } catch (NoSuchMethodException e) {
            problems.at(agent, "implementation class '" + implementation.getName()
                    + "' has no public no-argument constructor");
        } catch (LinkageError e) {
            problems.at(agent, "implementation class '" + implementation.getName() + "' cannot be linked: " + e);
        }
    }

    private void checkMethod(Class<?> implementation, Primitive primitive) {
        XmlElement element = declaration.memberElementAt(primitive.line(), primitive.column());
        List<Class<?>> parameterTypes = new ArrayList<>();
        boolean typesFound = true;
        for (Parameter parameter : primitive.parameters()) {
            Optional<Class<?>> type = JavaTypes.resolve(parameter.type(), classes);
            typesFound &= report(type, element, "type '" + parameter.type() + "' of parameter '" + parameter.name() + "'");
            type.ifPresent(parameterTypes::add);
        }
        Optional<Class<?>> returnType = JavaTypes.resolve(primitive.returnType(), classes);
        typesFound &= report(returnType, element, "return type '" + primitive.returnType() + "'");
        for (String exception : primitive.exceptions()) {
            Optional<Class<?>> type = JavaTypes.resolve(exception, classes);
            if (report(type, element, "exception '" + exception + "'") && !Throwable.class.isAssignableFrom(type.get())) {
                problems.at(element, "exception '" + exception + "' is not a Throwable");
            }
        }
        if (!typesFound) {
            return;
        }
        Method method;
        try {
            method = implementation.getMethod(primitive.name(), parameterTypes.toArray(Class<?>[]::new));
        } catch (NoSuchMethodException | LinkageError e) {
            problems.at(element, "implementation class '" + implementation.getName() + "' has no public method "
                    + primitive.signature());
            return;
        }
        if (!method.getReturnType().equals(returnType.get())) {
            problems.at(element, "method " + primitive.name() + " of '" + implementation.getName() + "' returns "
                    + method.getReturnType().getTypeName() + ", the descriptor says " + primitive.returnType());
        }
        if (Modifier.isStatic(method.getModifiers()) != primitive.isStatic()) {
            problems.at(element, "method " + primitive.name() + " of '" + implementation.getName() + "' is "
                    + (primitive.isStatic() ? "not static, the descriptor says static" : "static, the descriptor does not say static"));
        }
    }

    private void checkField(Class<?> implementation, Attribute attribute) {
        XmlElement element = declaration.memberElementAt(attribute.line(), attribute.column());
        Optional<Class<?>> type = JavaTypes.resolve(attribute.type(), classes);
        if (!report(type, element, "type '" + attribute.type() + "'")) {
            return;
        }
        Field field;
        try {
            field = implementation.getField(attribute.name());
        } catch (NoSuchFieldException | LinkageError e) {
            problems.at(element, "implementation class '" + implementation.getName() + "' has no public field "
                    + attribute.type() + " " + attribute.name());
            return;
        }
        if (!field.getType().equals(type.get())) {
            problems.at(element, "field " + attribute.name() + " of '" + implementation.getName() + "' has type "
                    + field.getType().getTypeName() + ", the descriptor says " + attribute.type());
        }
        checkModifier(element, field, Modifier.STATIC, "static", attribute.isStatic(), implementation);
        checkModifier(element, field, Modifier.FINAL, "final", attribute.isFinal(), implementation);
    }

    private void checkModifier(XmlElement element, Field field, int modifier, String word, boolean declared,
            Class<?> implementation) {
        if (((field.getModifiers() & modifier) != 0) != declared) {
            problems.at(element, "field " + field.getName() + " of '" + implementation.getName() + "' is "
                    + (declared ? "not " + word + ", the descriptor says " + word
                            : word + ", the descriptor does not say " + word));
        }
    }

    /** True when found; otherwise reports "{@code what} not found" at the element. */
    private boolean report(Optional<Class<?>> type, XmlElement element, String what) {
        if (type.isEmpty()) {
            problems.at(element, what + " not found");
        }
        return type.isPresent();
    }

}
