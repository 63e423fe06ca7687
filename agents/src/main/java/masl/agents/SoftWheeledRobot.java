package masl.agents;

/**
 * A wheeled robot simulated in software, without physics (descriptor {@code SoftWheeledRobot.xml}),
 * so that missions mixing robot types can be run and tested anywhere. Deterministic: its state
 * changes only through its primitives, never with time or chance.
 *
 * <ul>
 * <li>It starts at the origin, facing +X, its battery full, in a square arena whose walls stand at
 * ±{@link #ARENA_HALF_SIZE} on both axes.
 * <li>{@link #moveForward} and the turns are instantaneous; a move ends at a wall it meets (the
 * robot bumps and stays there). Positions are kept to the micrometre and headings in degrees, so
 * that four quarter turns or ten moves of 0.1 m give round numbers in a journal.
 * <li>The battery is counted in percent: every move costs {@link #MOVE_COST}, every turn
 * {@link #TURN_COST}, every calibration {@link #CALIBRATION_COST}. With an empty battery these
 * primitives throw {@link BatteryEmptyException} and do nothing.
 * <li>{@link #calibrate} (asynchronous) spins the compass a full turn in
 * {@link #CALIBRATION_STEPS} steps; {@link #abortCalibration}, its countermeasure, stops a
 * calibration in progress, which then returns false and leaves the robot uncalibrated.
 * </ul>
 *
 * <p>Primitives may be called from the agent's program and from asynchronous primitives at once:
 * the state is guarded by the object's monitor.
 */
public class SoftWheeledRobot extends Robot {

    /** Half the side of the square arena (m): walls at x = ±5 and y = ±5. */
    public static final double ARENA_HALF_SIZE = 5.0;
    /** Battery (percent) one {@link #moveForward} costs. */
    public static final int MOVE_COST = 5;
    /** Battery (percent) one turn costs. */
    public static final int TURN_COST = 1;
    /** Battery (percent) one {@link #calibrate} costs. */
    public static final int CALIBRATION_COST = 10;
    /** Steps of a calibration; an abort is seen between two steps. */
    public static final int CALIBRATION_STEPS = 36;

    private static final double MICROMETRE = 1e6;

    private double x;
    private double y;
    private double headingDegrees;
    private int charge = 100;
    private boolean calibrated;
    private boolean calibrating;
    private boolean abortRequested;
    private Runnable calibrationStep = () -> { };

    /**
     * Moves {@code distance} metres straight ahead (backwards when negative), or up to the wall in
     * the way. Returns the distance actually travelled, with the sign of {@code distance}.
     */
    public synchronized double moveForward(double distance) {
        requireFinite(distance, "distance");
        spend(MOVE_COST);
        double direction = distance < 0 ? headingDegrees + 180 : headingDegrees;
        double travelled = Math.min(Math.abs(distance), distanceToWall(direction));
        x = micrometres(x + travelled * cosDegrees(direction));
        y = micrometres(y + travelled * sinDegrees(direction));
        // 0.0 - d rather than -d: a move that went nowhere reads 0.0, never -0.0.
        return distance < 0 ? 0.0 - micrometres(travelled) : micrometres(travelled);
    }

    /** Turns on the spot by {@code degrees} counter-clockwise (clockwise when negative). */
    public synchronized void turnLeft(double degrees) {
        requireFinite(degrees, "degrees");
        spend(TURN_COST);
        headingDegrees = normalised(headingDegrees + degrees);
    }

    /** Turns on the spot by {@code degrees} clockwise. */
    public void turnRight(double degrees) {
        turnLeft(-degrees);
    }

    @Override
    public synchronized double getX() {
        return x;
    }

    @Override
    public synchronized double getY() {
        return y;
    }

    /** Both coordinates read at once, never half-way through a move another thread makes. */
    @Override
    public synchronized Position getPosition() {
        return new Position(x, y);
    }

