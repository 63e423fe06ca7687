package masl.sim.robots;

import java.util.HashMap;
import java.util.Map;
import masl.agents.MaamAtom;
import masl.agents.robots.AtomHardware;
import masl.sim.physics.BodyPose;
import masl.sim.physics.MotorCommand;
import masl.sim.physics.PhysicsWorld;
import masl.sim.xode.Pose;
import masl.sim.xode.XodeException;
import masl.sim.xode.XodeSource;

/**
 * The body of a {@link MaamAtom} in a {@link PhysicsWorld}: {@code maam-atom.xode} loaded with a
 * prefix. Servo targets become {@link MotorCommand.Servo} commands; ground contact is whether the
 * leg touched something static in the latest step; a latch is a fixed joint between two feet,
 * made only when they are at most {@link #LATCH_REACH} apart.
 *
 * <p>Thread-safe. Latches of all atoms of a world share one {@link Latches} table, so both atoms
 * of a latch always agree on it.
 */
public final class SimulatedAtom implements AtomHardware {

    public static final XodeSource BODY = XodeSource.resource("masl/agents/robots/maam-atom.xode");
    /** Largest distance (m) between two foot tips that can latch. */
    public static final double LATCH_REACH = 0.03;
    /** Servo loop: gain (1/s), speed limit (rad/s), torque limit (N·m). */
    static final double SERVO_GAIN = 10;
    static final double SERVO_SPEED = 3;
    static final double SERVO_TORQUE = 2;
    /** From a leg body's centre down to its foot tip (half the capsule plus its cap). */
    static final double FOOT_BELOW_CENTRE = 0.038;
    /** A foot is on the ground if it touched it in one of this many latest steps. */
    static final int CONTACT_DEBOUNCE_STEPS = 5;
    private static final String[] LEG_NAMES = {"front", "back", "left", "right"};
    private static final String[] JOINT_NAMES = {"Swing", "Lift"};

    /**
     * The latches of one world: who is latched to whom, and the atoms by proxy id. Atoms are
     * registered by the launcher once it knows their proxy ids.
     */
    public static final class Latches {
        /** Told of every latch made or released, while the latches' lock is held. */
        @FunctionalInterface
        public interface Listener {
            /** @param foot the leg body of the atom that acted, e.g. {@code a0.frontLeg} */
            void changed(boolean attached, String foot, String otherFoot);
        }

        private final Map<Integer, SimulatedAtom> atoms = new HashMap<>();
        private final Map<String, String> jointOfFoot = new HashMap<>();
        private final Listener listener;

        /** Latches nobody listens to. */
        public Latches() {
            this((attached, foot, otherFoot) -> { });
        }

        public Latches(Listener listener) {
            this.listener = listener;
        }

        /** Makes {@code atom} reachable as the neighbour with proxy id {@code proxyId}. */
        public synchronized void register(int proxyId, SimulatedAtom atom) {
            atoms.put(proxyId, atom);
        }

        synchronized SimulatedAtom atom(int proxyId) {
            return atoms.get(proxyId);
        }
    }

    private final PhysicsWorld world;
    private final String prefix;
    private final Latches latches;

    private SimulatedAtom(PhysicsWorld world, String prefix, Latches latches) {
        this.world = world;
        this.prefix = prefix;
        this.latches = latches;
    }

    /**
     * Loads an atom into {@code world} under {@code prefix}, standing at ({@code x}, {@code y}) on the
     * ground z = 0 and facing {@code heading}, with every servo holding its leg vertical.
     */
    public static SimulatedAtom load(PhysicsWorld world, String prefix, double x, double y, double heading, Latches latches)
            throws XodeException {
        return load(world, BODY, prefix, x, y, heading, latches);
    }

    /** Like {@link #load(PhysicsWorld, String, double, double, double, Latches)} with another body, named alike. */
    public static SimulatedAtom load(PhysicsWorld world, XodeSource body, String prefix, double x, double y, double heading,
            Latches latches) throws XodeException {
        world.load(body, prefix, Pose.axisAngle(0, 0, 1, heading).withTranslation(x, y, 0));
        SimulatedAtom atom = new SimulatedAtom(world, prefix, latches);
        for (int leg = 0; leg < MaamAtom.LEGS; leg++) {
            atom.setServoTarget(leg, MaamAtom.SWING, 0);
            atom.setServoTarget(leg, MaamAtom.LIFT, 0);
        }
        return atom;
    }

    /** The atom's central body, whose pose is the atom's. */
    public String mainBody() {
        return prefix + "atom";
    }

    /** The body of a leg, e.g. {@code a0.leftLeg}. */
    public String legBody(int leg) {
        return prefix + LEG_NAMES[leg] + "Leg";
    }

    @Override
    public void setServoTarget(int leg, int joint, double angle) {
        world.command(jointName(leg, joint), new MotorCommand.Servo(angle, SERVO_GAIN, SERVO_SPEED, SERVO_TORQUE));
    }

    @Override
    public double servoAngle(int leg, int joint) {
        return world.jointPosition(jointName(leg, joint));
    }

    @Override
    public boolean footOnGround(int leg) {
        return world.touchesEnvironment(legBody(leg), CONTACT_DEBOUNCE_STEPS);
    }

    @Override
    public boolean attach(int leg, int neighbour, int neighbourLeg) {
        synchronized (latches) {
            SimulatedAtom other = latches.atom(neighbour);
            if (other == null || other == this) {
                return false;
            }
            String mine = legBody(leg);
            String theirs = other.legBody(neighbourLeg);
            if (latches.jointOfFoot.containsKey(mine) || latches.jointOfFoot.containsKey(theirs)) {
                return false;
            }
            double[] a = footTip(mine);
            double[] b = footTip(theirs);
            if (Math.hypot(Math.hypot(a[0] - b[0], a[1] - b[1]), a[2] - b[2]) > LATCH_REACH) {
                return false;
            }
            String joint = "latch:" + mine + "+" + theirs;
            world.attachFixed(joint, mine, theirs);
            latches.jointOfFoot.put(mine, joint);
            latches.jointOfFoot.put(theirs, joint);
            latches.listener.changed(true, mine, theirs);
            return true;
        }
    }

    @Override
    public void detach(int leg) {
        synchronized (latches) {
            String mine = legBody(leg);
            String joint = latches.jointOfFoot.get(mine);
            if (joint != null) {
                world.detach(joint);
                String theirs = latches.jointOfFoot.entrySet().stream()
                        .filter(e -> e.getValue().equals(joint) && !e.getKey().equals(mine))
                        .map(Map.Entry::getKey).findFirst().orElseThrow();
                latches.jointOfFoot.remove(mine);
                latches.jointOfFoot.remove(theirs);
                latches.listener.changed(false, mine, theirs);
            }
        }
    }

    @Override
    public boolean attached(int leg) {
        synchronized (latches) {
            return latches.jointOfFoot.containsKey(legBody(leg));
        }
    }

    /** Where the foot of {@code leg} ends, in world coordinates. */
    double[] footTip(int leg) {
        return footTip(legBody(leg));
    }

    private double[] footTip(String legBody) {
        BodyPose pose = world.bodyPose(legBody);
        double[] down = pose.worldDirection(0, 0, -FOOT_BELOW_CENTRE);
        return new double[] {pose.x() + down[0], pose.y() + down[1], pose.z() + down[2]};
    }

    private String jointName(int leg, int joint) {
        return prefix + LEG_NAMES[leg] + JOINT_NAMES[joint];
    }
}
