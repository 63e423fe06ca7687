package masl.translator.generate;

import java.util.List;

/**
 * The helper methods a program class gets when it uses members of {@code Object}-typed values
 * (MASL §3: typed at run time): a method or field is looked up by name on the value's class when
 * the statement runs. A failure raises {@code uncaught_exception} (§8) and the value is {@code null}.
 */
final class DynamicMembers {

    private DynamicMembers() {
    }

    static String call(String receiver, String name, List<String> arguments) {
        StringBuilder call = new StringBuilder("dynamic$call(ctx, ").append(receiver).append(", ")
                .append(JavaText.quote(name));
        for (String argument : arguments) {
            call.append(", ").append(argument);
        }
        return call.append(")").toString();
    }

    static String field(String receiver, String name) {
        return "dynamic$field(ctx, " + receiver + ", " + JavaText.quote(name) + ")";
    }

    /** The helpers' source, indented as members of the program class. */
    static List<String> helpers() {
        return List.of(
                "    /** A method of an Object-typed value, found at run time (MASL 3); null if it fails. */",
                "    private static Object dynamic$call(AgentContext ctx, Object receiver, String name, Object... arguments) {",
                "        if (receiver == null) {",
                "            ctx.uncaughtException(new NullPointerException(name + \" called on null\"));",
                "            return null;",
                "        }",
                "        for (java.lang.reflect.Method method : receiver.getClass().getMethods()) {",
                "            if (method.getName().equals(name) && accepts(method.getParameterTypes(), arguments)) {",
                "                try {",
                "                    return publicDeclaration(method, receiver.getClass()).invoke(receiver, arguments);",
                "                } catch (java.lang.reflect.InvocationTargetException thrown) {",
                "                    ctx.uncaughtException(thrown.getCause());",
                "                    return null;",
                "                } catch (ReflectiveOperationException | RuntimeException failed) {",
                "                    ctx.uncaughtException(failed);",
                "                    return null;",
                "                }",
                "            }",
                "        }",
                "        ctx.uncaughtException(new NoSuchMethodException(receiver.getClass().getName() + \".\" + name));",
                "        return null;",
                "    }",
                "",
                "    /** A field of an Object-typed value, found at run time (MASL 3); null if there is none. */",
                "    private static Object dynamic$field(AgentContext ctx, Object receiver, String name) {",
                "        if (receiver == null) {",
                "            ctx.uncaughtException(new NullPointerException(name + \" read on null\"));",
                "            return null;",
                "        }",
                "        if (receiver.getClass().isArray() && name.equals(\"length\")) {",
                "            return java.lang.reflect.Array.getLength(receiver);",
                "        }",
                "        try {",
                "            return receiver.getClass().getField(name).get(receiver);",
                "        } catch (ReflectiveOperationException | RuntimeException failed) {",
                "            ctx.uncaughtException(failed);",
                "            return null;",
                "        }",
                "    }",
                "",
                "    private static boolean accepts(Class<?>[] parameters, Object[] arguments) {",
                "        if (parameters.length != arguments.length) {",
                "            return false;",
                "        }",
                "        for (int i = 0; i < parameters.length; i++) {",
                "            Class<?> parameter = java.lang.invoke.MethodType.methodType(parameters[i]).wrap().returnType();",
                "            if (arguments[i] != null ? !parameter.isInstance(arguments[i]) : parameters[i].isPrimitive()) {",
                "                return false;",
                "            }",
                "        }",
                "        return true;",
                "    }",
                "",
                "    /** The method as a public class or interface declares it: the value's own class may be hidden. */",
                "    private static java.lang.reflect.Method publicDeclaration(java.lang.reflect.Method method, Class<?> type) {",
                "        if (java.lang.reflect.Modifier.isPublic(method.getDeclaringClass().getModifiers())",
                "                && method.getDeclaringClass().getModule().isExported(",
                "                        method.getDeclaringClass().getPackageName())) {",
                "            return method;",
                "        }",
                "        for (Class<?> c = type; c != null; c = c.getSuperclass()) {",
                "            for (Class<?> candidate : candidates(c)) {",
                "                try {",
                "                    java.lang.reflect.Method declared = candidate.getMethod(method.getName(),",
                "                            method.getParameterTypes());",
                "                    if (java.lang.reflect.Modifier.isPublic(declared.getDeclaringClass().getModifiers())) {",
                "                        return declared;",
                "                    }",
                "                } catch (NoSuchMethodException notHere) {",
                "                    continue;",
                "                }",
                "            }",
                "        }",
                "        return method;",
                "    }",
                "",
                "    private static java.util.List<Class<?>> candidates(Class<?> type) {",
                "        java.util.List<Class<?>> all = new java.util.ArrayList<>();",
                "        if (java.lang.reflect.Modifier.isPublic(type.getModifiers())) {",
                "            all.add(type);",
                "        }",
                "        for (Class<?> implemented : type.getInterfaces()) {",
                "            all.add(implemented);",
                "            all.addAll(candidates(implemented));",
                "        }",
                "        return all;",
                "    }");
    }
}
