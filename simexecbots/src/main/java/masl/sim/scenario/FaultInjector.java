package masl.sim.scenario;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import masl.sim.output.RunRecorder;
import masl.sim.physics.PhysicsWorld;
import masl.sim.robots.SimulatedWheeledRobot;

/**
 * After each step, injects the scenario's faults that are due and records the wheeled robots
 * whose battery has just run empty. Runs on the stepping thread only.
 */
final class FaultInjector implements PhysicsWorld.StepListener {

    private final Simulation simulation;
    private final RunRecorder recorder;
    private final List<Scenario.Fault> pending;
    private final Set<String> empty = new HashSet<>();

    FaultInjector(Simulation simulation, RunRecorder recorder) {
        this.simulation = simulation;
        this.recorder = recorder;
        this.pending = new ArrayList<>(simulation.scenario().faults());
    }

    @Override
    public void afterStep(PhysicsWorld world) {
        double now = world.simulatedTime();
        pending.removeIf(fault -> {
            if (now < fault.time() - 1e-9) {
                return false;
            }
            simulation.robot(fault.agent()).hardware(SimulatedWheeledRobot.class).fail();
            recorder.event(fault.agent(), "fault", "motors stopped, battery 0");
            return true;
        });
        for (SimulatedRobot robot : simulation.robots().values()) {
            if (robot.hardware() instanceof SimulatedWheeledRobot wheeled && wheeled.battery() <= 0
                    && empty.add(robot.name())) {
                recorder.event(robot.name(), "battery-empty", "");
            }
        }
    }
}
