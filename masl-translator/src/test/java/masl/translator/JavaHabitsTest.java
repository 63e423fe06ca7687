package masl.translator;

import static masl.translator.FrontendErrors.errorsOf;
import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/**
 * What a Java developer writes first, each reported once with the MASL to write instead, and no
 * error that is only its consequence.
 */
class JavaHabitsTest {

    @Test
    void aDeclarationWithoutLocalOrShared() {
        assertEquals("p.masl:4:5: error: a declaration needs `local` or `shared` and goes at the head of its block:"
                + " `local String s …;`", errorsOf("""
                asynchronous entry main (true) {
                    String s = "x";
                    .logln(s);
                }
                """));
    }

    @Test
    void aJavaDeclarationAmongStatementsIsOneError() {
        assertEquals("""
                p.masl:5:5: error: a declaration needs `local` or `shared` and goes at the head of its block: `local String s …;`
                p.masl:7:5: error: a declaration needs `local` or `shared` and goes at the head of its block: `local java.util.Vector<Integer> v …;`""",
                errorsOf("""
                asynchronous entry main (true) {
                    .logln("start");
                    String s = "x";
                    .logln(s);
                    java.util.Vector<Integer> v = new java.util.Vector<Integer>();
                }
                """));
    }

    @Test
    void aForThatDeclaresItsVariable() {
        assertEquals("p.masl:4:10: error: a for cannot declare its variable: declare `local int i;` at the head of the"
                + " block, then write `for (i = …; …)`", errorsOf("""
                asynchronous entry main (true) {
                    for (int i = 0; i < 3; i++) {
                        .logln(i);
                    }
                }
                """));
    }

    @Test
    void javaModifiersOnAVariable() {
        assertEquals("p.masl:4:5: error: `public static` is Java, not MASL: a variable is `local` (each agent's own)"
                + " or `shared` (one for the block's members), declared at the head of its block: `local int count …;`",
                errorsOf("""
                asynchronous entry main (true) {
                    public static int count = 0;
                    count++;
                }
                """));
    }

    @Test
    void aJavaClassAroundTheProgramIsOneErrorAndTheProgramInItIsChecked() {
        assertEquals("""
                p.masl:3:1: error: `public` is Java, not MASL: a program is its imports, its agents and one entry block (`scalar entry main (true) { … }`), with no classes or methods
                p.masl:5:10: error: cannot find primitive logn in any imported agent type; did you mean `logln`?""",
                errorsOf("""
                public class Mission {
                    scalar entry main (true) {
                        .logn("x");
                    }
                }
                """));
    }

    @Test
    void aJavaMethod() {
        assertEquals("p.masl:4:5: error: `public` is Java, not MASL: a program is its imports, its agents and one"
                + " entry block (`scalar entry main (true) { … }`), with no classes or methods", errorsOf("""
                asynchronous entry main (true) {
                    public void f() {
                    }
                }
                """));
    }

    @Test
    void aDeclarationInTheBlockOfAnIfOrALoop() {
        assertEquals("""
                p.masl:6:9: error: only an entry block declares, at its head: move this declaration to the head of the entry block around it
                p.masl:10:9: error: only an entry block declares, at its head: move this declaration to the head of the entry block around it
                p.masl:11:12: error: expected ';'""", errorsOf("""
                asynchronous entry main (true) {
                    local int x = 0;
                    if (x == 0) {
                        local int t = 1;
                        x = t;
                    }
                    while (x < 3) {
                        shared event e;
                        x++
                    }
                }
                """));
    }

    @Test
    void printingOnTheConsole() {
        assertEquals("p.masl:5:5: error: System.out.println writes past the mission's journal: use `.logln(…)`"
                + " (`.log(…)` without the line break)", errorsOf("""
                asynchronous entry main (true) {
                    local int x = 1;
                    System.out.println(x);
                }
                """));
    }

    @Test
    void returningFromABlock() {
        assertEquals("p.masl:4:15: error: MASL has no return: `break;` leaves the block, `exit;` the loop", errorsOf("""
                asynchronous entry main (true) {
                    if (true) return;
                }
                """));
    }

    /** MASL compares strings by value (§3): {@code ==} is what a Java developer meant by equals. */
    @Test
    void stringsComparedWithEqualsAndElseIfAreMasl() {
        assertEquals("", errorsOf("""
                asynchronous entry main (true) {
                    local String s = "x";
                    if (s == "x") .logln("same");
                    else if (s != "y") .logln("other");
                    else .logln("y");
                }
                """));
    }
}
