package masl.agents;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

/** The soft robots' kinematics, arena, battery and calibration, on their own (no mission). */
class SoftWheeledRobotTest {

    @Test
    void squareOfQuarterTurnsComesBackToTheStartExactly() {
        SoftWheeledRobot robot = new SoftWheeledRobot();
        for (int side = 0; side < 4; side++) {
            assertEquals(2.0, robot.moveForward(2));
            robot.turnLeft(90);
        }
        assertEquals(new Position(0, 0), robot.getPosition());
        assertEquals(0.0, robot.getHeadingDegrees());
        assertEquals(1 - 4 * 0.05 - 4 * 0.01, robot.getBattery(), 1e-12);
        assertEquals(0.76, robot.getBattery());
    }

    @Test
    void positionsAreKeptToTheMicrometreSoSmallStepsAddUp() {
        SoftWheeledRobot robot = new SoftWheeledRobot();
        robot.turnLeft(90);
        for (int step = 0; step < 10; step++) {
            robot.moveForward(0.1);
        }
        assertEquals("(0.0, 1.0)", robot.getPosition().toString());
        assertEquals(Math.PI / 2, robot.getHeading());
    }

    @Test
    void headingsStayInMinus180To180() {
        SoftWheeledRobot robot = new SoftWheeledRobot();
        robot.turnRight(90);
        assertEquals(-90.0, robot.getHeadingDegrees());
        robot.turnRight(90);
        assertEquals(180.0, robot.getHeadingDegrees());
        robot.turnLeft(540);
        assertEquals(0.0, robot.getHeadingDegrees());
        assertEquals("0.0", String.valueOf(robot.getHeadingDegrees()));
        robot.turnLeft(45);
        robot.moveForward(Math.sqrt(2));
        assertEquals(new Position(1, 1), robot.getPosition());
    }

    @Test
    void aMoveEndsAtTheArenaWallAndSaysHowFarItWent() {
        SoftWheeledRobot robot = new SoftWheeledRobot();
        assertEquals(5.0, robot.moveForward(20));
        assertEquals(0.0, robot.moveForward(1));
        assertEquals(-10.0, robot.moveForward(-30));
        assertEquals(new Position(-5, 0), robot.getPosition());
        assertThrows(IllegalArgumentException.class, () -> robot.moveForward(Double.NaN));
        assertThrows(IllegalArgumentException.class, () -> robot.turnLeft(Double.POSITIVE_INFINITY));
    }

    @Test
    void anEmptyBatteryRefusesMotionAndTheRobotStaysPut() {
        SoftWheeledRobot robot = new SoftWheeledRobot();
        for (int move = 0; move < 20; move++) {
            robot.moveForward(0.1);
        }
        assertEquals(0.0, robot.getBattery());
        assertThrows(BatteryEmptyException.class, () -> robot.moveForward(1));
        assertThrows(BatteryEmptyException.class, () -> robot.turnLeft(1));
        assertThrows(BatteryEmptyException.class, robot::calibrate);
        assertEquals(new Position(2, 0), robot.getPosition());
    }

    @Test
    void calibrationSucceedsWithoutMovingTheRobot() {
        SoftWheeledRobot robot = new SoftWheeledRobot();
        assertFalse(robot.isCalibrated());
        assertTrue(robot.calibrate());
        assertTrue(robot.isCalibrated());
        assertEquals(new Position(0, 0), robot.getPosition());
        assertEquals(0.9, robot.getBattery());
        robot.abortCalibration();
        assertTrue(robot.isCalibrated(), "the countermeasure fired after a calibration keeps it");
    }

    @Test
    void abortStopsACalibrationInProgress() throws Exception {
        SoftWheeledRobot robot = new SoftWheeledRobot();
        CountDownLatch inProgress = new CountDownLatch(1);
        CountDownLatch aborted = new CountDownLatch(1);
        robot.onCalibrationStep(() -> {
            inProgress.countDown();
            await(aborted);
        });
        CompletableFuture<Boolean> calibration = CompletableFuture.supplyAsync(robot::calibrate);
        assertTrue(inProgress.await(10, TimeUnit.SECONDS));
        assertThrows(IllegalStateException.class, robot::calibrate, "one calibration at a time");
        robot.abortCalibration();
        aborted.countDown();
        assertFalse(calibration.get(10, TimeUnit.SECONDS));
        assertFalse(robot.isCalibrated());
        robot.onCalibrationStep(() -> { });
        assertTrue(robot.calibrate(), "a new calibration may start after an aborted one");
    }

    @Test
    void aScoutStopsShortOfTheWallAndScansIt() {
        Scout scout = new Scout();
        assertEquals(5.0, scout.scan());
        assertEquals(4.5, scout.moveForward(20));
        assertEquals(0.5, scout.scan());
        assertEquals(0.0, scout.moveForward(1));
        scout.turnLeft(90);
        assertEquals(5.0, scout.scan());
        assertEquals(-4.5, scout.moveForward(-7));
        assertEquals(new Position(4.5, -4.5), scout.getPosition());
        assertEquals(0.84, scout.getBattery());
    }

    @Test
    void aRobotWithoutADriveStaysAtTheOriginWithAFullBattery() {
        Robot robot = new Robot();
        robot.stop();
        assertEquals(new Position(0, 0), robot.getPosition());
        assertEquals(0.0, robot.getHeading());
        assertEquals(1.0, robot.getBattery());
        assertEquals(Math.sqrt(2), new Position(1, 1).distanceTo(new Position(2, 2)), 1e-15);
    }

    private static void await(CountDownLatch latch) {
        try {
            assertTrue(latch.await(10, TimeUnit.SECONDS));
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException(e);
        }
    }
}
