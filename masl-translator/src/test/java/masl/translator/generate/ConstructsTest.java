package masl.translator.generate;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * MASL constructs translated and run: each program's journal is asserted on the pool scheduler and
 * on seeds of the deterministic scheduler.
 */
@Timeout(120)
class ConstructsTest {

    private static final int RUNS = 10;
    private static final String ONE = "import Default.xml;\nDefault a = newAgent(Default);\n";
    private static final String FOUR = "import Default.xml;\nDefault a, b, c, d = newAgent(Default);\n";

    private static void assertJournal(String expected, String program) {
        for (String journal : Programs.journals(program, RUNS)) {
            assertEquals(expected, journal);
        }
    }

    @Test
    void ifElseWithNumericConditionsAndDiamond() {
        assertJournal("abe\n", ONE + """
                asynchronous entry main (true) {
                  local int n = 2;
                  if (n) { .log("a"); .log("b"); } else .log("c");
                  if (n - 2) .log("d"); else { .log("e"); }
                  if (n <> 2) .log("f");
                  .logln("");
                }
                """);
    }

    /** MASL §3: `==`, `!=` and `<>` compare objects by value, so two strings built apart are equal. */
    @Test
    void stringsAreComparedByValue() {
        assertJournal("equal\nnot different\n", ONE + """
                asynchronous entry main (true) {
                  local String s = new String("x");
                  if (s == "x") .logln("equal"); else .logln("identity");
                  if (s <> new String("x")) .logln("different"); else .logln("not different");
                }
                """);
    }

    @Test
    void whileForAndDoLoopWithExitAndExitN() {
        assertJournal("012wwwd1 5\n", ONE + """
                asynchronous entry main (true) {
                  local int i = 0;
                  for (i = 0; i < 3; i++) { .log(i); }
                  while (i > 0) { i--; .log("w"); }
                  do { i++; if (i == 2) exit; .log("d" + i); } loop
                  do { do { i++; if (i > 4) exit(2); } loop } loop
                  .logln(" " + i);
                }
                """);
    }

    @Test
    void readModifyWritesOfSharedVariablesAreAtomic() {
        assertJournal("16 160 abcd 10\n", FOUR + """
                synchronous entry main (true) {
                  shared int ids = 0;
                  shared int n = 0;
                  shared long total = 10;
                  shared String letters = "";
                  local int old = 0;
                  n++;
                  ++n;
                  n += 3;
                  ids += .getProxyID() + 1;
                  total = total * 2;
                  old = n--;
                  scalar entry letter (true) { letters = letters + "a"; }
                  .nop();
                  scalar entry report (true) { .logln(n + " " + total + " " + letters + "bcd " + ids); }
                }
                """);
    }

    @Test
    void siblingSynchronousChildrenKeepLockStepWithEachOther() {
        String program = "import Default.xml;\nDefault a, b, c = newAgent(Default);\n" + """
                synchronous entry main (true) {
                  synchronous entry right (.getProxyID() != 0) { .log("R"); .log("R"); }
                  synchronous entry left (.getProxyID() == 0) { .log("L"); .log("L"); }
                  scalar entry end (true) { .logln(""); }
                }
                """;
        for (String journal : Programs.journals(program, RUNS)) {
            assertEquals(7, journal.length(), journal);
            assertEquals("LRR", sorted(journal.substring(0, 3)), journal);
            assertEquals("LRR", sorted(journal.substring(3, 6)), journal);
            assertEquals("\n", journal.substring(6), journal);
        }
    }

    private static String sorted(String text) {
        char[] characters = text.toCharArray();
        java.util.Arrays.sort(characters);
        return new String(characters);
    }

    @Test
    void restartBreakNAndReelectKeepingLocals() {
        assertJournal("tries=4\ntries=4\n", "import Default.xml;\nDefault a, b = newAgent(Default);\n" + """
                asynchronous entry main (true) {
                  local int tries = 0;
                  asynchronous entry outer (true) {
                    local int visits = 0;
                    visits++;
                    asynchronous entry inner (true) {
                      tries++;
                      if (tries < 3) restart;
                      if (visits < 2) reelect(outer);
                      break(2);
                    }
                    .logln("never");
                  }
                  .logln("tries=" + tries);
                }
                """);
    }

    @Test
    void aReelectKeepsLocalsWhoseInitialisersWaitedForAnotherAgent() {
        assertJournal("visits=2 seen=1\nvisits=2 seen=1\n", "import Default.xml;\nDefault a, b = newAgent(Default);\n" + """
                asynchronous entry main (true) {
                  asynchronous entry outer (true) {
                    local int visits = 0;
                    local int seen = b.getProxyID() + visits;
                    visits++;
                    asynchronous entry inner (true) {
                      if (visits < 2) reelect(outer);
                      .logln("visits=" + visits + " seen=" + seen);
                    }
                  }
                }
                """);
    }

    @Test
    void relaxedTypingFinalAndValueEquality() {
        assertJournal("equal\ndifferent\n4\ny\n7\n0\n", ONE + """
                scalar entry main (true) {
                  local final String word = "ab";
                  local String built = "a";
                  local short small = 3;
                  local char c = 'x';
                  built = built + "b";
                  if (built == word) .logln("equal");
                  if (built != "ba") .logln("different");
                  .logln(small + 1);
                  c++;
                  .logln(c);
                  .logln(Math.max(2, 7));
                  .logln(new java.util.Vector<Integer>().size());
                }
                """);
    }

