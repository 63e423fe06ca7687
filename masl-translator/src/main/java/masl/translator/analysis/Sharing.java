package masl.translator.analysis;

/** Whether a variable, event or label has one copy per member ({@code local}, {@code LLabel}) or per wave ({@code shared}, {@code SLabel}). */
public enum Sharing {
    LOCAL, SHARED
}
