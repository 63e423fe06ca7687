package masl.translator.analysis;

import static masl.translator.analysis.Analysis.analyzeBody;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** Statements robot programs write, which the analysis must accept: Java's typing is not stricter here. */
class ValidProgramsTest {

    @ParameterizedTest
    @ValueSource(strings = {
        "local Khepera[] team = {k};",
        "local char c = 'a' + 1;",
        "local long t = System.currentTimeMillis();",
        "local String s = String.valueOf(3) + \"abc\".length() + Integer.parseInt(\"3\");",
        "local double r = Math.random() * 10;",
        "local java.util.Random rnd = new java.util.Random(42);\nlocal int n = rnd.nextInt(10);",
        "local java.util.HashMap<String, Integer> m = new HashMap<String, Integer>();\nm.put(\"a\", 1);",
        "local Integer boxed = 3;\nlocal int unboxed = boxed + 1;",
        "local float f = 1.5f;\nf = f * 2;\nf += 1;",
        "local int[][] g = new int[3][];\nlocal double[] ds = new double[] {1, 2.5};\ng[0] = new int[ds.length];",
        "local boolean b = k instanceof Khepera;\nlocal Khepera any = (Khepera) main.getList()[0];",
        "local boolean b = true;\nlocal Khepera other = b ? k : null;",
        "local int x = 0;\nx = x > 0 ? x : -x;\nx <<= 2;\nx = (int) (x * 1.5);",
        "local String s = \"ab\";\nif (s.equals(\"x\") || s.length() > 0 && s.charAt(0) == 'a') .logln(s);",
        "local java.util.Vector<Integer> seen = new java.util.Vector<Integer>();\n"
            + "local int first = seen.get(0) + seen.size();",
        "local Vector2d p = new Vector2d();\np.x = 3;\np = .position();",
        ".logln(Khepera.MAX_SPEED + k.MAX_SPEED + .MAX_SPEED + this.battery + Thread.currentThread().getName());",
        "local String state = getAcceptState(main.getList()[0]);\nmain.release(main.getWaitingInCount());",
        "local long started = System.nanoTime();\nwait(\"default\", (started % 100));",
        ".startGripper();\n.stopGripper();\nk.setSpeeds(1, 2.5f);"
    })
    void isAccepted(String body) {
        analyzeBody(body).assertNoError();
    }
}
