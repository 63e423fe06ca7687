package masl.sim.scenario;

/**
 * A robot agent of a run: its MASL name, model, the name of the body whose pose is its
 * trajectory, and its simulated hardware ({@code masl.sim.robots.SimulatedWheeledRobot} or
 * {@code SimulatedAtom}).
 */
public record SimulatedRobot(String name, RobotModel model, String mainBody, Object hardware) {

    /** The hardware as the given class. @throws ClassCastException when it is another model's */
    public <T> T hardware(Class<T> type) {
        return type.cast(hardware);
    }
}
