package masl.translator.generate;

import java.util.HashSet;
import java.util.Locale;
import java.util.Set;

/** How MASL names become Java names in generated code. */
final class JavaNames {

    private static final Set<String> JAVA_KEYWORDS = Set.of("abstract", "assert", "boolean", "break", "byte", "case",
            "catch", "char", "class", "const", "continue", "default", "do", "double", "else", "enum", "extends",
            "final", "finally", "float", "for", "goto", "if", "implements", "import", "instanceof", "int",
            "interface", "long", "native", "new", "package", "private", "protected", "public", "return", "short",
            "static", "strictfp", "super", "switch", "synchronized", "this", "throw", "throws", "transient", "try",
            "void", "volatile", "while", "true", "false", "null", "var", "record", "yield", "sealed", "permits",
            "_");

    /**
     * The simple names the generated classes import or declare besides their own ({@code
     * masl.runtime.AgentProgram}, {@code java.net.URI}, the mission's {@code Types}, ...): a class
     * or constant made from a MASL name must not hide one of them ({@code type Agent} would make a
     * program class {@code AgentProgram}).
     */
    static final String[] GENERATED_CODE_NAMES = {"AgentContext", "AgentImplementation", "AgentProgram", "Event",
        "Label", "Reaction", "Objects", "CompletableFuture", "URI", "ArrayList", "List", "ESequence",
        "EntryDefinition", "Mission", "MissionProgram", "Mode", "SharedDeclaration", "AgentPath", "AgentType",
        "DescriptorException", "DescriptorLoader", "DescriptorSource", "Types", "AgentSpec",
        "ImplementationFactory", "AGENTS", "LOADER"};

    private JavaNames() {
    }

    /**
     * The package-name part for a program file: its base name without extension, lower-case, with
     * every character a Java identifier cannot hold turned into {@code _} ({@code hello.masl} → {@code hello}).
     */
    static String missionId(String fileName) {
        String base = fileName.replace('\\', '/');
        base = base.substring(base.lastIndexOf('/') + 1);
        int dot = base.lastIndexOf('.');
        if (dot > 0) {
            base = base.substring(0, dot);
        }
        StringBuilder id = new StringBuilder();
        for (char c : base.toLowerCase(Locale.ROOT).toCharArray()) {
            id.append(c < 128 && Character.isJavaIdentifierPart(c) && c != '$' ? c : '_');
        }
        if (id.length() == 0 || !Character.isJavaIdentifierStart(id.charAt(0))) {
            id.insert(0, '_');
        }
        return JAVA_KEYWORDS.contains(id.toString()) ? id + "_" : id.toString();
    }

    /** The mission class's simple name: {@code hello} → {@code HelloMission}, {@code my_run} → {@code MyRunMission}. */
    static String missionClass(String missionId) {
        return camel(missionId) + "Mission";
    }

    /** The program class of an agent type: {@code Khepera} → {@code KheperaProgram}. */
    static String programClass(String typeName) {
        return camel(typeName) + "Program";
    }

    private static String camel(String name) {
        StringBuilder out = new StringBuilder();
        boolean upper = true;
        for (char c : name.toCharArray()) {
            if (c == '_' || c == '$') {
                upper = true;
            } else if (c < 128 && Character.isJavaIdentifierPart(c)) {
                out.append(upper ? Character.toUpperCase(c) : c);
                upper = false;
            } else {
                upper = true;
            }
        }
        return out.length() == 0 || !Character.isJavaIdentifierStart(out.charAt(0)) ? "M" + out : out.toString();
    }

    /** {@code myBlock} → {@code MY_BLOCK}: the spelling of a constant. */
    static String constant(String name) {
        StringBuilder out = new StringBuilder();
        char previous = 0;
        for (char c : name.toCharArray()) {
            if (Character.isUpperCase(c) && Character.isLowerCase(previous)) {
                out.append('_');
            }
            out.append(c < 128 && Character.isJavaIdentifierPart(c) && c != '$' ? Character.toUpperCase(c) : '_');
            previous = c;
        }
        return out.toString();
    }

    /** A MASL name usable as a Java identifier: Java keywords get a trailing {@code _}. */
    static String identifier(String name) {
        return JAVA_KEYWORDS.contains(name) ? name + "_" : name;
    }

    /** Hands out distinct names: the second {@code X} becomes {@code X_2}. */
    static final class Unique {
        private final Set<String> used = new HashSet<>();

        Unique(String... reserved) {
            used.addAll(Set.of(reserved));
        }

        /** Hands out no name of the generated code's own ({@link #GENERATED_CODE_NAMES}) either. */
        static Unique besideGeneratedNames(String... reserved) {
            Unique unique = new Unique(reserved);
            unique.used.addAll(Set.of(GENERATED_CODE_NAMES));
            return unique;
        }

        String take(String wanted) {
            String name = wanted;
            for (int n = 2; !used.add(name); n++) {
                name = wanted + "_" + n;
            }
            return name;
        }
    }
}
