package masl.sim.scenario;

import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.NoSuchElementException;
import masl.sim.output.RunRecorder;
import masl.sim.physics.PhysicsWorld;

/**
 * One run of a scenario as its initialisation class and its caller see it: the physics world, the
 * robots by agent name, and the recorder of trajectories and events.
 */
public final class Simulation {

    private final Scenario scenario;
    private final PhysicsWorld world;
    private final Map<String, SimulatedRobot> robots;
    private final RunRecorder recorder;

    Simulation(Scenario scenario, PhysicsWorld world, List<SimulatedRobot> robots, RunRecorder recorder) {
        this.scenario = scenario;
        this.world = world;
        Map<String, SimulatedRobot> byName = new LinkedHashMap<>();
        robots.forEach(robot -> byName.put(robot.name(), robot));
        this.robots = Collections.unmodifiableMap(byName);
        this.recorder = recorder;
    }

    public Scenario scenario() {
        return scenario;
    }

    public PhysicsWorld world() {
        return world;
    }

    /** The robot agents by MASL name, in proxy id order. */
    public Map<String, SimulatedRobot> robots() {
        return robots;
    }

    /** @throws NoSuchElementException when no robot agent has that name */
    public SimulatedRobot robot(String name) {
        SimulatedRobot robot = robots.get(name);
        if (robot == null) {
            throw new NoSuchElementException("no robot agent named '" + name + "' (robots: " + robots.keySet() + ")");
        }
        return robot;
    }

    public RunRecorder recorder() {
        return recorder;
    }
}
