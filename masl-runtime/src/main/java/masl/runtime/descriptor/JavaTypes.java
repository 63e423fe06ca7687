package masl.runtime.descriptor;

import java.lang.reflect.Array;
import java.util.Map;
import java.util.Optional;

/** Java type names as descriptors write them ({@code int.class}, {@code int[]}, class names). */
final class JavaTypes {

    private static final Map<String, Class<?>> PRIMITIVES = Map.of(
            "void", void.class, "boolean", boolean.class, "byte", byte.class, "char", char.class,
            "short", short.class, "int", int.class, "long", long.class, "float", float.class,
            "double", double.class);

    private JavaTypes() {
    }

    /**
     * The name without the {@code .class} that old descriptors append: {@code int.class} is {@code int},
     * {@code java.lang.String.class} is {@code java.lang.String}, {@code int.class[]} is {@code int[]}.
     */
    static String normalise(String written) {
        String name = written.strip();
        int arrayStart = name.indexOf('[');
        String dimensions = arrayStart < 0 ? "" : name.substring(arrayStart).replaceAll("\\s", "");
        String element = arrayStart < 0 ? name : name.substring(0, arrayStart).strip();
        if (element.endsWith(".class")) {
            element = element.substring(0, element.length() - ".class".length());
        }
        return element + dimensions;
    }

    /** The class of a normalised type name, loaded (not initialised) through {@code loader}; empty when absent. */
    static Optional<Class<?>> resolve(String normalised, ClassLoader loader) {
        int dimensions = 0;
        String element = normalised;
        while (element.endsWith("[]")) {
            element = element.substring(0, element.length() - 2);
            dimensions++;
        }
        Class<?> type = PRIMITIVES.get(element);
        if (type == null) {
            try {
                type = Class.forName(element, false, loader);
            } catch (ClassNotFoundException | LinkageError e) {
                return Optional.empty();
            }
        }
        if (type == void.class && dimensions > 0) {
            return Optional.empty();
        }
        for (int i = 0; i < dimensions; i++) {
            type = Array.newInstance(type, 0).getClass();
        }
        return Optional.of(type);
    }
}
