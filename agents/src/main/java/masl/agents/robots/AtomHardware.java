package masl.agents.robots;

/**
 * The hardware of a MAAM-like atom as {@link masl.agents.MaamAtom} drives it: a body with
 * {@link masl.agents.MaamAtom#LEGS} legs, each moved by two position servos (joint
 * {@link masl.agents.MaamAtom#SWING} moves the foot forward and back, joint
 * {@link masl.agents.MaamAtom#LIFT} raises it), a ground contact sensor per foot, and a latch per
 * foot that fixes it to a neighbour's foot. Angles are radians; swing &gt; 0 moves the foot forward
 * (+X of the atom), lift &gt; 0 raises it away from the body's side.
 *
 * <p>Thread-safe; no method blocks waiting for the body (servo targets are reached later).
 */
public interface AtomHardware {

    /** Sets the target angle of a leg's servo, in force until changed; clipped to the joint's stops. */
    void setServoTarget(int leg, int joint, double angle);

    /** The servo's current angle. */
    double servoAngle(int leg, int joint);

    /** Whether the leg's foot touched the ground (anything static) during the latest physics step. */
    boolean footOnGround(int leg);

    /**
     * Fixes the foot of {@code leg} to the foot of {@code neighbourLeg} of the atom with proxy id
     * {@code neighbour}.
     *
     * @return false (and nothing changes) when that atom does not exist, the feet are too far apart,
     *         or either foot is already attached
     */
    boolean attach(int leg, int neighbour, int neighbourLeg);

    /** Releases the foot's latch, whichever side made it; a no-op when not attached. */
    void detach(int leg);

    /** Whether the foot is latched to a neighbour's foot. */
    boolean attached(int leg);
}
