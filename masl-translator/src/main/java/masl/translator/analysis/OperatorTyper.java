package masl.translator.analysis;

import java.util.Optional;
import java.util.function.Predicate;

/**
 * The result types of Java's operators on MASL types, relaxed as MASL §3 says: {@code !}, {@code &&} and
 * {@code ||} accept numbers (non-zero is true), {@code ==}/{@code !=}/{@code <>} compare any two values
 * (objects by value), and an operand typed only at run time ({@code Object}) is accepted. Empty means the
 * operands do not fit the operator.
 */
final class OperatorTyper {

    private OperatorTyper() {
    }

    static Optional<MaslType> binary(String operator, MaslType left, MaslType right) {
        if (TypeRules.isError(left) || TypeRules.isError(right)) {
            return Optional.of(isComparison(operator) ? MaslType.BOOLEAN : MaslType.ERROR);
        }
        if (MaslType.VOID.equals(left) || MaslType.VOID.equals(right)) {
            return Optional.empty();
        }
        return switch (operator) {
            case "+" -> plus(left, right);
            case "-", "*", "/", "%" -> arithmetic(left, right);
            case "<", ">", "<=", ">=" -> bothFit(left, right, TypeRules::isNumeric) ? Optional.of(MaslType.BOOLEAN)
                    : Optional.empty();
            case "==", "!=", "<>" -> equality(left, right);
            case "&", "|", "^" -> bitwise(left, right);
            case "&&", "||" -> bothFit(left, right, TypeRules::isCondition) ? Optional.of(MaslType.BOOLEAN)
                    : Optional.empty();
            case "<<", ">>", ">>>" -> shift(left, right);
            default -> Optional.empty();
        };
    }

    /** {@code x op= y} is {@code x = (T) (x op y)}: valid when {@code x op y} is. */
    static boolean compound(String assignOperator, MaslType target, MaslType value) {
        String operator = assignOperator.substring(0, assignOperator.length() - 1);
        if (operator.equals("+") && TypeRules.isString(target)) {
            return true;
        }
        Optional<MaslType> result = binary(operator, target, value);
        return result.isPresent() && !TypeRules.isString(result.get());
    }

    /** Unary {@code +}, {@code -}, {@code ~}, {@code !}. */
    static Optional<MaslType> unary(String operator, MaslType operand) {
        if (TypeRules.isError(operand)) {
            return Optional.of(operator.equals("!") ? MaslType.BOOLEAN : MaslType.ERROR);
        }
        if (TypeRules.isOpen(operand)) {
            return Optional.of(operator.equals("!") ? MaslType.BOOLEAN : MaslType.OBJECT);
        }
        return switch (operator) {
            case "+", "-" -> TypeRules.isNumeric(operand) ? Optional.of(TypeRules.promote(operand)) : Optional.empty();
            case "~" -> TypeRules.isIntegral(operand) ? Optional.of(TypeRules.promote(operand)) : Optional.empty();
            case "!" -> TypeRules.isCondition(operand) ? Optional.of(MaslType.BOOLEAN) : Optional.empty();
            default -> Optional.empty();
        };
    }

    private static boolean isComparison(String operator) {
        return switch (operator) {
            case "<", ">", "<=", ">=", "==", "!=", "<>", "&&", "||" -> true;
            default -> false;
        };
    }

    private static Optional<MaslType> plus(MaslType left, MaslType right) {
        if (TypeRules.isString(left) || TypeRules.isString(right)) {
            return Optional.of(MaslType.STRING);
        }
        return arithmetic(left, right);
    }

    private static Optional<MaslType> arithmetic(MaslType left, MaslType right) {
        if (!bothFit(left, right, TypeRules::isNumeric)) {
            return Optional.empty();
        }
        return Optional.of(TypeRules.isOpen(left) || TypeRules.isOpen(right) ? MaslType.OBJECT
                : TypeRules.promote(left, right));
    }

    /** Any two values compare, but a boolean with a number is surely a mistake. */
    private static Optional<MaslType> equality(MaslType left, MaslType right) {
        boolean mixed = TypeRules.isBoolean(left) && TypeRules.isNumeric(right)
                || TypeRules.isNumeric(left) && TypeRules.isBoolean(right);
        return mixed ? Optional.empty() : Optional.of(MaslType.BOOLEAN);
    }

    private static Optional<MaslType> bitwise(MaslType left, MaslType right) {
        if (bothFit(left, right, TypeRules::isBoolean)) {
            return Optional.of(MaslType.BOOLEAN);
        }
        if (bothFit(left, right, TypeRules::isIntegral)) {
            return Optional.of(TypeRules.isOpen(left) || TypeRules.isOpen(right) ? MaslType.OBJECT
                    : TypeRules.promote(left, right));
        }
        return Optional.empty();
    }

    private static Optional<MaslType> shift(MaslType left, MaslType right) {
        if (!bothFit(left, right, TypeRules::isIntegral)) {
            return Optional.empty();
        }
        return Optional.of(TypeRules.isOpen(left) ? MaslType.OBJECT : TypeRules.promote(left));
    }

    private static boolean bothFit(MaslType left, MaslType right, Predicate<MaslType> rule) {
        return (TypeRules.isOpen(left) || rule.test(left)) && (TypeRules.isOpen(right) || rule.test(right));
    }
}
