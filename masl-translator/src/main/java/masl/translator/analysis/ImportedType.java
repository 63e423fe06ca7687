package masl.translator.analysis;

import masl.runtime.descriptor.AgentType;

/**
 * An agent type as the program names it (MASL §4): {@code import F as Name;} or {@code type Name use F;}.
 * Two {@code ImportedType}s may share a descriptor ({@code type OtherDefault use Default.xml;}) and are
 * still distinct types. {@code descriptor} is null when the descriptor could not be loaded: the name
 * stays known so that its uses raise no further error.
 *
 * @param name the MASL name
 * @param file the descriptor file as written in the program
 * @param descriptor the loaded type, or null when loading failed (already reported)
 * @param definedByType whether it comes from {@code type Name use F;}, which makes a type of its own
 */
public record ImportedType(String name, String file, AgentType descriptor, boolean definedByType) {

    public boolean isLoaded() {
        return descriptor != null;
    }

    /**
     * Whether agents of this type are agents of {@code other}. A type made by {@code type … use} exists
     * to be told apart: it has no subtypes, and it is no subtype of another name of its own
     * descriptor; it is still a subtype of the types its descriptor extends ({@code type Spare use
     * SoftWheeledRobot.xml;} makes robots: {@code Robot r = newAgent(Spare);} is fine).
     */
    public boolean isSubtypeOf(ImportedType other) {
        if (this.equals(other)) {
            return true;
        }
        if (!isLoaded() || !other.isLoaded() || other.definedByType) {
            return false;
        }
        if (definedByType && descriptor.fullClassName().equals(other.descriptor.fullClassName())) {
            return false;
        }
        return descriptor.isSubtypeOf(other.descriptor);
    }

    // Written out, as Variable's: a record's own equals and hashCode are slow in a fresh JVM's interpreter.
    @Override
    public boolean equals(Object o) {
        return o instanceof ImportedType t && name.equals(t.name) && file.equals(t.file) && descriptor == t.descriptor
                && definedByType == t.definedByType;
    }

    @Override
    public int hashCode() {
        return name.hashCode() * 31 + file.hashCode();
    }
}
