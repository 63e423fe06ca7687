package masl.translator.analysis;

import static masl.translator.analysis.Analysis.analyze;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import masl.runtime.diagnostic.Diagnostic;
import org.junit.jupiter.api.Test;

/** Errors in the program's headers: descriptors, agent types, agents and Entry declarations (MASL §3, §4). */
class HeaderErrorsTest {

    @Test
    void importOfAMissingDescriptorIsReportedAtThePathAndItsTypeRaisesNoMoreErrors() {
        analyze("""
                import robots/Missing.xml;
                Missing m = newAgent(Missing);
                """).assertError(1, 8, "cannot find descriptor robots/Missing.xml: looked in the program's folder "
                        + Analysis.FIXTURES + " and the descriptors shipped with masl");
    }

    @Test
    void unquotedPathWithWhiteSpaceMustBeQuoted() {
        analyze("import my robots/Robot.xml;\n")
                .assertError(1, 8, "a descriptor path with white space must be quoted: \"my robots/Robot.xml\"");
    }

    @Test
    void quotedPathWithWhiteSpaceIsFine() {
        Analysis.Result result = analyze("import \"my robots/Robot.xml\";\nRobot r = newAgent();\n");
        result.assertNoError();
        assertEquals("Robot", result.program().agents().get(0).declaredType().name());
    }

    @Test
    void descriptorProblemsAreReportedInTheDescriptorAndAtTheImport() {
        Analysis.Result result = analyze("import broken/Broken.xml as Broken;\nBroken b = newAgent(Broken);\n");
        List<Diagnostic> inDescriptor = result.diagnostics().stream()
                .filter(diagnostic -> diagnostic.file().endsWith("Broken.xml")).toList();
        assertTrue(!inDescriptor.isEmpty() && inDescriptor.get(0).message().contains("stand"), result.rendered());
        assertTrue(result.rendered().contains(Analysis.FILE + ":1:8: error: descriptor broken/Broken.xml has errors"),
                result.rendered());
    }

    @Test
    void headersOutOfOrderAreReported() {
        analyze("""
                import Default.xml;
                Default a = newAgent(Default);
                import robots/Khepera.xml;
                """).assertError(3, 1, "An import must come before an agent declaration: the order is imports, "
                + "types, agents, then Entry declarations");
    }

    @Test
    void typeDeclarationAfterEntryDeclarationIsReported() {
        analyze("""
                import Default.xml;
                Entry e;
                type Other use Default.xml;
                asynchronous entry main (true) { asynchronous entry e (true) { } }
                """).assertError(3, 1, "A type declaration must come before an Entry declaration: the order is "
                + "imports, types, agents, then Entry declarations");
    }

    @Test
    void agentOfAnUnknownTypeIsReportedOnce() {
        analyze("""
                Khepera k = newAgent(Khepera);
                asynchronous entry main (k.getProximity(1) > 0) {
                  shared int x limited(Khepera) = k.battery;
                }
                """).assertError(1, 1, "cannot find agent type Khepera: import its descriptor first");
    }

    @Test
    void newAgentOfAnUnknownTypeIsReported() {
        analyze("import Default.xml;\nDefault a = newAgent(Robo);\n")
                .assertError(2, 22, "cannot find agent type Robo: import its descriptor first");
    }

    @Test
    void instantiatedTypeMustBeASubtypeOfTheDeclaredOne() {
        analyze("""
                import Default.xml;
                import robots/Khepera.xml;
                Khepera k = newAgent(Default);
                """).assertError(3, 22, "Default is not a subtype of Khepera: agents declared Khepera cannot be "
                + "created as Default");
    }

    @Test
    void aTypeDefinedByTypeUseIsNotASubtypeOfItsDescriptorsOtherName() {
        analyze("""
                import Default.xml;
                type Other use Default.xml;
                Default d = newAgent(Other);
                """).assertError(3, 22, "Other is not a subtype of Default: agents declared Default cannot be "
                + "created as Other");
    }

    @Test
    void typeNameDefinedByTwoDifferentFilesIsReported() {
        analyze("""
                import robots/Khepera.xml as T;
                import "my robots/Robot.xml" as T;
                """).assertError(2, 1, "agent type T is already defined by robots/Khepera.xml");
    }

    @Test
    void sameTypeImportedTwiceFromTheSameFileIsFine() {
        analyze("import Default.xml;\ntype Default use Default.xml;\nDefault a = newAgent(Default);\n")
                .assertNoError();
        analyze("import robots/Khepera.xml;\nimport robots/../robots/Khepera.xml;\n").assertNoError();
    }

    @Test
    void agentDeclaredTwiceIsReported() {
        analyze("import Default.xml;\nDefault a, b = newAgent(Default);\nDefault a = newAgent(Default);\n")
                .assertError(3, 9, "agent a is already declared");
    }

    @Test
    void entryDeclaredTwiceIsReported() {
        analyze("""
                import Default.xml;
                Entry e, e;
                asynchronous entry main (true) { asynchronous entry e (true) { } }
                """).assertError(2, 10, "Entry e is already declared");
    }

    @Test
    void entryDeclarationNamingNoBlockIsReported() {
        analyze("""
                import Default.xml;
                Entry team;
                asynchronous entry main (true) { }
                """).assertError(2, 7, "Entry team names no entry block");
    }
}
