package masl.translator.generate;

import masl.translator.analysis.MaslType;

/** Java spellings of MASL types in generated code. */
final class JavaTypes {

    private JavaTypes() {
    }

    /** The type as a field's or a cast's type; {@code java.lang} classes by their simple name. */
    static String name(MaslType type) {
        String name = type.javaName();
        if (name.startsWith("java.lang.") && name.indexOf('.', "java.lang.".length()) < 0) {
            return name.substring("java.lang.".length());
        }
        return name;
    }

    /** The boxed type, the type parameter of a shared variable. */
    static String boxed(MaslType type) {
        if (type instanceof MaslType.JavaPrimitive primitive) {
            return primitive.boxed().getSimpleName();
        }
        return name(type);
    }

    static boolean isPrimitive(MaslType type) {
        return type instanceof MaslType.JavaPrimitive;
    }

    static boolean isPrimitive(MaslType type, Class<?> which) {
        return type instanceof MaslType.JavaPrimitive primitive && primitive.type() == which;
    }

    /** Whether a value of this type is a number (a primitive or a boxed one), chars included. */
    static boolean isNumeric(MaslType type) {
        Class<?> c = unboxed(type);
        return c != null && c != boolean.class && c != void.class;
    }

    static boolean isBoolean(MaslType type) {
        return unboxed(type) == boolean.class;
    }

    /** The primitive class of a primitive or boxed type, null otherwise. */
    static Class<?> unboxed(MaslType type) {
        if (type instanceof MaslType.JavaPrimitive primitive) {
            return primitive.type();
        }
        if (type instanceof MaslType.JavaClass javaClass) {
            Class<?> c = javaClass.type();
            if (c == Integer.class) {
                return int.class;
            } else if (c == Long.class) {
                return long.class;
            } else if (c == Double.class) {
                return double.class;
            } else if (c == Float.class) {
                return float.class;
            } else if (c == Short.class) {
                return short.class;
            } else if (c == Byte.class) {
                return byte.class;
            } else if (c == Character.class) {
                return char.class;
            } else if (c == Boolean.class) {
                return boolean.class;
            }
        }
        return null;
    }

    /** The default value of the type (MASL §7), as an expression of the boxed type. */
    static String defaultValue(MaslType type) {
        if (!(type instanceof MaslType.JavaPrimitive primitive)) {
            return "null";
        }
        Class<?> c = primitive.type();
        if (c == boolean.class) {
            return "false";
        } else if (c == long.class) {
            return "0L";
        } else if (c == float.class) {
            return "0f";
        } else if (c == double.class) {
            return "0d";
        } else if (c == int.class) {
            return "0";
        }
        return "(" + c.getName() + ") 0";
    }

    /** Rank of a numeric primitive in Java's promotions: the result of {@code a op b} has the larger rank. */
    static int rank(Class<?> c) {
        if (c == double.class) {
            return 4;
        } else if (c == float.class) {
            return 3;
        } else if (c == long.class) {
            return 2;
        }
        return 1;
    }
}
