package masl.translator.analysis;

import java.lang.reflect.Constructor;
import java.lang.reflect.Executable;
import java.lang.reflect.Field;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Optional;
import java.util.stream.Stream;

/**
 * Finds the public methods, constructors and fields of Java classes by reflection and chooses among
 * overloads as Java does (the most specific applicable one), with MASL's relaxation that an
 * {@code Object}-typed argument fits any parameter (it is cast at run time).
 */
final class JavaMembers {

    /** The outcome of looking up a method or constructor. */
    sealed interface Lookup {
        /** One applicable member, the most specific. */
        record Found(Executable member) implements Lookup { }

        /** Members of that name exist but none accepts the arguments. */
        record NotApplicable() implements Lookup { }

        /** No member of that name. */
        record Missing() implements Lookup { }
    }

    private JavaMembers() {
    }

    static Lookup method(Class<?> owner, String name, List<MaslType> arguments, boolean staticOnly) {
        List<Method> named = Stream.concat(Arrays.stream(owner.getMethods()),
                        owner.isInterface() ? Arrays.stream(Object.class.getMethods()) : Stream.empty())
                .filter(method -> method.getName().equals(name))
                .filter(method -> !staticOnly || Modifier.isStatic(method.getModifiers()))
                .toList();
        return choose(named, arguments);
    }

    static Lookup constructor(Class<?> owner, List<MaslType> arguments) {
        return choose(List.of(owner.getConstructors()), arguments);
    }

    static Optional<Field> field(Class<?> owner, String name, boolean staticOnly) {
        try {
            Field field = owner.getField(name);
            return staticOnly && !Modifier.isStatic(field.getModifiers()) ? Optional.empty() : Optional.of(field);
        } catch (NoSuchFieldException absent) {
            return Optional.empty();
        }
    }

    /** The result type of a method; a generic result is erased, hence {@code Object} and typed at run time. */
    static MaslType resultOf(Executable member) {
        if (member instanceof Constructor<?> constructor) {
            return MaslType.of(constructor.getDeclaringClass());
        }
        return MaslType.of(((Method) member).getReturnType());
    }

    private static Lookup choose(List<? extends Executable> named, List<MaslType> arguments) {
        if (named.isEmpty()) {
            return new Lookup.Missing();
        }
        List<Executable> applicable = new ArrayList<>();
        for (Executable candidate : named) {
            if (accepts(candidate, arguments)) {
                applicable.add(candidate);
            }
        }
        if (applicable.isEmpty()) {
            return new Lookup.NotApplicable();
        }
        return new Lookup.Found(mostSpecific(applicable, arguments));
    }

    private static boolean accepts(Executable candidate, List<MaslType> arguments) {
        Class<?>[] parameters = candidate.getParameterTypes();
        if (parameters.length == arguments.size() && allAccepted(parameters, arguments, parameters.length)) {
            return true;
        }
        if (!candidate.isVarArgs() || arguments.size() < parameters.length - 1) {
            return false;
        }
        int fixed = parameters.length - 1;
        MaslType element = MaslType.of(parameters[fixed].getComponentType());
        return allAccepted(parameters, arguments, fixed) && arguments.subList(fixed, arguments.size()).stream()
                .allMatch(argument -> TypeRules.isAssignable(element, argument, false));
    }

    private static boolean allAccepted(Class<?>[] parameters, List<MaslType> arguments, int count) {
        for (int i = 0; i < count; i++) {
            if (!TypeRules.isAssignable(MaslType.of(parameters[i]), arguments.get(i), false)) {
                return false;
            }
        }
        return true;
    }

    /**
     * Java's rule: prefer the members that need no boxing (Java's first phase), then the one whose
     * parameters all fit every other's; the first one when none does.
     */
    private static Executable mostSpecific(List<Executable> applicable, List<MaslType> arguments) {
        List<Executable> withoutBoxing = applicable.stream()
                .filter(candidate -> needsNoBoxing(candidate.getParameterTypes(), arguments))
                .toList();
        List<Executable> candidates = withoutBoxing.isEmpty() ? applicable : withoutBoxing;
        for (Executable candidate : candidates) {
            boolean fitsAll = candidates.stream().allMatch(other -> other == candidate
                    || fits(candidate.getParameterTypes(), other.getParameterTypes()));
            if (fitsAll) {
                return candidate;
            }
        }
        return candidates.get(0);
    }

    private static boolean needsNoBoxing(Class<?>[] parameters, List<MaslType> arguments) {
        for (int i = 0; i < Math.min(parameters.length, arguments.size()); i++) {
            MaslType argument = arguments.get(i);
            boolean primitiveArgument = argument instanceof MaslType.JavaPrimitive;
            boolean boxes = primitiveArgument != parameters[i].isPrimitive();
            if (!TypeRules.isOpen(argument) && argument != MaslType.NULL && boxes) {
                return false;
            }
        }
        return true;
    }

    /** Whether every parameter of {@code narrower} converts to the one of {@code wider} without boxing. */
    private static boolean fits(Class<?>[] narrower, Class<?>[] wider) {
        if (narrower.length != wider.length) {
            return false;
        }
        for (int i = 0; i < narrower.length; i++) {
            boolean fitsHere = narrower[i] == wider[i]
                    || narrower[i].isPrimitive() && wider[i].isPrimitive()
                            && TypeRules.isWidening(narrower[i], wider[i])
                    || !narrower[i].isPrimitive() && !wider[i].isPrimitive() && wider[i].isAssignableFrom(narrower[i]);
            if (!fitsHere) {
                return false;
            }
        }
        return true;
    }
}
