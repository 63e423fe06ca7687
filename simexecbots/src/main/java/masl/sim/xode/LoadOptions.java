package masl.sim.xode;

/**
 * Choices a caller makes about a load.
 *
 * @param strict turn every warning (unknown element or attribute, ignored scale, skipped cone,
 *               other version, duplicate name…) into an error
 * @param euler  the Euler-angle convention
 */
public record LoadOptions(boolean strict, EulerConvention euler) {

    /** Lenient (warnings are kept in the model), odejava's Euler convention. */
    public static LoadOptions defaults() {
        return new LoadOptions(false, EulerConvention.XYZ);
    }

    /** Like {@link #defaults()} but every warning is an error. */
    public static LoadOptions strictMode() {
        return new LoadOptions(true, EulerConvention.XYZ);
    }

    public LoadOptions withEuler(EulerConvention convention) {
        return new LoadOptions(strict, convention);
    }
}
