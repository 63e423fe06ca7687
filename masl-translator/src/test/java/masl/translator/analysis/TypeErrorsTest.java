package masl.translator.analysis;

import static masl.translator.analysis.Analysis.analyzeBody;
import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/** Java's typing, relaxed as MASL §3 says. */
class TypeErrorsTest {

    @Test
    void stringCannotBeAssignedToAnInt() {
        analyzeBody("local int x = \"five\";")
                .assertError(7, 15, "incompatible types: String cannot be converted to int");
    }

    @Test
    void notOnAStringIsReported() {
        analyzeBody("local boolean b = !\"yes\";").assertError(7, 19, "bad operand type String for !");
    }

    @Test
    void arithmeticOnBooleansIsReported() {
        analyzeBody("local int x = true + 1;").assertError(7, 20, "bad operand types for +: boolean and int");
    }

    @Test
    void conditionOfTypeStringIsReported() {
        analyzeBody("if (\"yes\") .nop();")
                .assertError(7, 5, "the condition of if must be boolean or numeric, found String");
    }

    @Test
    void entryTestOfTypeStringIsReported() {
        analyzeBody("asynchronous entry a (\"x\") { }")
                .assertError(7, 23, "the test of entry a must be boolean or numeric, found String");
    }

    @Test
    void numericConditionsAndNotOnNumbersAreFine() {
        analyzeBody("""
                local int n = 1;
                while (n) { exit; }
                if (!n && .getProximity(0)) .nop();
                asynchronous entry a (n % 2) { }""").assertNoError();
    }

    @Test
    void anythingMayBeAssignedToAString() {
        analyzeBody("local String s = 3;\ns = k;\ns += 1.5;").assertNoError();
    }

    @Test
    void objectValuesAreTypedAtRunTime() {
        analyzeBody("local Object o = \"x\";\nlocal int n = o;\nlocal Khepera kk = o;\nn = o.hashCode() + 1;")
                .assertNoError();
    }

    @Test
    void equalityOnObjectsIsValueEquality() {
        analyzeBody("if (getAcceptState() == \"default\" && getAcceptState(k) <> \"nothing\") .nop();").assertNoError();
    }

    @Test
    void booleanComparedWithANumberIsReported() {
        analyzeBody("if (true == 1) .nop();").assertError(7, 10, "bad operand types for ==: boolean and int");
    }

    @Test
    void agentOfAnotherTypeCannotBeAssigned() {
        analyzeBody("local Khepera kk = d;")
                .assertError(7, 20, "incompatible types: Default cannot be converted to Khepera");
    }

    @Test
    void finalVariableCannotBeAssignedIncrementedOrCompoundAssigned() {
        Analysis.Result result = analyzeBody("local final int x = 1;\nx = 2;\nx++;\nx += 3;");
        assertEquals("""
                test.masl:8:1: error: cannot assign a value to final variable x
                test.masl:9:1: error: cannot assign a value to final variable x
                test.masl:10:1: error: cannot assign a value to final variable x""", result.rendered());
    }

    @Test
    void undeclaredNameIsReportedOnceWhateverUsesIt() {
        analyzeBody("local int x = foo + 1;\nlocal String s = foo.bar().baz;")
                .assertError(7, 15, "cannot find symbol foo");
    }

    @Test
    void voidValueCannotBeStored() {
        analyzeBody("local int x = .nop();").assertError(7, 15, "incompatible types: void cannot be converted to int");
    }

    @Test
    void expressionThatIsNotAStatementIsReported() {
        analyzeBody("local int x;\nx + 1;").assertError(8, 1, "not a statement: x+1");
    }

    @Test
    void castBetweenUnrelatedTypesIsReported() {
        analyzeBody("local int x = (int) \"3\";").assertError(7, 15, "cannot cast String to int");
    }

    @Test
    void arrayIndexMustBeAnInteger() {
        analyzeBody("local int[] a = {1, 2};\nlocal int x = a[1.5];")
                .assertError(8, 17, "an array index must be an integer, found double");
    }
}
