package masl.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.ByteArrayOutputStream;
import java.io.EOFException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.Test;

class StackTraceFoldingTest {

    @Test
    void aStackTraceWithCausesIsItsFirstLineAndOtherLinesPassUnchanged() {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        PrintStream err = StackTraceFolding.around(new PrintStream(bytes, true, StandardCharsets.UTF_8));
        err.println("before");
        Exception nested = new IllegalStateException("connection lost", new EOFException("EOF reached"));
        nested.addSuppressed(new RuntimeException("also"));
        nested.printStackTrace(err);
        err.println("Nested Exception:");
        err.println("after, at the end");
        assertEquals("before\njava.lang.IllegalStateException: connection lost\nafter, at the end\n",
                bytes.toString(StandardCharsets.UTF_8));
    }

    /** JADE's AMS removing a container twice prints a NotFoundException: the departure, in masl's words. */
    @Test
    void jadesNotFoundContainerIsTheContainersDepartureInMaslsWords() {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        PrintStream err = StackTraceFolding.around(new PrintStream(bytes, true, StandardCharsets.UTF_8));
        err.println("jade.core.NotFoundException: No container named c7 was found");
        err.println("\tat jade.core.MainContainerImpl.removeAllMTPs(MainContainerImpl.java:1210)");
        err.println("after");
        assertEquals("masl: container c7 left the platform (its JVM ended or its connection broke)\nafter\n",
                bytes.toString(StandardCharsets.UTF_8));
    }

    /** On SIGTERM, JADE's resource manager prints the interrupt of its own terminator's sleep: dropped. */
    @Test
    void jadesOwnInterruptIsDroppedAndAnotherIsItsFirstLine() {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        PrintStream err = StackTraceFolding.around(new PrintStream(bytes, true, StandardCharsets.UTF_8));
        err.println("java.lang.InterruptedException: sleep interrupted");
        err.println("\tat java.base/java.lang.Thread.sleep(Native Method)");
        err.println("\tat jade.core.FullResourceManager$2.run(FullResourceManager.java:175)");
        err.println("before");
        err.println("java.lang.InterruptedException: sleep interrupted");
        err.println("\tat java.base/java.lang.Thread.sleep(Native Method)");
        err.println("\tat masl.cli.Elsewhere.run(Elsewhere.java:1)");
        err.println("java.lang.InterruptedException");
        err.println("after");
        assertEquals("before\njava.lang.InterruptedException: sleep interrupted\njava.lang.InterruptedException\nafter\n",
                bytes.toString(StandardCharsets.UTF_8));
    }
}
