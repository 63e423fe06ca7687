package masl.bench;

import java.lang.management.ManagementFactory;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;

/**
 * The CPU time a deployed mission's JVMs spend per step over the later half of its steps: this JVM's
 * (the mission's, with JADE's main container) and its containers' together, read every
 * {@value #PERIOD_MILLIS} ms with the number of steps ended so far ({@link TripTimes}), from the
 * first reading at or after the middle step to the last before the mission ends. Every thread of
 * each JVM counts: its JIT, its collector, a pool's runners spinning for work. The sum of the two
 * over the machine's cores is the fastest a step could be, were no JVM ever waiting for another.
 */
final class JvmCpu implements AutoCloseable {

    /** CPU per step over the later half, in milliseconds; NaN if too few readings fell in it. */
    record PerStep(double mission, double containers) {

        /** No figure: a mission too short for two readings in its later half (in-process, a few milliseconds). */
        static final PerStep NOT_READ = new PerStep(Double.NaN, Double.NaN);
    }

    private static final long PERIOD_MILLIS = 100;

    private record Reading(int steps, long mission, long containers) {
    }

    private final TripTimes trips;
    private final List<ProcessHandle> containers = new ArrayList<>();
    private final List<Reading> readings = new ArrayList<>();
    private final ScheduledExecutorService timer = Executors.newSingleThreadScheduledExecutor(work -> {
        Thread thread = new Thread(work, "bench-jvm-cpu");
        thread.setDaemon(true);
        return thread;
    });

    JvmCpu(TripTimes trips) {
        this.trips = trips;
        timer.scheduleAtFixedRate(this::read, PERIOD_MILLIS, PERIOD_MILLIS, TimeUnit.MILLISECONDS);
    }

    /** A container's JVM, counted from its next reading on: the process of the installed command, which execs java. */
    synchronized void container(Process process) {
        containers.add(process.toHandle());
    }

    private synchronized void read() {
        long mine = ((com.sun.management.OperatingSystemMXBean) ManagementFactory.getOperatingSystemMXBean())
                .getProcessCpuTime();
        long theirs = 0;
        for (ProcessHandle container : containers) {
            if (!container.isAlive()) {
                return;
            }
            theirs += container.info().totalCpuDuration().map(Duration::toNanos).orElse(0L);
        }
        readings.add(new Reading(trips.count(), mine, theirs));
    }

    /** The CPU per step over the later half of the steps ended so far; stops reading. */
    synchronized PerStep perStep() {
        timer.shutdownNow();
        int half = trips.count() / 2;
        Reading first = readings.stream().filter(reading -> reading.steps() >= half).findFirst().orElse(null);
        Reading last = readings.isEmpty() ? null : readings.get(readings.size() - 1);
        if (first == null || last.steps() <= first.steps()) {
            return PerStep.NOT_READ;
        }
        double steps = last.steps() - first.steps();
        return new PerStep((last.mission() - first.mission()) / 1e6 / steps,
                (last.containers() - first.containers()) / 1e6 / steps);
    }

    @Override
    public void close() {
        timer.shutdownNow();
    }
}
