package masl.runtime;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;
import masl.runtime.testing.Driver;
import masl.runtime.testing.MaslProgram;
import masl.runtime.testing.Missions;
import masl.runtime.testing.TestAgent;
import masl.runtime.trace.Trace;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * {@code setAcceptState}, {@code getAcceptState()}, {@code getAcceptState(a)} and attribute access
 * under permeability (MASL §9, §11). State {@code readOnly} gives {@code battery} rights 666 with
 * umask 022: the agent reads and writes it, others only read it.
 */
@Timeout(120)
class AcceptStateAndAttributesTest {

    private static final MaslProgram STATES = MaslProgram.of("states.masl", MaslProgram.header(2) + """
            asynchronous entry main (true) {
              shared int done = 0;
              if (.getProxyID() == 0) {
                setAcceptState("nope");
                .logln("state " + getAcceptState());
                .battery = 50;
                setAcceptState("readOnly");
                while (done == 0) {}
              } else {
                while (getAcceptState(a0) != "readOnly") {}
                .logln("read " + a0.battery);
                a0.battery = 7;
                done = 1;
              }
              react (uncaught_exception) { .logln(getMessageFromEvent(uncaught_exception)); resume; }
              react (forbidden_access) { .logln("forbidden " + getMessageFromEvent(forbidden_access)); resume; }
            }
            """);

    @ParameterizedTest
    @EnumSource(Driver.class)
    void statesFilterAttributeAccessAndAnUndeclaredStateIsAnUncaughtException(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            List<TestAgent> population = new ArrayList<>();
            String journal = STATES.run(driver.newScheduler(), Trace.NONE,
                    MaslProgram.recording(TestAgent::new, population)).journal();
            assertEquals("java.lang.IllegalArgumentException\nstate default\nread 50\nforbidden battery\n", journal);
            assertEquals(50, population.get(0).battery, "the denied write did not run");
        }
    }
}
