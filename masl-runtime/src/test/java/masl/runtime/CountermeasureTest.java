package masl.runtime;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import masl.runtime.testing.Driver;
import masl.runtime.testing.MaslProgram;
import masl.runtime.testing.Missions;
import masl.runtime.testing.TestAgent;
import masl.runtime.trace.MemoryTrace;
import masl.runtime.trace.Trace;
import masl.runtime.trace.TraceEvent;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * Countermeasures (MASL §9): each agent launches {@code calibrate} (countermeasure
 * {@code stopCalibrate}, which logs "i stops") in {@code outer} and again in {@code inner}, then
 * leaves in its own way; agent 4 invokes {@code stopCalibrate} itself, which disarms both.
 */
@Timeout(120)
class CountermeasureTest {

    private static final MaslProgram LEAVING = MaslProgram.of("leaving.masl", 5, """
            asynchronous entry main (true) {
              asynchronous entry outer (true) {
                local event halt;
                .calibrate();
                asynchronous entry inner (true) {
                  .calibrate();
                  if (.getProxyID() == 0) break;
                  else if (.getProxyID() == 1) break(outer);
                  else if (.getProxyID() == 2) emit halt;
                  else if (.getProxyID() == 4) .stopCalibrate();
                }
                react (halt) { }
              }
            }
            """);

    @ParameterizedTest
    @EnumSource(Driver.class)
    void everyWayOfLeavingFiresEachArmedCountermeasureOnceInnermostFirst(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            MemoryTrace trace = new MemoryTrace();
            String journal = LEAVING.run(driver.newScheduler(), trace).journal();
            assertEquals(List.of("0 stops", "0 stops", "1 stops", "1 stops", "2 stops", "2 stops", "3 stops", "3 stops",
                    "4 stops"), journal.lines().filter(line -> line.endsWith("stops")).sorted().toList(), journal);
            List<List<String>> fired = new ArrayList<>();
            for (int agent = 0; agent < 5; agent++) {
                fired.add(new ArrayList<>());
            }
            for (TraceEvent.CountermeasureFired event : trace.events(TraceEvent.CountermeasureFired.class)) {
                assertEquals(event.agent(), event.callee());
                assertEquals("stopCalibrate", event.member());
                fired.get(event.agent()).add(event.block());
            }
            List<String> innermostFirst = List.of("inner", "outer");
            assertEquals(List.of(innermostFirst, innermostFirst, innermostFirst, innermostFirst, List.of()), fired);
        }
    }

    /**
     * A fired countermeasure counts as the completion of its launch (§10), which stores the
     * primitive's default value: {@code calibrate} runs until {@code stopCalibrate} stops it; the
     * agent breaks out of {@code inner} while it runs.
     */
    private static final MaslProgram STOPPED = MaslProgram.of("stopped.masl", 1, """
            asynchronous entry main (true) {
              LLabel l;
              local int x = 7;
              asynchronous entry inner (true) { l.x = .calibrate(); break; }
              .logln(l.isFinished() + " x=" + x);
            }
            """);

    /** Calibrates until its countermeasure runs. */
    private static final class Calibrating extends TestAgent {
        private final CountDownLatch stopped = new CountDownLatch(1);

        @Override
        public int calibrate() {
            awaitOpening(stopped);
            return 5;
        }

        @Override
        public void stopCalibrate() {
            stopped.countDown();
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void aFiredCountermeasureCompletesItsLaunchForLabels(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            assertEquals("true x=0\n", STOPPED.run(driver.newScheduler(), Trace.NONE, Calibrating::new).journal());
        }
    }
}
