package masl.sim.scenario;

import java.util.Locale;
import masl.agents.WheeledRobot;
import masl.runtime.AgentContext;
import masl.runtime.Arrival;
import masl.runtime.EntryDefinition;
import masl.runtime.Mode;
import masl.runtime.AgentImplementation;
import masl.runtime.AgentProgram;

/** Agent programs written against the generated-code contract, as the translator would emit them. */
final class RobotPrograms {

    private RobotPrograms() {
    }

    /** {@code setSpeeds(left, right); sleep(ms); stop(); logln(odometry)}. */
    static AgentProgram driveThenStop(AgentImplementation implementation, double left, double right, long ms) {
        WheeledRobot robot = (WheeledRobot) implementation;
        return new AgentProgram() {
            @Override
            protected void resume(AgentContext ctx) {
                if (pc == 0) {
                    robot.setSpeeds(left, right);
                    pc = 1;
                    if (!ctx.sleep(ms)) {
                        return;
                    }
                }
                robot.stop();
                robot.logln(String.format(Locale.ROOT, "%d at %.3f %.3f", robot.getProxyID(), robot.getX(), robot.getY()));
                ctx.finish();
            }
        };
    }

    /**
     * Wanders for {@code rounds} rounds of 50 ms: drives forward, turns left on the spot while
     * something is closer than 6 cm in front; logs its odometry every 20 rounds.
     */
    static AgentProgram wander(AgentImplementation implementation, int rounds) {
        WheeledRobot robot = (WheeledRobot) implementation;
        return new AgentProgram() {
            private int round;

            @Override
            protected void resume(AgentContext ctx) {
                while (true) {
                    if (pc == 0) {
                        if (round == rounds) {
                            robot.stop();
                            ctx.finish();
                            return;
                        }
                        boolean blocked = Math.min(robot.getProximity(2), robot.getProximity(3)) < 0.06;
                        robot.setSpeeds(blocked ? -3 : 5, blocked ? 3 : 5);
                        if (round % 20 == 0) {
                            robot.logln(String.format(Locale.ROOT, "%d r%d %.4f %.4f", robot.getProxyID(), round,
                                    robot.getX(), robot.getY()));
                        }
                        round++;
                        pc = 1;
                        if (!ctx.stepBoundary()) {
                            return;
                        }
                    }
                    pc = 0;
                    if (!ctx.sleep(50)) {
                        return;
                    }
                }
            }
        };
    }

    /** The top-level block of {@link #wanderInStep}: synchronous, so its members move in lock-step rounds. */
    static final EntryDefinition TOGETHER = EntryDefinition.main("together", Mode.SYNCHRONOUS);

    /**
     * Like {@link #wander} inside the synchronous block {@link #TOGETHER}: every round ends at the
     * block's barrier, so the runtime trace records memberships and barrier trips.
     */
    static AgentProgram wanderInStep(AgentImplementation implementation, int rounds) {
        WheeledRobot robot = (WheeledRobot) implementation;
        return new AgentProgram() {
            private int round;

            @Override
            protected void resume(AgentContext ctx) {
                while (true) {
                    switch (pc) {
                        case 0 -> {
                            pc = 1;
                            Arrival arrival = ctx.enter(TOGETHER, true);
                            if (arrival == Arrival.WAITING) {
                                return;
                            }
                        }
                        case 1 -> {
                            boolean blocked = Math.min(robot.getProximity(2), robot.getProximity(3)) < 0.06;
                            robot.setSpeeds(blocked ? -3 : 5, blocked ? 3 : 5);
                            if (round % 20 == 0) {
                                robot.logln(String.format(Locale.ROOT, "%d r%d %.4f %.4f", robot.getProxyID(), round,
                                        robot.getX(), robot.getY()));
                            }
                            round++;
                            pc = 2;
                            if (!ctx.sleep(50)) {
                                return;
                            }
                        }
                        case 2 -> {
                            pc = round < rounds ? 1 : 3;
                            if (!ctx.stepBoundary()) {
                                return;
                            }
                        }
                        case 3 -> {
                            robot.stop();
                            pc = 4;
                            if (!ctx.leave(TOGETHER)) {
                                return;
                            }
                        }
                        default -> {
                            ctx.finish();
                            return;
                        }
                    }
                }
            }
        };
    }

    /** A software agent: logs once and finishes. */
    static AgentProgram hello(AgentImplementation implementation) {
        return new AgentProgram() {
            @Override
            protected void resume(AgentContext ctx) {
                ((masl.agents.Default) implementation).logln("hello from " + implementation.getClass().getSimpleName());
                ctx.finish();
            }
        };
    }
}
