package masl.translator.analysis;

import java.lang.reflect.Executable;
import java.util.List;

/**
 * A member reached through a receiver or the current agent.
 *
 * @param kind what sort of member it is
 * @param name the member's name
 * @param declaringTypes for primitives and attributes: the imported types that have it (several when
 *        the call is polymorphic, MASL §4); empty otherwise
 * @param javaMember for Java methods and constructors: the one chosen by reflection, or null when it is
 *        resolved at run time (a receiver of static type {@code Object})
 */
public record Member(Kind kind, String name, List<ImportedType> declaringTypes, Executable javaMember)
        implements Symbol {

    public enum Kind {
        /** A primitive of an agent type (MASL §9). */
        PRIMITIVE,
        /** An attribute of an agent type. */
        ATTRIBUTE,
        /** {@code count}, {@code getList()}, {@code lock()}, … of an entry (§6.7). */
        ENTRY_MEMBER,
        /** {@code isFinished()}, {@code getRemainingInvocations()} or {@code free()} of a label (§10). */
        LABEL_MEMBER,
        /** A method of a Java object or class. */
        JAVA_METHOD,
        /** A field of a Java object or class, {@code length} of an array, or {@code X.class}. */
        JAVA_FIELD,
        /** A method or field of an {@code Object}-typed receiver: resolved at run time (§3). */
        DYNAMIC
    }

    public Member {
        declaringTypes = List.copyOf(declaringTypes);
    }
}