    @Override
    public synchronized double getHeading() {
        return Math.toRadians(headingDegrees);
    }

    /** Heading in degrees, counter-clockwise from +X, in (−180, 180]. */
    public synchronized double getHeadingDegrees() {
        return headingDegrees;
    }

    @Override
    public synchronized double getBattery() {
        return charge / 100.0;
    }

    /**
     * Calibrates the compass: a full turn of it in {@link #CALIBRATION_STEPS} steps (the robot itself
     * does not move). Returns true once done, false if {@link #abortCalibration} stopped it.
     *
     * @throws IllegalStateException when a calibration is already in progress
     * @throws BatteryEmptyException when the battery is empty
     */
    public boolean calibrate() {
        synchronized (this) {
            if (calibrating) {
                throw new IllegalStateException("a calibration is already in progress");
            }
            spend(CALIBRATION_COST);
            calibrating = true;
            calibrated = false;
            abortRequested = false;
        }
        try {
            for (int step = 0; step < CALIBRATION_STEPS; step++) {
                calibrationStep.run();
                synchronized (this) {
                    if (abortRequested) {
                        return false;
                    }
                }
            }
            synchronized (this) {
                calibrated = true;
                return true;
            }
        } finally {
            synchronized (this) {
                calibrating = false;
            }
        }
    }

    /**
     * The countermeasure of {@link #calibrate}: stops a calibration in progress (it returns false,
     * the robot stays uncalibrated). A finished calibration is kept: leaving the block that
     * launched it fires this countermeasure and must not undo a calibration that succeeded.
     */
    public synchronized void abortCalibration() {
        if (calibrating) {
            abortRequested = true;
        }
    }

    /** Whether the last calibration finished without being aborted. */
    public synchronized boolean isCalibrated() {
        return calibrated;
    }

    /** Runs {@code step} at each step of a calibration, before the abort check: tests pace calibrations with it. */
    final void onCalibrationStep(Runnable step) {
        calibrationStep = step;
    }

    /** Distance (m) from the robot to the arena wall it would meet going in {@code direction} (degrees). */
    final synchronized double distanceToWall(double direction) {
        double cos = cosDegrees(direction);
        double sin = sinDegrees(direction);
        double alongX = cos > 0 ? (ARENA_HALF_SIZE - x) / cos : cos < 0 ? (-ARENA_HALF_SIZE - x) / cos : Double.MAX_VALUE;
        double alongY = sin > 0 ? (ARENA_HALF_SIZE - y) / sin : sin < 0 ? (-ARENA_HALF_SIZE - y) / sin : Double.MAX_VALUE;
        return Math.max(0, Math.min(alongX, alongY));
    }

    private void spend(int cost) {
        if (charge == 0) {
            throw new BatteryEmptyException();
        }
        charge = Math.max(0, charge - cost);
    }

    static double micrometres(double metres) {
        return Math.round(metres * MICROMETRE) / MICROMETRE;
    }

    /** Cosine of an angle in degrees, exact at multiples of 90° so that axis-aligned moves stay on the axis. */
    static double cosDegrees(double degrees) {
        return sinDegrees(degrees + 90);
    }

    static double sinDegrees(double degrees) {
        double turn = normalised(degrees);
        if (turn % 90 == 0) {
            return turn == 90 ? 1 : turn == -90 ? -1 : 0;
        }
        return Math.sin(Math.toRadians(turn));
    }

    /** {@code degrees} brought into (−180, 180]. */
    static double normalised(double degrees) {
        double turn = degrees % 360;
        if (turn <= -180) {
            return turn + 360;
        }
        // + 0.0 turns −0.0 (from −360 % 360) into 0.0, which a journal shows as 0.0.
        return turn > 180 ? turn - 360 : turn + 0.0;
    }

    static void requireFinite(double value, String name) {
        if (!Double.isFinite(value)) {
            throw new IllegalArgumentException(name + " is " + value);
        }
    }
}
