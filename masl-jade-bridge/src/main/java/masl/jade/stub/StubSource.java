package masl.jade.stub;

import java.lang.invoke.MethodType;
import java.lang.reflect.Method;
import java.util.List;
import java.util.StringJoiner;
import masl.jade.platform.JadeException;

/**
 * The Java source of a stub class: a subclass of an agent's implementation class whose primitives,
 * instead of running, hand their index and arguments to a {@link BodyStub}, as do the runtime's reads
 * and writes of its attributes ({@link masl.runtime.AttributesElsewhere}). For a primitive
 * {@code int add(int, int)}, number 0 of the list:
 * <pre>{@code
 * @Override
 * public int add(int a0, int a1) {
 *     return (java.lang.Integer) body.call(0, new Object[] {a0, a1});
 * }
 * }</pre>
 * The class is in the implementation's package, so that an implementation nested in a class of
 * that package compiles too; its name ends in {@value #SUFFIX}.
 */
record StubSource(Class<?> implementation, List<Method> methods) {

    static final String SUFFIX = "$MaslStub";

    StubSource {
        methods = List.copyOf(methods);
    }

    /** The binary name of the stub class. */
    String className() {
        return implementation.getName() + SUFFIX;
    }

    /** @throws JadeException if a type the stub must name has no name in Java source (a local or anonymous class) */
    String text() {
        String packageName = implementation.getPackageName();
        String simpleName = className().substring(packageName.isEmpty() ? 0 : packageName.length() + 1);
        StringBuilder java = new StringBuilder();
        if (!packageName.isEmpty()) {
            java.append("package ").append(packageName).append(";\n\n");
        }
        java.append("/** Made by masl-jade-bridge: the stand-in of a ").append(implementation.getSimpleName())
                .append(" whose body runs in another container; its primitives are requests to that body. */\n")
                .append("public final class ").append(simpleName).append(" extends ").append(sourceName(implementation))
                .append(" implements masl.runtime.AttributesElsewhere {\n\n")
                .append("    private final masl.jade.stub.BodyStub body;\n\n")
                .append("    public ").append(simpleName).append("(masl.jade.stub.BodyStub body) {\n")
                .append("        this.body = body;\n")
                .append("    }\n");
        for (int index = 0; index < methods.size(); index++) {
            appendForwarder(java, index, methods.get(index));
        }
        java.append("\n    @Override\n")
                .append("    public java.lang.Object readAttribute(java.lang.String attribute,"
                        + " java.util.function.Supplier<?> read) {\n")
                .append("        return body.readAttribute(attribute, read);\n")
                .append("    }\n")
                .append("\n    @Override\n")
                .append("    public void writeAttribute(java.lang.String attribute, java.lang.Runnable write) {\n")
                .append("        body.writeAttribute(attribute, write);\n")
                .append("    }\n");
        return java.append("}\n").toString();
    }

    private void appendForwarder(StringBuilder java, int index, Method method) {
        Class<?>[] parameters = method.getParameterTypes();
        StringJoiner declared = new StringJoiner(", ");
        StringJoiner passed = new StringJoiner(", ");
        for (int i = 0; i < parameters.length; i++) {
            declared.add(sourceName(parameters[i]) + " a" + i);
            passed.add("a" + i);
        }
        Class<?> result = method.getReturnType();
        String call = "body.call(" + index + ", new Object[] {" + passed + "})";
        java.append("\n    @Override\n")
                .append("    public ").append(sourceName(result)).append(' ').append(method.getName())
                .append('(').append(declared).append(") {\n")
                .append("        ").append(result == void.class ? call
                        : "return (" + sourceName(MethodType.methodType(result).wrap().returnType()) + ") " + call)
                .append(";\n")
                .append("    }\n");
    }

    private static String sourceName(Class<?> type) {
        String name = type.getCanonicalName();
        if (name == null) {
            throw new JadeException(type.getName() + " has no name in Java source: a stub cannot name it");
        }
        return name;
    }
}
