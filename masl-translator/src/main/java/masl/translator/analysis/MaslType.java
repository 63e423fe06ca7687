package masl.translator.analysis;

import java.util.Map;
import java.util.Objects;
import masl.runtime.AgentImplementation;

/**
 * The static type of a MASL expression or variable: Java's types plus agent types. {@link #ERROR}
 * is the type of an expression already reported as wrong; every rule accepts it, so one mistake
 * yields one error. {@link #NULL} is the type of the literal {@code null}.
 */
// The records below but JavaPrimitive write out equals and hashCode, as Variable does: the translator
// compares types at every expression, and a record's own go through method handles, slow in a fresh
// JVM's interpreter.
public sealed interface MaslType {

    MaslType BOOLEAN = new JavaPrimitive(boolean.class);
    MaslType BYTE = new JavaPrimitive(byte.class);
    MaslType CHAR = new JavaPrimitive(char.class);
    MaslType SHORT = new JavaPrimitive(short.class);
    MaslType INT = new JavaPrimitive(int.class);
    MaslType LONG = new JavaPrimitive(long.class);
    MaslType FLOAT = new JavaPrimitive(float.class);
    MaslType DOUBLE = new JavaPrimitive(double.class);
    MaslType VOID = new JavaPrimitive(void.class);
    MaslType STRING = new JavaClass(String.class);
    MaslType OBJECT = new JavaClass(Object.class);
    MaslType NULL = Special.NULL;
    MaslType ERROR = Special.ERROR;
    /** What {@code this} and the elements of an entry list are: an agent of any imported type. */
    MaslType ANY_AGENT = new AgentRef(null);

    /** The type as a user writes it, for messages: {@code int}, {@code String}, {@code Khepera[]}. */
    String describe();

    /**
     * The type in Java source: {@code int}, {@code java.lang.String}, {@code java.util.Map.Entry[]}; an agent
     * type is its implementation class (the root type's for any agent, {@code Object} when its descriptor
     * could not be loaded). {@code Object} for {@link #NULL} and {@link #ERROR}.
     */
    String javaName();

    /** The Java type of a class object, primitives included. */
    static MaslType of(Class<?> type) {
        if (type.isArray()) {
            return new ArrayOf(of(type.getComponentType()));
        }
        return type.isPrimitive() ? new JavaPrimitive(type) : new JavaClass(type);
    }

    /** A primitive Java type ({@code int}, {@code boolean}, …) or {@code void}. */
    record JavaPrimitive(Class<?> type) implements MaslType {
        private static final Map<Class<?>, Class<?>> BOXES = Map.of(boolean.class, Boolean.class,
                byte.class, Byte.class, char.class, Character.class, short.class, Short.class,
                int.class, Integer.class, long.class, Long.class, float.class, Float.class,
                double.class, Double.class, void.class, Void.class);

        public Class<?> boxed() {
            return BOXES.get(type);
        }

        @Override
        public String describe() {
            return type.getName();
        }

        @Override
        public String javaName() {
            return type.getName();
        }
    }

    /** A Java class or interface, found by reflection ({@code String}, {@code java.util.Vector}, …). */
    record JavaClass(Class<?> type) implements MaslType {
        @Override
        public boolean equals(Object o) {
            return o instanceof JavaClass c && type == c.type;
        }

        @Override
        public int hashCode() {
            return type.hashCode();
        }

        @Override
        public String describe() {
            String name = type.getName();
            return name.startsWith("java.lang.") && name.indexOf('.', 10) < 0 ? type.getSimpleName() : name;
        }

        @Override
        public String javaName() {
            return type.getCanonicalName() != null ? type.getCanonicalName() : type.getName();
        }
    }

    /** An agent of an imported type (or of its subtypes); {@code type} is null for any agent. */
    record AgentRef(ImportedType type) implements MaslType {
        @Override
        public boolean equals(Object o) {
            return o instanceof AgentRef a && Objects.equals(type, a.type);
        }

        @Override
        public int hashCode() {
            return Objects.hashCode(type);
        }

        @Override
        public String describe() {
            return type == null ? "agent" : type.name();
        }

        @Override
        public String javaName() {
            if (type == null) {
                // Any agent, of whatever root: a user's own Default.xml may name a class of its own.
                return AgentImplementation.class.getName();
            }
            return type.isLoaded() ? type.descriptor().fullClassName() : Object.class.getName();
        }
    }

    record ArrayOf(MaslType element) implements MaslType {
        @Override
        public boolean equals(Object o) {
            return o instanceof ArrayOf a && element.equals(a.element);
        }

        @Override
        public int hashCode() {
            return element.hashCode() * 31 + 1;
        }

        @Override
        public String describe() {
            return element.describe() + "[]";
        }

        @Override
        public String javaName() {
            return element.javaName() + "[]";
        }
    }

    enum Special implements MaslType {
        NULL, ERROR;

        @Override
        public String describe() {
            return this == NULL ? "null" : "<error>";
        }

        @Override
        public String javaName() {
            return Object.class.getName();
        }
    }
}
