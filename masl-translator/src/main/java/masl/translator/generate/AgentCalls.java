package masl.translator.generate;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
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

    /** Who registers a call with a label (§10): the call site, or the helper, with or without a store. */
    private enum Registration {
        /** The helper gives the invocation's future; a label's invocation is registered at the call site. */
        NONE,
        /** The helper registers the invocation with the label it is given. */
        LABEL,
        /** The same, with the consumer that stores the result. */
        LABEL_STORING
    }

    /** The names a helper gives its own parameters and locals: a primitive's parameter of one is renamed. */
    private static final Set<String> HELPER_NAMES = Set.of("ctx", "callee", "self", "receiver", "label", "store");

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
        String helper = helper(kind, primitive, countermeasure, calleeClass, receiverClass, Registration.NONE);
        List<String> all = new ArrayList<>();
        all.add("ctx");
        if (kind != Kind.INVOKE_SELF) {
            all.add(callee);
        }
        all.addAll(arguments);
        return helper + "(" + String.join(", ", all) + ")";
    }

    /**
     * A label's invocation (§10) of another agent's primitive, {@code label} and {@code store} (null
     * for none) Java, on a receiver of static class {@code receiverClass} that may not be a
     * {@code calleeClass} (§4): the helper registers it, and registers the {@code nop()} of an agent
     * without the primitive as done at once, storing nothing.
     */
    String registered(Kind kind, Primitive primitive, Primitive countermeasure, String calleeClass,
            String receiverClass, String label, String callee, List<String> arguments, String store) {
        String helper = helper(kind, primitive, countermeasure, calleeClass, receiverClass,
                store == null ? Registration.LABEL : Registration.LABEL_STORING);
        List<String> all = new ArrayList<>();
        all.add("ctx");
        all.add(label);
        all.add(callee);
        all.addAll(arguments);
        if (store != null) {
            all.add(store);
        }
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
            String receiverClass, Registration registration) {
        String key = kind + " " + primitive.name() + " " + calleeClass + " " + receiverClass + " " + registration;
        String existing = names.get(key);
        if (existing != null) {
            return existing;
        }
        boolean labelled = registration != Registration.NONE;
        String prefix = labelled ? "label" + Character.toUpperCase(kind.prefix.charAt(0)) + kind.prefix.substring(1)
                : kind.prefix;
        String name = unique(prefix + "$" + primitive.name());
        names.put(key, name);
        boolean self = kind == Kind.INVOKE_SELF;
        boolean dispatches = !calleeClass.equals(receiverClass);
        String runtimeCall = runtimeCall(kind, primitive, countermeasure);
        String nop = "CompletableFuture.completedFuture(" + defaultValue(primitive.returnType()) + ")";
        if (labelled) {
            runtimeCall = "label.register(" + runtimeCall
                    + (registration == Registration.LABEL_STORING ? ", store)" : ")");
            nop = "label.register(" + nop + ")";
        }
        String type = self ? simple(primitive.returnType()) : futureType(primitive);
        List<String> lines = new ArrayList<>();
        lines.add("    /** " + describe(kind, primitive, countermeasure)
                + (labelled ? " Registered with a label (MASL 10); a nop() is done at once and stores nothing." : "")
                + " */");
        lines.add("    private " + (self ? "" : "static ") + type + " " + name + "("
                + String.join(", ", parameters(kind, primitive, calleeClass, receiverClass, registration)) + ") {");
        if (dispatches) {
            lines.addAll(dispatch(calleeClass, "callee", "return " + nop + ";", primitive.name()));
        }
        boolean isVoid = primitive.returnType().equals("void");
        lines.add("        " + (self && isVoid ? "" : "return ") + runtimeCall + ";");
        lines.add("    }");
        helpers.put(name, lines);
        return name;
    }

    /** A helper's parameters: the context, the label, the receiver, the primitive's arguments, the store. */
    private static List<String> parameters(Kind kind, Primitive primitive, String calleeClass, String receiverClass,
            Registration registration) {
        List<String> parameters = new ArrayList<>();
        parameters.add("AgentContext ctx");
        if (registration != Registration.NONE) {
            parameters.add("final Label label");
        }
        if (kind != Kind.INVOKE_SELF) {
            parameters.add("final " + (calleeClass.equals(receiverClass) ? calleeClass + " callee"
                    : receiverClass + " receiver"));
        }
        int i = 0;
        for (Parameter parameter : primitive.parameters()) {
            parameters.add("final " + simple(parameter.type()) + " " + argumentName(parameter, i++));
        }
        if (registration == Registration.LABEL_STORING) {
            parameters.add("final java.util.function.Consumer<? super " + simple(boxed(primitive.returnType()))
                    + "> store");
        }
        return parameters;
    }

    /** The runtime's call of {@code primitive} (contract §8.1) on {@code self} or {@code callee}, with its countermeasure. */
    private static String runtimeCall(Kind kind, Primitive primitive, Primitive countermeasure) {
        boolean self = kind == Kind.INVOKE_SELF;
        List<String> argumentNames = new ArrayList<>();
        for (int i = 0; i < primitive.parameters().size(); i++) {
            argumentNames.add(argumentName(primitive.parameters().get(i), i));
        }
        String run = callable((self ? "self" : "callee") + "." + primitive.name() + "("
                + String.join(", ", argumentNames) + ")", primitive.returnType().equals("void"));
        String call = "ctx." + kind.prefix + "(" + (self ? "" : "callee, ") + JavaText.quote(primitive.name())
                + ", " + defaultValue(primitive.returnType()) + ", " + run;
        if (kind == Kind.LAUNCH && countermeasure != null) {
            call += ", " + JavaText.quote(countermeasure.name()) + ", "
                    + callable("callee." + countermeasure.name() + "()", countermeasure.returnType().equals("void"));
        }
        return call + ")";
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

    /**
     * The lines that make a helper's {@code receiver} the {@code name} of class {@code declaringClass}
     * it needs, running {@code otherwise} (a nop, §4) for an agent of a type without {@code member}.
     * A null receiver goes on to the runtime, which raises {@code uncaught_exception} for it.
     */
    private static List<String> dispatch(String declaringClass, String name, String otherwise, String member) {
        return List.of(
                "        if (receiver != null && !(receiver instanceof " + declaringClass + ")) {",
                "            " + otherwise + " // a nop() for an agent whose type lacks " + member + " (MASL 4)",
                "        }",
                "        final " + declaringClass + " " + name + " = (" + declaringClass + ") receiver;");
    }

    /**
     * {@code read$x(ctx, owner)}: a read of attribute {@code attribute}, declared by
     * {@code ownerClass}, of an agent whose static class is {@code receiverClass}.
     */
    String read(Attribute attribute, String ownerClass, String receiverClass, String owner) {
        String key = "read " + attribute.name() + " " + ownerClass + " " + receiverClass;
        String name = names.get(key);
        if (name == null) {
            name = unique("read$" + attribute.name());
            names.put(key, name);
            boolean dispatches = !ownerClass.equals(receiverClass);
            String field = (attribute.isStatic() ? ownerClass : "owner") + "." + attribute.name();
            List<String> lines = new ArrayList<>();
            lines.add("    /** A read of attribute " + attribute.name() + ", filtered by permeability (MASL 9, 11). */");
            lines.add("    private static " + simple(attribute.type()) + " " + name + "(AgentContext ctx, final "
                    + (dispatches ? receiverClass + " receiver" : ownerClass + " owner") + ") {");
            if (dispatches) {
                lines.addAll(dispatch(ownerClass, "owner", "return " + defaultValue(attribute.type()) + ";",
                        attribute.name()));
            }
            lines.add("        return ctx.readAttribute(owner, " + JavaText.quote(attribute.name()) + ", "
                    + defaultValue(attribute.type()) + ", () -> " + field + ");");
            lines.add("    }");
            helpers.put(name, lines);
        }
        return name + "(ctx, " + owner + ")";
    }

    /** {@code write$x(ctx, owner, value)}: a write of attribute {@code attribute}, as {@link #read}. */
    String write(Attribute attribute, String ownerClass, String receiverClass, String owner, String value) {
        String key = "write " + attribute.name() + " " + ownerClass + " " + receiverClass;
        String name = names.get(key);
        if (name == null) {
            name = unique("write$" + attribute.name());
            names.put(key, name);
            boolean dispatches = !ownerClass.equals(receiverClass);
            String field = (attribute.isStatic() ? ownerClass : "owner") + "." + attribute.name();
            List<String> lines = new ArrayList<>();
            lines.add("    /** A write of attribute " + attribute.name() + ", filtered by permeability (MASL 9, 11). */");
            lines.add("    private static void " + name + "(AgentContext ctx, final "
                    + (dispatches ? receiverClass + " receiver" : ownerClass + " owner") + ", final "
                    + simple(attribute.type()) + " value) {");
            if (dispatches) {
                lines.addAll(dispatch(ownerClass, "owner", "return;", attribute.name()));
            }
            lines.add("        ctx.writeAttribute(owner, " + JavaText.quote(attribute.name()) + ", () -> " + field
                    + " = value);");
            lines.add("    }");
            helpers.put(name, lines);
        }
        return name + "(ctx, " + owner + ", " + value + ")";
    }

    /**
     * {@code store$x(owner)}: the consumer a label stores a result with into attribute
     * {@code attribute} (§10), declared by {@code ownerClass}, of an agent whose static class is
     * {@code receiverClass}: an {@code AttributeStore} naming the owner and the attribute, so that the
     * runtime writes it where the owner runs; one that does nothing for an agent without the attribute (§4).
     */
    String store(Attribute attribute, String ownerClass, String receiverClass, String owner) {
        String key = "store " + attribute.name() + " " + ownerClass + " " + receiverClass;
        String name = names.get(key);
        if (name == null) {
            name = unique("store$" + attribute.name());
            names.put(key, name);
            boolean dispatches = !ownerClass.equals(receiverClass);
            String field = (attribute.isStatic() ? ownerClass : "owner") + "." + attribute.name();
            List<String> lines = new ArrayList<>();
            lines.add("    /** Stores a label's result in attribute " + attribute.name() + " of owner (MASL 10). */");
            lines.add("    private static java.util.function.Consumer<" + simple(boxed(attribute.type())) + "> " + name
                    + "(final " + (dispatches ? receiverClass + " receiver" : ownerClass + " owner") + ") {");
            if (dispatches) {
                lines.addAll(dispatch(ownerClass, "owner", "return value -> { };", attribute.name()));
            }
            // Through the runtime, which writes where the owner's state is: another JVM's for a deployed agent.
            lines.add("        return new masl.runtime.AttributeStore<>(owner, " + JavaText.quote(attribute.name())
                    + ", value -> " + field + " = value);");
            lines.add("    }");
            helpers.put(name, lines);
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
        return HELPER_NAMES.contains(name) ? name + "_" + index : name;
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
