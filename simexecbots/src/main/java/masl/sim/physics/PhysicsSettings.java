package masl.sim.physics;

/**
 * The physics settings of a simulation (components.md, "Scenario").
 *
 * @param stepSize         simulated seconds per step (fixed), &gt; 0
 * @param solverIterations quickStep iterations per step, &gt; 0
 * @param gravityX         gravity in m/s², world X
 * @param gravityY         gravity, world Y
 * @param gravityZ         gravity, world Z (the robot models are Z-up)
 * @param seed             seeds ode4j's constraint reordering, so lock-step runs repeat exactly
 * @param friction         Coulomb friction coefficient of every contact, ≥ 0
 * @param maxContacts      contact points kept per colliding geom pair, &gt; 0
 * @param realTimeFactor   in threaded mode, simulated seconds per wall-clock second; 0 runs as fast as possible
 */
public record PhysicsSettings(double stepSize, int solverIterations, double gravityX, double gravityY, double gravityZ,
        long seed, double friction, int maxContacts, double realTimeFactor) {

    /** @throws IllegalArgumentException when a setting is out of range */
    public PhysicsSettings {
        if (!(stepSize > 0) || solverIterations <= 0 || !(friction >= 0) || maxContacts <= 0 || !(realTimeFactor >= 0)) {
            throw new IllegalArgumentException("invalid physics settings: " + this);
        }
    }

    /** dt 0.01 s and 20 iterations (the figures of platform-notes.md), Z-up gravity, friction 1, real time. */
    public static PhysicsSettings defaults() {
        return new PhysicsSettings(0.01, 20, 0, 0, -9.81, 0, 1.0, 4, 1.0);
    }

    public PhysicsSettings withStepSize(double newStepSize) {
        return new PhysicsSettings(newStepSize, solverIterations, gravityX, gravityY, gravityZ, seed, friction, maxContacts, realTimeFactor);
    }

    public PhysicsSettings withGravity(double x, double y, double z) {
        return new PhysicsSettings(stepSize, solverIterations, x, y, z, seed, friction, maxContacts, realTimeFactor);
    }

    public PhysicsSettings withSeed(long newSeed) {
        return new PhysicsSettings(stepSize, solverIterations, gravityX, gravityY, gravityZ, newSeed, friction, maxContacts, realTimeFactor);
    }

    public PhysicsSettings withRealTimeFactor(double factor) {
        return new PhysicsSettings(stepSize, solverIterations, gravityX, gravityY, gravityZ, seed, friction, maxContacts, factor);
    }
}
