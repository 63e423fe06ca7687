package masl.translator.parse;

import java.math.BigInteger;
import java.util.Locale;

/**
 * The values of MASL's number literals, which are Java's (JLS 3.10.1, 3.10.2): decimal, octal
 * (a leading {@code 0}), hexadecimal and binary integers with underscores and an {@code L} suffix,
 * and floating-point numbers. Java's limits on them are checked before the generated Java reaches
 * javac, which would otherwise refuse it.
 */
public final class NumberLiterals {

    private NumberLiterals() {
    }

    /**
     * Why Java refuses the integer literal {@code text}, or null if it accepts it.
     *
     * @param negated whether the literal is the operand of a unary minus: only there may a decimal
     *     literal be one more than the largest value ({@code -2147483648})
     */
    public static String integerProblem(String text, boolean negated) {
        if (isShortDecimal(text)) {
            return null;
        }
        boolean isLong = isLong(text);
        String digits = digits(text);
        int radix = radix(digits);
        if (radix == 8 && !digits.chars().allMatch(c -> c >= '0' && c <= '7')) {
            return text + " is not a number: one that starts with 0 is octal, with the digits 0 to 7";
        }
        BigInteger value = integer(text);
        int bits = isLong ? 64 : 32;
        String type = isLong ? "a long" : "an int";
        if (radix == 10) {
            BigInteger largest = BigInteger.ONE.shiftLeft(bits - 1).subtract(BigInteger.ONE);
            boolean fits = value.compareTo(largest) <= 0 || negated && value.equals(largest.add(BigInteger.ONE));
            if (!fits) {
                return "integer number too large for " + type + ": at most " + largest
                        + (isLong ? "" : "; write " + text + "L for a long");
            }
        } else if (value.bitLength() > bits) {
            return "integer number too large for " + type + ": at most " + bits + " bits"
                    + (isLong ? "" : "; write " + text + "L for a long");
        }
        return null;
    }

    /** Why Java refuses the floating-point literal {@code text}, or null if it accepts it. */
    public static String floatingProblem(String text) {
        String number = text.replace("_", "");
        boolean isFloat = number.endsWith("f") || number.endsWith("F");
        double value = isFloat ? Float.parseFloat(number) : Double.parseDouble(number);
        String type = isFloat ? "a float" : "a double";
        if (Double.isInfinite(value)) {
            return "floating-point number too large for " + type;
        }
        if (value == 0 && hasNonZeroDigit(number)) {
            return "floating-point number too small for " + type + ": it would be 0";
        }
        return null;
    }

    /** The value of an integer literal Java accepts, or of one with too many digits. */
    public static BigInteger integer(String text) {
        String digits = digits(text);
        int radix = radix(digits);
        String significant = radix == 16 || radix == 2 ? digits.substring(2) : digits;
        return new BigInteger(significant, radix);
    }

    /**
     * A count written as an integer literal ({@code break(2)}, {@code exit(0x1)}): its value, or
     * {@link Integer#MAX_VALUE} for one larger than an int, which exceeds any nesting.
     */
    public static int count(String text) {
        if (radix(digits(text)) == 8 && integerProblem(text, false) != null) {
            return Integer.MAX_VALUE;
        }
        BigInteger value = integer(text);
        return value.bitLength() < 32 ? value.intValue() : Integer.MAX_VALUE;
    }

    /** Up to nine decimal digits, not octal: most literals, and always an int; no need to compute their value. */
    private static boolean isShortDecimal(String text) {
        if (text.length() > 9 || text.length() > 1 && text.charAt(0) == '0') {
            return false;
        }
        for (int i = 0; i < text.length(); i++) {
            if (text.charAt(i) < '0' || text.charAt(i) > '9') {
                return false;
            }
        }
        return true;
    }

    private static boolean isLong(String text) {
        return text.endsWith("l") || text.endsWith("L");
    }

    private static String digits(String text) {
        String digits = text.replace("_", "");
        return isLong(digits) ? digits.substring(0, digits.length() - 1) : digits;
    }

    private static int radix(String digits) {
        String lower = digits.toLowerCase(Locale.ROOT);
        if (lower.startsWith("0x")) {
            return 16;
        }
        if (lower.startsWith("0b")) {
            return 2;
        }
        return lower.length() > 1 && lower.startsWith("0") ? 8 : 10;
    }

    /** Whether the significand (the digits before any exponent) is not zero. */
    private static boolean hasNonZeroDigit(String number) {
        for (int i = 0; i < number.length(); i++) {
            char c = number.charAt(i);
            if (c == 'e' || c == 'E') {
                return false;
            }
            if (c >= '1' && c <= '9') {
                return true;
            }
        }
        return false;
    }
}
