package masl.translator.analysis;

/**
 * Whether a variable, event or label has one copy per member ({@code local}, {@code LLabel}) or one per
 * wave of its block ({@code shared}, {@code SLabel}).
 */
public enum Sharing {
    LOCAL, SHARED
}
