package masl.runtime.invocation;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import masl.runtime.testing.Driver;
import masl.runtime.testing.MaslProgram;
import masl.runtime.testing.Missions;
import masl.runtime.testing.TestAgent;
import masl.runtime.trace.Trace;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * MASL §11, table-driven: for each of the 8 combinations of x bits (u g o) that state {@code xK} of
 * agents/Default.xml gives {@code nop}, the callee (agent 0, in block {@code inner}) takes that
 * state, and {@code nop} is invoked by the callee itself (u), by a member of the same innermost
 * block (g), by an agent in the parent block {@code main} (o) and by one in the sibling block
 * {@code elsewhere} (o). Exactly the allowed invocations run, each once.
 * Each requester logs whether its call ran (a denied one gives it {@code timeout}); the callee's
 * {@code nop} counts its runs. The callee takes the state its attribute {@code battery} names, and
 * {@code default} again to log (a state that lists members denies the others).
 */
@Timeout(120)
class PermeabilityTableTest {

    private static final MaslProgram REQUESTS = MaslProgram.of("permeability.masl", 4, """
            asynchronous entry main (true) {
              shared int ready = 0;
              shared int done = 0;
              local int denied = 0;
              asynchronous entry inner (.getProxyID() <= 1) {
                if (.getProxyID() == 0) {
                  setAcceptState("x" + .battery); ready = 1; while (done < 3) {}
                  .nop();
                  setAcceptState("default");
                  .logln("0 ran " + (1 - denied));
                } else {
                  while (ready == 0) {} a0.nop(); .logln("1 ran " + (1 - denied)); done++;
                }
              }
              asynchronous entry elsewhere (.getProxyID() == 3) {
                while (ready == 0) {} a0.nop(); .logln("3 ran " + (1 - denied)); done++;
              }
              if (.getProxyID() == 2) {
                while (ready == 0) {} a0.nop(); .logln("2 ran " + (1 - denied)); done++;
              }
              react (timeout) { denied = 1; resume; }
            }
            """);

    /** An agent whose {@code battery} names the callee's state and whose {@code nop} counts its runs. */
    private static final class Counting extends TestAgent {
        private final AtomicInteger runs;

        Counting(int bits, AtomicInteger runs) {
            this.runs = runs;
            battery = bits;
        }

        @Override
        public void nop() {
            runs.incrementAndGet();
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void exactlyTheAllowedInvocationsRun(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS / 5; run++) {
            for (int bits = 0; bits < 8; bits++) {
                AtomicInteger runs = new AtomicInteger();
                int state = bits;
                String journal = REQUESTS.run(driver.newScheduler(), Trace.NONE, () -> new Counting(state, runs)).journal();
                int u = bits >> 2 & 1;
                int g = bits >> 1 & 1;
                int o = bits & 1;
                assertEquals(List.of("0 ran " + u, "1 ran " + g, "2 ran " + o, "3 ran " + o), journal.lines().sorted().toList(),
                        "runs by self, same block, parent block, sibling block in state x" + bits);
                assertEquals(u + g + o + o, runs.get(), "nop's runs in state x" + bits);
            }
        }
    }
}
