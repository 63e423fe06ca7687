package masl.sim.physics;

/**
 * What a caller asks of a joint's first axis; applied by the physics thread before each step.
 * Supported joints: hinge and slider (axis 1), hinge2 and universal (axis 1), amotor (axis 1).
 */
public sealed interface MotorCommand {

    /** Drive at {@code velocity} (rad/s or m/s) with at most {@code maxForce}. */
    record Velocity(double velocity, double maxForce) implements MotorCommand { }

    /**
     * Position servo: each step the motor velocity is {@code gain·(target − position)}, limited to
     * ±{@code maxVelocity}, with at most {@code maxForce}.
     */
    record Servo(double target, double gain, double maxVelocity, double maxForce) implements MotorCommand { }
}
