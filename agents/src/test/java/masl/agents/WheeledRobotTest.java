package masl.agents;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import masl.agents.robots.AtomHardware;
import masl.agents.robots.DifferentialDrive;
import org.junit.jupiter.api.Test;

/** The robot classes pass primitives on to their hardware, clipped and checked. */
class WheeledRobotTest {

    /** Records the last wheel speeds; reads return fixed values. */
    private static final class RecordingDrive implements DifferentialDrive {
        double left = Double.NaN;
        double right = Double.NaN;

        @Override
        public void setWheelSpeeds(double l, double r) {
            left = l;
            right = r;
        }

        @Override
        public double proximity(int sensor) {
            return sensor * 0.01;
        }

        @Override
        public double[] odometry() {
            return new double[] {1, 2, 3};
        }

        @Override
        public double battery() {
            return 0.5;
        }
    }

    @Test
    void wheelSpeedsAreClippedToTheMaximum() {
        WheeledRobot robot = new WheeledRobot();
        RecordingDrive drive = new RecordingDrive();
        robot.attachHardware(drive);
        robot.setSpeeds(25, -3);
        assertArrayEquals(new double[] {WheeledRobot.MAX_WHEEL_SPEED, -3}, new double[] {drive.left, drive.right});
        robot.stop();
        assertArrayEquals(new double[] {0, 0}, new double[] {drive.left, drive.right});
        assertThrows(IllegalArgumentException.class, () -> robot.setSpeeds(Double.NaN, 0));
    }

    @Test
    void readsComeFromTheHardware() {
        WheeledRobot robot = new WheeledRobot();
        robot.attachHardware(new RecordingDrive());
        assertEquals(0.03, robot.getProximity(3), 1e-12);
        assertEquals(1, robot.getX());
        assertEquals(2, robot.getY());
        assertEquals(3, robot.getHeading());
        assertEquals(0.5, robot.getBattery());
    }

    @Test
    void hardwareIsAttachedOnce() {
        WheeledRobot robot = new WheeledRobot();
        robot.attachHardware(new RecordingDrive());
        assertThrows(IllegalStateException.class, () -> robot.attachHardware(new RecordingDrive()));
    }

    @Test
    void sensorAnglesRunFromLeftToRightThenBack() {
        assertEquals(Math.PI / 2, WheeledRobot.sensorAngle(0), 1e-12);
        assertEquals(-Math.PI / 2, WheeledRobot.sensorAngle(5), 1e-12);
        assertThrows(IndexOutOfBoundsException.class, () -> WheeledRobot.sensorAngle(8));
    }

    @Test
    void atomChecksLegAndJointNumbers() {
        MaamAtom atom = new MaamAtom();
        atom.attachHardware(new AtomHardware() {
            @Override
            public void setServoTarget(int leg, int joint, double angle) {
            }

            @Override
            public double servoAngle(int leg, int joint) {
                return leg * 10 + joint;
            }

            @Override
            public boolean footOnGround(int leg) {
                return leg == MaamAtom.LEFT;
            }

            @Override
            public boolean attach(int leg, int neighbour, int neighbourLeg) {
                return true;
            }

            @Override
            public void detach(int leg) {
            }

            @Override
            public boolean attached(int leg) {
                return false;
            }
        });
        assertEquals(31, atom.getJoint(MaamAtom.RIGHT, MaamAtom.LIFT));
        assertEquals(true, atom.isOnGround(MaamAtom.LEFT));
        assertThrows(IndexOutOfBoundsException.class, () -> atom.setJoint(4, 0, 0));
        assertThrows(IndexOutOfBoundsException.class, () -> atom.getJoint(0, 2));
        assertThrows(IndexOutOfBoundsException.class, () -> atom.attach(0, 1, -1));
    }
}
