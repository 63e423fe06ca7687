package masl.translator.generate;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import masl.runtime.descriptor.Attribute;
import masl.runtime.descriptor.Parameter;
import masl.runtime.descriptor.Primitive;

/**
 * The helper methods through which a program calls primitives and accesses attributes
 * (generated-code contract §8.1, §8.4): one per member and kind of access, so that a call site
 * reads {@code invoke$getProxyID(ctx, agent$b)} and the arguments, evaluated by the caller, are
 * the helper's parameters, which the lambda handed to the runtime captures (effectively final).
 */
final class AgentCalls {

    /** How a primitive is called. */
    enum Kind {
        /** {@code ctx.invokeSelf}: an internal synchronous invocation, run now; gives the value. */
        INVOKE_SELF("invokeSelf"),
        /** {@code ctx.invoke}: an external synchronous invocation; gives the future to await. */
        INVOKE("invoke"),
        /** {@code ctx.launch}: an asynchronous primitive; gives the future at once. */
        LAUNCH("launch");

        private final String prefix;

        Kind(String prefix) {
            this.prefix = prefix;
        }
    }

    /** Helper name to its lines; a name is taken once per member, kind and receiver class. */
    private final Map<String, List<String>> helpers = new LinkedHashMap<>();
    private final Map<String, String> names = new LinkedHashMap<>();

    /** The helper methods used so far, in the order of first use. */
    List<List<String>> helpers() {
        return List.copyOf(helpers.values());
    }

    /**
     * The call of {@code primitive} of {@code calleeClass} with {@code arguments} (Java, evaluated
     * by the caller); {@code callee} is the receiver's Java expression, ignored for an internal call.
     */
    String call(Kind kind, Primitive primitive, Primitive countermeasure, String calleeClass, String callee,
            List<String> arguments) {
        return call(kind, primitive, countermeasure, calleeClass, calleeClass, callee, arguments);
    }

    /**
     * The same, on a receiver of static class {@code receiverClass} that may not be a
     * {@code calleeClass} (§4): the helper calls the primitive only on an agent of that class, and
     * gives an agent without it (a nop) the default value.
     */
    String call(Kind kind, Primitive primitive, Primitive countermeasure, String calleeClass, String receiverClass,
            String callee, List<String> arguments) {
        String helper = helper(kind, primitive, countermeasure, calleeClass, receiverClass);
        List<String> all = new ArrayList<>();
        all.add("ctx");
        if (kind != Kind.INVOKE_SELF) {
            all.add(callee);
        }
        all.addAll(arguments);
        return helper + "(" + String.join(", ", all) + ")";
    }

    /** The Java type of the value of {@code primitive}'s call: boxed in a future for INVOKE and LAUNCH. */
    static String futureType(Primitive primitive) {
        return "CompletableFuture<" + simple(boxed(primitive.returnType())) + ">";
    }

    /** A {@code java.lang} class by its simple name, as in Java source. */
    private static String simple(String javaType) {
        String lang = "java.lang.";
        return javaType.startsWith(lang) && javaType.indexOf('.', lang.length()) < 0
                ? javaType.substring(lang.length()) : javaType;
    }

    private String helper(Kind kind, Primitive primitive, Primitive countermeasure, String calleeClass,
            String receiverClass) {
        String key = kind + " " + primitive.name() + " " + calleeClass + " " + receiverClass;
        boolean dispatches = !calleeClass.equals(receiverClass);
        String existing = names.get(key);
        if (existing != null) {
            return existing;
        }
        String name = unique(kind.prefix + "$" + primitive.name());
        names.put(key, name);
        boolean self = kind == Kind.INVOKE_SELF;
        String receiver = self ? "self" : "callee";
        List<String> parameters = new ArrayList<>();
        parameters.add("AgentContext ctx");
        if (!self) {
            parameters.add("final " + (dispatches ? receiverClass + " receiver" : calleeClass + " callee"));
        }
        List<String> argumentNames = new ArrayList<>();
        int i = 0;
        for (Parameter parameter : primitive.parameters()) {
            parameters.add("final " + simple(parameter.type()) + " " + argumentName(parameter, i));
            argumentNames.add(argumentName(parameter, i));
            i++;
        }
        boolean isVoid = primitive.returnType().equals("void");
        String type = self ? simple(primitive.returnType()) : futureType(primitive);
        String run = callable(receiver + "." + primitive.name() + "(" + String.join(", ", argumentNames) + ")", isVoid);
        String runtimeCall = "ctx." + kind.prefix + "(" + (self ? "" : "callee, ") + JavaText.quote(primitive.name())
                + ", " + defaultValue(primitive.returnType()) + ", " + run;
        if (kind == Kind.LAUNCH && countermeasure != null) {
            runtimeCall += ", " + JavaText.quote(countermeasure.name()) + ", "
                    + callable("callee." + countermeasure.name() + "()", countermeasure.returnType().equals("void"));
        }
        runtimeCall += ")";
        List<String> lines = new ArrayList<>();
        lines.add("    /** " + describe(kind, primitive, countermeasure) + " */");
        lines.add("    private " + (self ? "" : "static ") + type + " " + name + "(" + String.join(", ", parameters)
                + ") {");
        if (dispatches) {
            lines.add("        if (!(receiver instanceof " + calleeClass + " callee)) {");
            lines.add("            return CompletableFuture.completedFuture(" + defaultValue(primitive.returnType())
                    + "); // a nop() for an agent whose type lacks " + primitive.name() + " (MASL 4)");
            lines.add("        }");
        }
        lines.add("        " + (self && isVoid ? "" : "return ") + runtimeCall + ";");
        lines.add("    }");
        helpers.put(name, lines);
        return name;
    }