    @Test
    void membersOfObjectTypedValuesAreFoundAtRunTime() {
        assertJournal("3\nbc\n3\ntrue\ntrue false\n", ONE + """
                asynchronous entry main (true) {
                  local java.util.Vector v = new java.util.Vector();
                  local java.util.Vector w = new java.util.Vector();
                  local int n = 0;
                  v.add("abc");
                  w.add(v.iterator());
                  .logln(v.get(0).length());
                  .logln(v.get(0).substring(1));
                  n = v.get(0).length();
                  .logln(n);
                  .logln(w.get(0).hasNext());
                  .logln((v.get(0) instanceof String) + " " + (this instanceof Default && v instanceof java.util.Map));
                }
                """);
    }

    @Test
    void aReactionThatRestartsItsBlock() {
        assertJournal("ping 1\nping 2\nafter 3\ndone 3\n", ONE + """
                asynchronous entry main (true) {
                  local event ping;
                  local int tries = 0;
                  asynchronous entry work (true) {
                    tries++;
                    if (tries < 3) emit ping;
                    .logln("after " + tries);
                    react (ping) { .logln("ping " + tries); restart; }
                  }
                  .logln("done " + tries);
                }
                """);
    }

    @Test
    void aCallThatThrowsRaisesUncaughtExceptionAndAReactionWithoutEndingLeavesItsBlock() {
        assertJournal("before\ncaught java.lang.ArrayIndexOutOfBoundsException\nafter\n", ONE + """
                asynchronous entry main (true) {
                  local java.util.Vector v = new java.util.Vector();
                  asynchronous entry risky (true) {
                    .logln("before");
                    v.get(3);
                    .logln("never");
                    react (uncaught_exception) { .logln("caught " + getMessageFromEvent(uncaught_exception)); }
                  }
                  .logln("after");
                }
                """);
    }

    @Test
    void aDefaultReactionResumesWhereTheAgentWas() {
        assertJournal("default 42\nresumed\n", ONE + """
                asynchronous entry main (true) {
                  local event e;
                  emitWithMessage(e, 42);
                  .logln("resumed");
                  react (default) { .logln("default " + getMessageFromEvent(e)); resume; }
                }
                """);
    }

    @Test
    void sleepSuspendsOnTheMissionClock() {
        assertJournal("slept\n", ONE + """
                asynchronous entry main (true) {
                  .sleep(5);
                  Thread.sleep(5);
                  .logln("slept");
                }
                """);
    }

    @Test
    void absentMembersMakeStatementsNopsAndTestsFalse() {
        String program = """
                import Default.xml;
                import robots/Khepera.xml;
                Default d = newAgent(Default);
                Khepera k = newAgent(Khepera);
                synchronous entry main (true) {
                  .startGripper();
                  if (.getProximity(3) == 3) .logln("near " + .getProxyID()); else .logln("far " + .getProxyID());
                  scalar entry charged (.battery == 0) { .logln("battery"); }
                }
                """;
        for (String journal : Programs.journals(program, RUNS)) {
            assertEquals(List.of("battery", "far 0", "near 1"), Programs.sortedLines(journal), journal);
        }
    }

    @Test
    void aStateChangeOrAWaitUsingAnAbsentMemberIsANop() {
        String program = """
                import robots/Khepera.xml;
                import robots/Explorer.xml;
                Khepera k = newAgent(Khepera);
                Khepera e = newAgent(Explorer);
                synchronous entry main (true) {
                  wait(.explore("default"), 1);
                  setAcceptState(.explore("nothing"));
                  asynchronous entry report (!(this instanceof Explorer)) {
                    .logln(getAcceptState(k) + " " + getAcceptState(e));
                  }
                }
                """;
        // The explorer, in state nothing, may not even log: the khepera, which kept its state, reports.
        assertJournal("default nothing\n", program);
    }

    @Test
    void aWriteToALimitedVariableByAnotherTypeIsIgnoredAndRaisesForbiddenAccess() {
        assertJournal("forbidden owned\nowned 1\n", """
                import Default.xml;
                import robots/Khepera.xml;
                Default d = newAgent(Default);
                Khepera k = newAgent(Khepera);
                synchronous entry main (true) {
                  shared int owned limited(Khepera) = 0;
                  owned = owned + 1;
                  scalar entry report (true) { .logln("owned " + owned); }
                  react (forbidden_access) { .logln("forbidden " + getMessageFromEvent(forbidden_access)); resume; }
                }
                """);
    }

    @Test
    void aBusyWaitOnASharedVariableEndsWhenAnotherAgentWritesIt() {
        assertJournal("go\n", "import Default.xml;\nDefault a, b = newAgent(Default);\n" + """
                asynchronous entry main (true) {
                  shared int flag = 0;
                  asynchronous entry waiter (.getProxyID() == 0) {
                    while (flag != 1) {}
                    .logln("go");
                  }
                  asynchronous entry setter (.getProxyID() == 1) { .sleep(10); flag = 1; }
                }
                """);
    }
}
