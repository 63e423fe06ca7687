package masl.sim.scenario;

import java.util.Locale;
import masl.agents.WheeledRobot;
import masl.runtime.AgentContext;
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
