package masl.agents;

import masl.agents.robots.AtomHardware;

/**
 * A legged modular robot, MAAM-like atom (descriptor {@code MaamAtom.xml}): four legs
 * ({@link #FRONT}, {@link #BACK}, {@link #LEFT}, {@link #RIGHT}), each with two position-servoed
 * joints ({@link #SWING}: foot forward/back; {@link #LIFT}: foot up/down), a ground contact
 * sensor per foot, and a latch per foot that attaches it to a neighbour atom's foot. The
 * primitives act on the {@link AtomHardware} the launcher attaches before the mission starts.
 */
public class MaamAtom extends Default {

    public static final int LEGS = 4;
    public static final int FRONT = 0;
    public static final int BACK = 1;
    public static final int LEFT = 2;
    public static final int RIGHT = 3;
    public static final int SWING = 0;
    public static final int LIFT = 1;

    private volatile AtomHardware body;

    /**
     * Gives the atom its hardware; called once by the launcher, before the mission starts.
     *
     * @throws IllegalStateException when hardware is already attached
     */
    public final void attachHardware(AtomHardware hardware) {
        if (hardware == null) {
            throw new NullPointerException("hardware");
        }
        if (body != null) {
            throw new IllegalStateException("atom hardware already attached");
        }
        body = hardware;
    }

    /** Sets the target angle (rad) of joint {@code joint} of leg {@code leg}. */
    public void setJoint(int leg, int joint, double angle) {
        body().setServoTarget(checkLeg(leg), checkJoint(joint), angle);
    }

    /** The current angle (rad) of a leg's joint. */
    public double getJoint(int leg, int joint) {
        return body().servoAngle(checkLeg(leg), checkJoint(joint));
    }

    /** Whether the leg's foot is on the ground. */
    public boolean isOnGround(int leg) {
        return body().footOnGround(checkLeg(leg));
    }

    /** Latches the foot of {@code leg} to the foot of {@code neighbourLeg} of atom {@code neighbour}. */
    public boolean attach(int leg, int neighbour, int neighbourLeg) {
        return body().attach(checkLeg(leg), neighbour, checkLeg(neighbourLeg));
    }

    /** Releases the latch of the foot of {@code leg}. */
    public void detach(int leg) {
        body().detach(checkLeg(leg));
    }

    /** Whether the foot of {@code leg} is latched to a neighbour. */
    public boolean isAttached(int leg) {
        return body().attached(checkLeg(leg));
    }

    private AtomHardware body() {
        AtomHardware attached = body;
        if (attached == null) {
            throw new IllegalStateException("atom " + getProxyID() + " has no hardware attached");
        }
        return attached;
    }

    private static int checkLeg(int leg) {
        if (leg < 0 || leg >= LEGS) {
            throw new IndexOutOfBoundsException("leg " + leg + " (an atom has legs 0 to " + (LEGS - 1) + ")");
        }
        return leg;
    }

    private static int checkJoint(int joint) {
        if (joint != SWING && joint != LIFT) {
            throw new IndexOutOfBoundsException("joint " + joint + " (a leg has joints SWING=0 and LIFT=1)");
        }
        return joint;
    }
}
