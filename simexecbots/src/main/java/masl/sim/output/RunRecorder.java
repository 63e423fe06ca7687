package masl.sim.output;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import masl.sim.physics.BodyPose;
import masl.sim.physics.PhysicsWorld;

/**
 * Records a run: every robot's pose each {@code sampleSteps} physics steps (its trajectory) and
 * the physical events of the run (faults, empty batteries, latches), stamped with simulated time.
 * Writes them as CSV and JSON lines whose bytes depend only on what was recorded, so two
 * identical lock-step runs give identical files.
 *
 * <p>Thread-safe: samples are taken on the stepping thread, events come from any thread.
 */
public final class RunRecorder implements PhysicsWorld.StepListener {

    /** One pose of one robot. @param heading radians, counter-clockwise from +X */
    public record Sample(double time, String agent, double x, double y, double z, double heading) { }

    /** Something that happened to a robot at a simulated time. */
    public record Event(double time, String agent, String kind, String detail) { }

    private final long sampleSteps;
    /** Robot name to the body whose pose is its trajectory, in the order robots were added. */
    private final Map<String, String> tracked = new LinkedHashMap<>();
    private final List<Sample> samples = new ArrayList<>();
    private final List<Event> events = new ArrayList<>();
    private volatile double now;

    /** @param sampleSteps a sample every this many steps, &gt; 0 */
    public RunRecorder(long sampleSteps) {
        if (sampleSteps <= 0) {
            throw new IllegalArgumentException("sampleSteps: " + sampleSteps);
        }
        this.sampleSteps = sampleSteps;
    }

    /** Records the trajectory of {@code agent} as the pose of {@code body}, from the next sample on. */
    public synchronized void track(String agent, String body) {
        tracked.put(agent, body);
    }

    /** Takes the first sample (the initial poses) now; call once before the run starts. */
    public void sampleNow(PhysicsWorld world) {
        sample(world);
    }

    @Override
    public void afterStep(PhysicsWorld world) {
        now = world.simulatedTime();
        if (world.stepCount() % sampleSteps == 0) {
            sample(world);
        }
    }

    /** Reads the poses without holding this recorder's lock: never wait for the world while holding it. */
    private void sample(PhysicsWorld world) {
        Map<String, String> bodies;
        synchronized (this) {
            bodies = new LinkedHashMap<>(tracked);
        }
        double time = world.simulatedTime();
        List<Sample> taken = new ArrayList<>();
        bodies.forEach((agent, body) -> {
            BodyPose pose = world.bodyPose(body);
            taken.add(new Sample(time, agent, pose.x(), pose.y(), pose.z(), pose.heading()));
        });
        synchronized (this) {
            samples.addAll(taken);
        }
    }

    /** Records an event at the simulated time of the latest step. */
    public synchronized void event(String agent, String kind, String detail) {
        events.add(new Event(now, agent, kind, detail));
    }

    public synchronized List<Sample> samples() {
        return List.copyOf(samples);
    }

    public synchronized List<Event> events() {
        return List.copyOf(events);
    }

    /** The samples of one robot, in time order. */
    public synchronized List<Sample> trajectory(String agent) {
        return samples.stream().filter(s -> s.agent().equals(agent)).toList();
    }

    /** {@code time,agent,x,y,z,heading}: a header line, then one line per sample; metres and radians. */
    public synchronized void writeTrajectoriesCsv(Appendable out) {
        try {
            out.append("time,agent,x,y,z,heading\n");
            for (Sample s : samples) {
                out.append(String.format(Locale.ROOT, "%.3f,%s,%.6f,%.6f,%.6f,%.6f%n",
                        s.time(), s.agent(), s.x(), s.y(), s.z(), s.heading()));
            }
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** One JSON object per line: {@code {"time":1.250,"agent":"k0","event":"fault","detail":"…"}}. */
    public synchronized void writeEventsJsonLines(Appendable out) {
        try {
            for (Event e : events) {
                out.append(String.format(Locale.ROOT, "{\"time\":%.3f,\"agent\":%s,\"event\":%s,\"detail\":%s}%n",
                        e.time(), json(e.agent()), json(e.kind()), json(e.detail())));
            }
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    static String json(String text) {
        StringBuilder quoted = new StringBuilder("\"");
        for (char c : text.toCharArray()) {
            switch (c) {
                case '"' -> quoted.append("\\\"");
                case '\\' -> quoted.append("\\\\");
                case '\n' -> quoted.append("\\n");
                case '\r' -> quoted.append("\\r");
                case '\t' -> quoted.append("\\t");
                default -> {
                    if (c < 0x20) {
                        quoted.append(String.format(Locale.ROOT, "\\u%04x", (int) c));
                    } else {
                        quoted.append(c);
                    }
                }
            }
        }
        return quoted.append('"').toString();
    }
}
