package masl.jade.stub;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.reflect.Method;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.function.Supplier;
import masl.jade.platform.JadeException;
import masl.runtime.AgentImplementation;
import masl.runtime.AttributesElsewhere;
import org.junit.jupiter.api.Test;

/**
 * A stub's primitives hand their index and boxed arguments to its {@link BodyStub} and return its answer;
 * the stub is Java source ({@link StubSource}) compiled once per implementation class and primitives.
 */
class StubClassesTest {

    /** An implementation with primitives of every kind of parameter and result. */
    public static class Calculator extends AgentImplementation {
        public int add(int a, int b) {
            return a + b;
        }

        public void log(String text) {
            throw new AssertionError("the stub must not run the body's code");
        }

        public long mix(long a, double b, boolean c, char d, float e, byte f, short g) {
            return 0;
        }

        public String[] names() {
            return null;
        }

        public double half(double x) {
            return x / 2;
        }

        /** Not a primitive: runs as the class has it. */
        public String local() {
            return "local";
        }
    }

    private final List<String> calls = new ArrayList<>();
    private final StubClasses stubs = new StubClasses();

    private Calculator stub(BodyStub answers) throws NoSuchMethodException {
        List<Method> primitives = List.of(
                Calculator.class.getMethod("add", int.class, int.class),
                Calculator.class.getMethod("log", String.class),
                Calculator.class.getMethod("mix", long.class, double.class, boolean.class, char.class, float.class,
                        byte.class, short.class),
                Calculator.class.getMethod("names"),
                Calculator.class.getMethod("half", double.class));
        return (Calculator) stubs.instantiate(Calculator.class, primitives, (method, args) -> {
            calls.add(primitives.get(method).getName() + Arrays.toString(args));
            return answers.call(method, args);
        });
    }

    @Test
    void primitivesGoToTheBodyStubWithTheirArgumentsAndReturnItsResult() throws Exception {
        String[] names = {"a", "b"};
        Calculator stub = stub((method, args) -> switch (method) {
            case 0 -> 42;
            case 2 -> 7L;
            case 3 -> names;
            case 4 -> 0.25;
            default -> null;
        });
        assertEquals(42, stub.add(2, 3));
        stub.log("hello");
        assertEquals(7L, stub.mix(1L << 40, 2.5, true, 'x', 1.5f, (byte) 3, (short) 4));
        assertSame(names, stub.names());
        assertEquals(0.25, stub.half(8));
        assertEquals("local", stub.local());
        assertEquals(List.of("add[2, 3]", "log[hello]", "mix[1099511627776, 2.5, true, x, 1.5, 3, 4]", "names[]",
                "half[8.0]"), calls);
        assertTrue(stub.getClass().getSuperclass() == Calculator.class);
    }

    @Test
    void whatTheBodyThrowsIsThrownByTheStub() throws Exception {
        Calculator stub = stub((method, args) -> {
            throw new ArithmeticException("/ by zero");
        });
        assertEquals("/ by zero", assertThrows(ArithmeticException.class, () -> stub.add(1, 0)).getMessage());
    }

    @Test
    void agentsOfOneTypeShareOneStubClass() throws Exception {
        Calculator first = stub((method, args) -> 1);
        Calculator second = stub((method, args) -> 2);
        assertSame(first.getClass(), second.getClass());
        assertEquals(1, first.add(0, 0));
        assertEquals(2, second.add(0, 0));
    }

    @Test
    void theRuntimesReadsAndWritesOfAttributesGoToTheBody() throws Exception {
        AgentImplementation stub = stubs.instantiate(Calculator.class, List.of(), new BodyStub() {
            @Override
            public Object call(int method, Object[] args) {
                return null;
            }

            @Override
            public Object readAttribute(String attribute, Supplier<?> read) {
                calls.add("read " + attribute);
                return 7;
            }

            @Override
            public void writeAttribute(String attribute, Runnable write) {
                calls.add("write " + attribute);
            }
        });
        AttributesElsewhere elsewhere = (AttributesElsewhere) stub;
        assertEquals(7, elsewhere.readAttribute("x", () -> 0));
        elsewhere.writeAttribute("x", () -> calls.add("the stub's own field"));
        assertEquals(List.of("read x", "write x"), calls);
    }

    @Test
    void theStubIsReadableJava() throws Exception {
        String text = new StubSource(Calculator.class, List.of(Calculator.class.getMethod("add", int.class, int.class),
                Calculator.class.getMethod("log", String.class))).text();
        assertTrue(text.startsWith("package masl.jade.stub;\n"), text);
        assertTrue(text.contains("public final class StubClassesTest$Calculator$MaslStub extends"
                + " masl.jade.stub.StubClassesTest.Calculator implements masl.runtime.AttributesElsewhere {"), text);
        assertTrue(text.contains("""
                    @Override
                    public int add(int a0, int a1) {
                        return (java.lang.Integer) body.call(0, new Object[] {a0, a1});
                    }
                """), text);
        assertTrue(text.contains("""
                    public void log(java.lang.String a0) {
                        body.call(1, new Object[] {a0});
                    }
                """), text);
    }

    @Test
    void aClassThatIsNotPublicCannotBeStubbed() {
        class Sealed extends AgentImplementation {
        }
        JadeException refused = assertThrows(JadeException.class,
                () -> stubs.instantiate(Sealed.class, List.of(), (method, args) -> null));
        assertTrue(refused.getMessage().contains("must be public and not final"), refused.getMessage());
        assertArrayEquals(new Object[0], calls.toArray());
    }
}
