package masl.e2e;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The mixed team mission: {@code missions/planner-team.masl}, three wheeled robots and a software
 * planner through {@code masl run --sim}, lock-step. Two boxes the robots do not know about stand
 * across the paths of k0 and k2; they report them to the planner by events, drive around them on
 * the way-points the planner returns to their asynchronous invocations (collected by labels), and
 * every robot ends at its goal without touching a box; and every run is the same, byte for byte.
 */
@Tag("slow")
class PlannerTeamMissionTest {

    private static final Path MISSIONS = Path.of(System.getProperty("user.dir")).resolve("missions");
    /** How close to its goal a robot's hull centre must end (m); the mission stops within 2 cm by odometry. */
    private static final double TOLERANCE = 0.05;
    /** The hull's centre ahead of the centre of mass, and the hull's half diagonal (wheeled-robot.xode). */
    private static final double HULL_AHEAD = 0.0045;
    private static final double HALF_DIAGONAL = Math.hypot(0.05, 0.035);
    /** The boxes of planner-arena.xode: centre x, centre y, half size. */
    private static final double[][] BOXES = {{0.8, 0.03, 0.1}, {1.0, 1.57, 0.1}};

    @TempDir
    Path folder;

    @Test
    void everyRobotReachesItsGoalAroundTheObstaclesItReported() throws Exception {
        String journal = masl(MISSIONS.resolve("planner-team.scenario.xml"), folder);
        Trajectories trajectories = Trajectories.read(folder.resolve("trajectories.csv"));

        double[][] goals = {{1.6, 0.0}, {1.6, 0.8}, {1.6, 1.6}};
        for (int robot = 0; robot < goals.length; robot++) {
            Trajectories.Sample end = trajectories.last("k" + robot);
            double x = end.x() + HULL_AHEAD * Math.cos(end.heading());
            double y = end.y() + HULL_AHEAD * Math.sin(end.heading());
            double miss = Math.hypot(x - goals[robot][0], y - goals[robot][1]);
            assertTrue(miss < TOLERANCE, "k" + robot + " ended " + miss + " m from its goal");
            assertTrue(journal.contains("k" + robot + " reached its goal"), journal);
            for (Trajectories.Sample sample : trajectories.of("k" + robot)) {
                for (double[] box : BOXES) {
                    double clearance = Math.max(Math.abs(sample.x() - box[0]), Math.abs(sample.y() - box[1])) - box[2];
                    assertTrue(clearance > HALF_DIAGONAL, "k" + robot + " touched a box at " + sample);
                }
            }
        }
        assertEquals(List.of("k0", "k2"), Pattern.compile("(k\\d) saw an obstacle").matcher(journal)
                .results().map(match -> match.group(1)).sorted().toList(), journal);
        assertTrue(journal.contains("), 1 known\n") && journal.contains("), 2 known\n"), journal);
    }

    /**
     * Lock-step is reproducible with asynchronous invocations too: the planner's {@code route} runs
     * as a task the simulator draws, so when each label finishes is the same in every run.
     */
    @Test
    void lockStepRunsAreByteIdenticalAlthoughTheRobotsLaunchPrimitives() throws Exception {
        List<String> runs = new ArrayList<>();
        for (int run = 0; run < 3; run++) {
            Path out = folder.resolve("run" + run);
            String journal = masl(MISSIONS.resolve("planner-team.scenario.xml"), out);
            runs.add(journal + "\n" + Files.readString(out.resolve("trajectories.csv")));
        }
        assertEquals(runs.get(0), runs.get(1));
        assertEquals(runs.get(0), runs.get(2));
    }

    private static String masl(Path scenario, Path out) {
        MaslCommand run = MaslCommand.run("run", "--sim", scenario.toString(), "--out", out.toString(), "--timeout", "120");
        assertEquals(0, run.status(), run::err);
        return run.out();
    }
}