    private static String describe(Kind kind, Primitive primitive, Primitive countermeasure) {
        String signature = primitive.signature();
        return switch (kind) {
            case INVOKE_SELF -> signature + " of this agent: an internal invocation, filtered by permeability (MASL 9, 11).";
            case INVOKE -> signature + " of another agent: queued at it, served at its step boundary (MASL 9).";
            case LAUNCH -> signature + ", asynchronous: runs on a thread of its own (MASL 9)"
                    + (countermeasure == null ? "." : "; arms its countermeasure " + countermeasure.name() + ".");
        };
    }

    /** {@code read$x(ctx, owner)}: a read of attribute {@code attribute} of an agent of {@code ownerClass}. */
    String read(Attribute attribute, String ownerClass, String owner) {
        String key = "read " + attribute.name() + " " + ownerClass;
        String name = names.get(key);
        if (name == null) {
            name = unique("read$" + attribute.name());
            names.put(key, name);
            String field = (attribute.isStatic() ? ownerClass : "owner") + "." + attribute.name();
            helpers.put(name, List.of(
                    "    /** A read of attribute " + attribute.name() + ", filtered by permeability (MASL 9, 11). */",
                    "    private static " + simple(attribute.type()) + " " + name + "(AgentContext ctx, final " + ownerClass
                            + " owner) {",
                    "        return ctx.readAttribute(owner, " + JavaText.quote(attribute.name()) + ", "
                            + defaultValue(attribute.type()) + ", () -> " + field + ");",
                    "    }"));
        }
        return name + "(ctx, " + owner + ")";
    }

    /** {@code write$x(ctx, owner, value)}: a write of attribute {@code attribute}. */
    String write(Attribute attribute, String ownerClass, String owner, String value) {
        String key = "write " + attribute.name() + " " + ownerClass;
        String name = names.get(key);
        if (name == null) {
            name = unique("write$" + attribute.name());
            names.put(key, name);
            String field = (attribute.isStatic() ? ownerClass : "owner") + "." + attribute.name();
            helpers.put(name, List.of(
                    "    /** A write of attribute " + attribute.name() + ", filtered by permeability (MASL 9, 11). */",
                    "    private static void " + name + "(AgentContext ctx, final " + ownerClass + " owner, final "
                            + simple(attribute.type()) + " value) {",
                    "        ctx.writeAttribute(owner, " + JavaText.quote(attribute.name()) + ", () -> " + field
                            + " = value);",
                    "    }"));
        }
        return name + "(ctx, " + owner + ", " + value + ")";
    }

    /** {@code store$x(owner)}: the consumer a label stores a result with into attribute {@code attribute} (§10). */
    String store(Attribute attribute, String ownerClass, String owner) {
        String key = "store " + attribute.name() + " " + ownerClass;
        String name = names.get(key);
        if (name == null) {
            name = unique("store$" + attribute.name());
            names.put(key, name);
            String field = (attribute.isStatic() ? ownerClass : "owner") + "." + attribute.name();
            helpers.put(name, List.of(
                    "    /** Stores a label's result in attribute " + attribute.name() + " of owner (MASL 10). */",
                    "    private static java.util.function.Consumer<" + simple(boxed(attribute.type())) + "> " + name
                            + "(final " + ownerClass + " owner) {",
                    "        return value -> " + field + " = value;",
                    "    }"));
        }
        return name + "(" + owner + ")";
    }

    private String unique(String base) {
        String name = base;
        for (int n = 2; helpers.containsKey(name); n++) {
            name = base + "$" + n;
        }
        helpers.put(name, List.of());
        return name;
    }

    private static String argumentName(Parameter parameter, int index) {
        String name = JavaNames.identifier(parameter.name());
        return name.equals("ctx") || name.equals("callee") || name.equals("self") ? name + "_" + index : name;
    }

    private static String callable(String call, boolean isVoid) {
        return isVoid ? "() -> {\n            " + call + ";\n            return null;\n        }" : "() -> " + call;
    }

    /** The default value of a descriptor's Java type, boxed as the runtime's type parameter wants it. */
    static String defaultValue(String javaType) {
        return switch (javaType) {
            case "boolean" -> "false";
            case "int" -> "0";
            case "long" -> "0L";
            case "float" -> "0f";
            case "double" -> "0d";
            case "byte", "short", "char" -> "(" + javaType + ") 0";
            default -> "null";
        };
    }

    static String boxed(String javaType) {
        return switch (javaType) {
            case "boolean" -> "Boolean";
            case "int" -> "Integer";
            case "long" -> "Long";
            case "float" -> "Float";
            case "double" -> "Double";
            case "byte" -> "Byte";
            case "short" -> "Short";
            case "char" -> "Character";
            case "void" -> "Object";
            default -> javaType;
        };
    }
}
