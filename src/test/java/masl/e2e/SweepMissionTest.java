package masl.e2e;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * The sweep mission: {@code missions/sweep.masl}, four wheeled robots sweeping four lanes through
 * {@code masl run --sim}, lock-step. One robot fails mid-lane (in the second scenario, the leader):
 * the whole arena is still swept, the failed robot's lane by another robot, and the trace shows the
 * failed robot dropping out, the lead passing on, and the leader asking the robot it re-elects the
 * lane to where it is.
 */
@Tag("slow")
class SweepMissionTest {

    private static final Path MISSIONS = Path.of(System.getProperty("user.dir")).resolve("missions");
    /** The lanes of sweep.masl: along +X from 0 to END, lane i at y = WIDTH * i. */
    private static final int LANES = 4;
    private static final double END = 1.0;
    private static final double WIDTH = 0.25;
    /** The hull's half length, and where its centre lies ahead of the centre of mass (wheeled-robot.xode). */
    private static final double HALF_HULL = 0.05;
    private static final double HULL_AHEAD = 0.0045;
    /** The largest stretch of a lane no hull passed over: where a robot stopped short of a failed one. */
    private static final double GAP = 0.03;
    /** A robot's control tick in sweep.masl (simulated nanoseconds). */
    private static final long TICK = 50_000_000;
    private static final Pattern REELECTED = Pattern.compile("leader k(\\d): lane (\\d) re-elected to k(\\d)");
    private static final Pattern TRACE = Pattern.compile(
            "\\{\"nanos\":(\\d+),\"event\":\"(entered|left)\",\"agent\":(\\d),\"block\":\"(\\w+)\".*");

    @TempDir
    Path folder;

    /** Each scenario with its own seed and with another (the schedule decides who gets the orphaned lane). */
    @ParameterizedTest(name = "{0}, seed {1}")
    @CsvSource({"sweep-fault, 21, 2, 4.0, 0", "sweep-fault, 7, 2, 4.0, 0",
        "sweep-leader-fault, 21, 0, 3.0, 1", "sweep-leader-fault, 7, 0, 3.0, 1"})
    void theArenaIsSweptAndTheFailedRobotsLaneIsDoneByAnother(String name, int seed, int failed, double faultTime,
            int leaderAfter) throws Exception {
        String journal = masl(MISSIONS.resolve(name + ".scenario.xml"), seed, folder);
        Trajectories trajectories = Trajectories.read(folder.resolve("trajectories.csv"));

        for (int lane = 0; lane < LANES; lane++) {
            double gap = largestGap(trajectories, lane, List.of("k0", "k1", "k2", "k3"));
            assertTrue(gap <= GAP, "lane " + lane + " has an unswept stretch of " + gap + " m");
        }
        Matcher reelected = REELECTED.matcher(journal);
        assertTrue(reelected.find(), journal);
        assertEquals(failed, Integer.parseInt(reelected.group(2)), journal);
        String rescuer = "k" + reelected.group(3);
        assertNotEquals("k" + failed, rescuer);
        assertTrue(largestGap(trajectories, failed, List.of("k" + failed)) > 0.3,
                "the failed robot swept its lane before the fault");
        assertTrue(largestGap(trajectories, failed, List.of("k" + failed, rescuer)) <= GAP,
                "the failed robot and " + rescuer + " left a stretch of lane " + failed + " unswept");
        assertTrue(journal.contains("k" + failed + " failed and dropped out\n"), journal);
        assertTrue(journal.endsWith("4 of 4 lanes swept, 4.0 of 4.0 m\n"), journal);

        List<String[]> trace = membership(folder.resolve("trace.jsonl"));
        long fault = Math.round(faultTime * 1e9);
        long lastTick = trace.stream().filter(e -> is(e, "entered", failed, "robot"))
                .mapToLong(SweepMissionTest::nanos).max().orElseThrow();
        assertTrue(lastTick >= fault && lastTick <= fault + TICK,
                "the failed robot's last tick (in which it reads its battery and drops out) at " + lastTick + " ns");
        assertTrue(trace.stream().anyMatch(e -> is(e, "left", failed, "main") && nanos(e) >= fault),
                "the failed robot did not leave the mission after its fault");
        List<Integer> leadersAfter = trace.stream().filter(e -> e[1].equals("entered") && e[3].equals("lead")
                && nanos(e) > fault).map(e -> Integer.parseInt(e[2])).distinct().toList();
        assertEquals(List.of(leaderAfter), leadersAfter, "leaders after the fault");
        assertEquals(leaderAfter == 0 ? List.of("k0 leads") : List.of("k0 leads", "k" + leaderAfter + " leads"),
                journal.lines().filter(line -> line.endsWith(" leads")).toList());
        String asked = "\"event\":\"invocation-served\",\"requester\":" + leadersAfter.get(0) + ",\"callee\":"
                + reelected.group(3) + ",\"member\":\"getY\"";
        assertTrue(Files.readAllLines(folder.resolve("trace.jsonl")).stream().anyMatch(line -> line.contains(asked)),
                "the leader did not ask " + rescuer + " where it is");
    }

    /**
     * The longest stretch of lane {@code lane}, from its start to its end, over which no hull of
     * {@code robots} passed while driving along the lane.
     */
    private static double largestGap(Trajectories trajectories, int lane, List<String> robots) {
        List<double[]> swept = new ArrayList<>();
        for (String robot : robots) {
            for (Trajectories.Sample sample : trajectories.of(robot)) {
                double x = sample.x() + HULL_AHEAD * Math.cos(sample.heading());
                double y = sample.y() + HULL_AHEAD * Math.sin(sample.heading());
                boolean alongTheLane = Math.abs(Math.sin(sample.heading())) < 0.25;
                if (alongTheLane && Math.abs(y - WIDTH * lane) < HALF_HULL) {
                    swept.add(new double[] {x - HALF_HULL, x + HALF_HULL});
                }
            }
        }
        swept.sort(Comparator.comparingDouble(interval -> interval[0]));
        double covered = 0;
        double gap = 0;
        for (double[] interval : swept) {
            gap = Math.max(gap, interval[0] - covered);
            covered = Math.max(covered, interval[1]);
        }
        return Math.max(gap, END - covered);
    }

    /** The trace's membership events as {nanos, entered|left, agent, block}. */
    private static List<String[]> membership(Path trace) throws Exception {
        List<String[]> events = new ArrayList<>();
        for (String line : Files.readAllLines(trace)) {
            Matcher matcher = TRACE.matcher(line);
            if (matcher.matches()) {
                events.add(new String[] {matcher.group(1), matcher.group(2), matcher.group(3), matcher.group(4)});
            }
        }
        return events;
    }

    private static boolean is(String[] event, String kind, int agent, String block) {
        return event[1].equals(kind) && Integer.parseInt(event[2]) == agent && event[3].equals(block);
    }

    private static long nanos(String[] event) {
        return Long.parseLong(event[0]);
    }

    private static String masl(Path scenario, int seed, Path out) {
        MaslCommand run = MaslCommand.run("run", "--sim", scenario.toString(), "--seed", String.valueOf(seed), "--out", out.toString(),
                        "--timeout", "120");
        assertEquals(0, run.status(), run::err);
        return run.out();
    }
}
