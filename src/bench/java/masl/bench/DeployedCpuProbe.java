package masl.bench;

import com.sun.management.OperatingSystemMXBean;
import java.lang.management.ManagementFactory;
import java.time.Duration;
import java.util.Optional;
import masl.runtime.descriptor.AgentPath;
import masl.runtime.trace.TraceEvent;
import masl.testing.TranslatedMission;
import masl.testing.jade.DeployedInMemory;
import masl.translator.MissionLoader;

/**
 * The CPU time a deployed lock-step mission ({@link MaslLockStep#source}, spread over two containers)
 * costs per step in one JVM, with no JADE: {@link DeployedInMemory} joins the mission and its
 * containers with wires that carry each message as JSON text, so that what is measured is the
 * coordination's own code on both sides (stand-ins, outboxes, batches, remote contexts), without
 * the three JVMs' scheduling, JADE's transport and their JITs competing for the machine's cores,
 * which make {@code gradle bench}'s deployed rows vary by a third from run to run. The process's CPU
 * time and the clock are read at the middle barrier trip of each mission and at its last. Not a test and
 * not part of {@code gradle bench}: {@code gradle deployedCpuProbe -PprobeArgs="agents steps missions"}
 * (defaults 1,000, 3,000, 4); the first mission warms the JIT up and is not printed.
 */
final class DeployedCpuProbe {

    private DeployedCpuProbe() {
    }

    public static void main(String[] args) throws Exception {
        int agents = args.length > 0 ? Integer.parseInt(args[0]) : 1_000;
        int steps = args.length > 1 ? Integer.parseInt(args[1]) : 3_000;
        int missions = args.length > 2 ? Integer.parseInt(args[2]) : 4;
        OperatingSystemMXBean os = (OperatingSystemMXBean) ManagementFactory.getOperatingSystemMXBean();
        AgentPath shippedAgentsOnly = AgentPath.parse("");
        MissionLoader program = MaslLockStep.compile(MaslLockStep.source(agents, steps));
        TranslatedMission mission = new TranslatedMission(program, shippedAgentsOnly, Optional.empty());
        for (int m = 0; m < missions; m++) {
            long[] cpu = new long[2];
            long[] clock = new long[2];
            int[] trips = new int[1];
            int half = steps / 2;
            DeployedInMemory.spread().run(mission, event -> {
                if (event instanceof TraceEvent.BarrierTripped) {
                    int trip = ++trips[0];
                    if (trip == half || trip == steps) {
                        int at = trip == half ? 0 : 1;
                        cpu[at] = os.getProcessCpuTime();
                        clock[at] = System.nanoTime();
                    }
                }
            }, Duration.ofMinutes(10)).requireCompleted();
            if (trips[0] != steps) {
                throw new IllegalStateException("the mission tripped its barrier " + trips[0] + " times, not " + steps);
            }
            if (m > 0) {
                double later = steps - half;
                System.out.printf("agents %d, mission %d of %d steps, later half: CPU %.2f ms per step, %.0f steps/s%n",
                        agents, m, steps, (cpu[1] - cpu[0]) / 1e6 / later, later / ((clock[1] - clock[0]) / 1e9));
            }
        }
    }
}
