package masl.translator.analysis;

import java.util.List;
import java.util.Optional;

/**
 * Java's typing rules, relaxed as MASL §3 says: an {@code Object} value may go anywhere (it is cast at
 * run time), and, where asked, anything may go where a {@code String} is expected (it is converted with
 * {@code String.valueOf}). {@link MaslType#ERROR} is compatible with everything, so that an error is
 * reported once.
 */
final class TypeRules {

    /** Numeric primitives from narrowest to widest; a type widens to any later one (char aside). */
    private static final List<Class<?>> WIDENING = List.of(byte.class, short.class, int.class, long.class,
            float.class, double.class);

    private TypeRules() {
    }

    static boolean isError(MaslType type) {
        return type == MaslType.ERROR;
    }

    /** Whether the type is only known at run time: an error already reported, or {@code Object}. */
    static boolean isOpen(MaslType type) {
        return isError(type) || MaslType.OBJECT.equals(type);
    }

    static boolean isString(MaslType type) {
        return MaslType.STRING.equals(type);
    }

    /** The primitive a type is or unboxes to. */
    static Optional<Class<?>> primitiveOf(MaslType type) {
        if (type instanceof MaslType.JavaPrimitive primitive && primitive.type() != void.class) {
            return Optional.of(primitive.type());
        }
        if (type instanceof MaslType.JavaClass javaClass) {
            for (Class<?> primitive : List.of(boolean.class, byte.class, char.class, short.class, int.class,
                    long.class, float.class, double.class)) {
                if (((MaslType.JavaPrimitive) MaslType.of(primitive)).boxed() == javaClass.type()) {
                    return Optional.of(primitive);
                }
            }
        }
        return Optional.empty();
    }

    static boolean isNumeric(MaslType type) {
        return primitiveOf(type).filter(primitive -> primitive != boolean.class).isPresent();
    }

    static boolean isIntegral(MaslType type) {
        return primitiveOf(type).filter(primitive -> primitive != boolean.class && primitive != float.class
                && primitive != double.class).isPresent();
    }

    static boolean isBoolean(MaslType type) {
        return primitiveOf(type).filter(primitive -> primitive == boolean.class).isPresent();
    }

    /** §3: a condition or an entry test may be boolean or numeric (non-zero is true). */
    static boolean isCondition(MaslType type) {
        return isOpen(type) || isBoolean(type) || isNumeric(type);
    }

    /** Unary numeric promotion: byte, short and char become int. */
    static MaslType promote(MaslType type) {
        Class<?> primitive = primitiveOf(type).orElse(int.class);
        return primitive == long.class || primitive == float.class || primitive == double.class
                ? MaslType.of(primitive) : MaslType.INT;
    }

    /** Binary numeric promotion. */
    static MaslType promote(MaslType left, MaslType right) {
        MaslType a = promote(left);
        MaslType b = promote(right);
        return rank(a) >= rank(b) ? a : b;
    }

    private static int rank(MaslType type) {
        return WIDENING.indexOf(primitiveOf(type).orElse(int.class));
    }

    /**
     * Whether a value of type {@code source} may be stored where {@code target} is expected.
     *
     * @param anythingToString whether any value converts to a {@code String} target (§3)
     */
    static boolean isAssignable(MaslType target, MaslType source, boolean anythingToString) {
        if (isError(target) || isError(source)) {
            return true;
        }
        if (MaslType.VOID.equals(source) || MaslType.VOID.equals(target)) {
            return false;
        }
        if (anythingToString && isString(target) || MaslType.OBJECT.equals(source)) {
            return true;
        }
        if (target instanceof MaslType.JavaPrimitive primitive) {
            return primitiveOf(source).filter(from -> widens(from, primitive.type())).isPresent();
        }
        if (source == MaslType.NULL) {
            return true;
        }
        if (MaslType.OBJECT.equals(target)) {
            return true;
        }
        if (source instanceof MaslType.JavaPrimitive primitive) {
            return target instanceof MaslType.JavaClass javaClass
                    && javaClass.type().isAssignableFrom(primitive.boxed());
        }
        if (target instanceof MaslType.JavaClass targetClass && source instanceof MaslType.JavaClass sourceClass) {
            return targetClass.type().isAssignableFrom(sourceClass.type());
        }
        if (target instanceof MaslType.AgentRef targetAgent && source instanceof MaslType.AgentRef sourceAgent) {
            // An agent of unknown type (an entry list element) is checked when assigned, at run time.
            return targetAgent.type() == null || sourceAgent.type() == null
                    || sourceAgent.type().isSubtypeOf(targetAgent.type());
        }
        if (target instanceof MaslType.ArrayOf targetArray && source instanceof MaslType.ArrayOf sourceArray) {
            if (targetArray.element() instanceof MaslType.JavaPrimitive
                    || sourceArray.element() instanceof MaslType.JavaPrimitive) {
                return targetArray.element().equals(sourceArray.element());
            }
            return isAssignable(targetArray.element(), sourceArray.element(), false);
        }
        return false;
    }

    /**
     * Primitive widening, and the narrowing of {@code int} to {@code byte}, {@code short} and {@code char}
     * that Java allows for constants: the analysis does not fold constants, the generated code casts.
     */
    private static boolean widens(Class<?> from, Class<?> to) {
        if (from == to) {
            return true;
        }
        if (from == boolean.class || to == boolean.class) {
            return false;
        }
        if (from == int.class && (to == byte.class || to == short.class || to == char.class)) {
            return true;
        }
        return isWidening(from, to);
    }

    /** Java's widening primitive conversion (JLS 5.1.2), identity included. */
    static boolean isWidening(Class<?> from, Class<?> to) {
        if (from == to) {
            return true;
        }
        if (from == boolean.class || to == boolean.class) {
            return false;
        }
        if (from == char.class) {
            return WIDENING.indexOf(to) >= WIDENING.indexOf(int.class);
        }
        return to != char.class && WIDENING.indexOf(from) < WIDENING.indexOf(to);
    }

    /** Whether {@code (target) value} can succeed for some value of type {@code source}. */
    static boolean isCastable(MaslType target, MaslType source) {
        boolean nullToReference = source == MaslType.NULL && !(target instanceof MaslType.JavaPrimitive);
        if (isOpen(source) || isError(target) || nullToReference) {
            return true;
        }
        if (isNumeric(target) && isNumeric(source) || isBoolean(target) && isBoolean(source)) {
            return true;
        }
        if (target instanceof MaslType.JavaPrimitive || source instanceof MaslType.JavaPrimitive) {
            return isAssignable(target, source, false);
        }
        return isAssignable(target, source, false) || isAssignable(source, target, false)
                || target instanceof MaslType.JavaClass targetClass && targetClass.type().isInterface()
                || source instanceof MaslType.JavaClass sourceClass && sourceClass.type().isInterface();
    }
}
