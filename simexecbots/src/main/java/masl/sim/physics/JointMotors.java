package masl.sim.physics;

import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import org.ode4j.ode.DAMotorJoint;
import org.ode4j.ode.DHinge2Joint;
import org.ode4j.ode.DHingeJoint;
import org.ode4j.ode.DJoint;
import org.ode4j.ode.DSliderJoint;
import org.ode4j.ode.DUniversalJoint;

/**
 * Motor commands set by any thread and applied to joints by the stepping thread. A later
 * command for a joint replaces the earlier one; a command stays in force until replaced.
 */
final class JointMotors {

    private final Map<DJoint, MotorCommand> commands = new ConcurrentHashMap<>();

    /** @throws IllegalArgumentException when the joint has no motorised first axis */
    void command(DJoint joint, MotorCommand command) {
        if (!isMotorised(joint)) {
            throw new IllegalArgumentException("joint " + joint.getData() + " (" + joint.getClass().getSimpleName()
                    + ") has no motor: use a hinge, slider, hinge2, universal or amotor");
        }
        commands.put(joint, command);
    }

    /** Writes every command into its joint's motor parameters; call before each step, under the world lock. */
    void apply() {
        commands.forEach((joint, command) -> {
            double velocity;
            double maxForce;
            if (command instanceof MotorCommand.Velocity v) {
                velocity = v.velocity();
                maxForce = v.maxForce();
            } else {
                MotorCommand.Servo s = (MotorCommand.Servo) command;
                velocity = Math.max(-s.maxVelocity(), Math.min(s.maxVelocity(), s.gain() * (s.target() - position(joint))));
                maxForce = s.maxForce();
            }
            joint.setParam(DJoint.PARAM_N.dParamVel1, velocity);
            joint.setParam(DJoint.PARAM_N.dParamFMax1, maxForce);
        });
    }

    /** The joint's first-axis position: an angle in radians, or a distance for a slider. */
    static double position(DJoint joint) {
        if (joint instanceof DHingeJoint hinge) {
            return hinge.getAngle();
        } else if (joint instanceof DSliderJoint slider) {
            return slider.getPosition();
        } else if (joint instanceof DHinge2Joint hinge2) {
            return hinge2.getAngle1();
        } else if (joint instanceof DUniversalJoint universal) {
            return universal.getAngle1();
        } else if (joint instanceof DAMotorJoint motor) {
            return motor.getAngle(0);
        }
        throw new IllegalArgumentException("joint " + joint.getData() + " has no position");
    }

    private static boolean isMotorised(DJoint joint) {
        return joint instanceof DHingeJoint || joint instanceof DSliderJoint || joint instanceof DHinge2Joint
                || joint instanceof DUniversalJoint || joint instanceof DAMotorJoint;
    }
}
