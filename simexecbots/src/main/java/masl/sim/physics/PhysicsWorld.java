package masl.sim.physics;

import java.time.Duration;
import java.util.HashSet;
import java.util.Map;
import java.util.NoSuchElementException;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.Condition;
import java.util.concurrent.locks.LockSupport;
import java.util.concurrent.locks.ReentrantLock;
import java.util.function.Supplier;
import masl.sim.xode.LoadTarget;
import masl.sim.xode.LoadedModel;
import masl.sim.xode.OdeRuntime;
import masl.sim.xode.Pose;
import masl.sim.xode.XodeException;
import masl.sim.xode.XodeLoader;
import masl.sim.xode.XodeSource;
import org.ode4j.math.DQuaternionC;
import org.ode4j.math.DVector3C;
import org.ode4j.ode.DBody;
import org.ode4j.ode.DHashSpace;
import org.ode4j.ode.DJoint;
import org.ode4j.ode.DJointGroup;
import org.ode4j.ode.DMisc;
import org.ode4j.ode.DWorld;
import org.ode4j.ode.OdeHelper;

/**
 * An ode4j world with its root hash space and contact group, stepped with {@code quickStep} at a
 * fixed step either by the caller ({@link #step()}, lock-step) or by its own thread
 * ({@link #start()}/{@link #stop()}).
 *
 * <p><b>Determinism.</b> In lock-step mode the same settings, the same loads and the same
 * commands at the same steps give the same trajectory bit for bit: ode4j's only randomness (the
 * constraint reordering of quickStep) is reseeded from the seed and the step number before every
 * step. That generator is global in ode4j, so steps of all worlds of a JVM are serialised.
 *
 * <p><b>Thread safety.</b> Every method may be called from any thread. One lock guards the ode4j
 * objects; a step holds it, and so do {@link #load}, {@link #bodyPose}, {@link #jointPosition} and
 * {@link #withLock}, so callers always see the state between two steps. Motor commands are
 * queued without the lock and take effect at the next step. Code that touches ode4j objects
 * directly (e.g. those of a {@link LoadedModel}) must do so inside {@link #withLock}.
 */
public final class PhysicsWorld implements AutoCloseable {

    /** Guards ode4j's global random generator (see class comment). */
    private static final Object ODE_GLOBAL_STATE = new Object();

    private final PhysicsSettings settings;
    private final ReentrantLock lock = new ReentrantLock();
    private final Condition stepped = lock.newCondition();
    private final DWorld world;
    private final DHashSpace space;
    private final DJointGroup contactJoints;
    private final ContactGenerator contacts;
    private final JointMotors motors = new JointMotors();
    private final XodeLoader loader;
    /** Concurrent so that commands can find their joint without waiting for a step to end. */
    private final Map<String, DBody> bodies = new ConcurrentHashMap<>();
    private final Map<String, DJoint> joints = new ConcurrentHashMap<>();
    private final Set<String> names = new HashSet<>();
    private volatile long steps;
    private volatile boolean running;
    private volatile Throwable failure;
    private Thread stepper;
    private boolean closed;

    public PhysicsWorld(PhysicsSettings settings) {
        this(settings, new XodeLoader());
    }

    /** @param loader used by {@link #load}, e.g. a strict one */
    public PhysicsWorld(PhysicsSettings settings, XodeLoader loader) {
        OdeRuntime.ensureInitialised();
        this.settings = settings;
        this.loader = loader;
        world = OdeHelper.createWorld();
        world.setGravity(settings.gravityX(), settings.gravityY(), settings.gravityZ());
        world.setQuickStepNumIterations(settings.solverIterations());
        // A thin allowed penetration keeps resting contacts from chattering between touching and not.
        world.setContactSurfaceLayer(0.001);
        space = OdeHelper.createHashSpace(null);
        contactJoints = OdeHelper.createJointGroup();
        contacts = new ContactGenerator(world, contactJoints, settings.friction(), settings.maxContacts());
    }

    public PhysicsSettings settings() {
        return settings;
    }

    /**
     * Loads an XODE document into this world, its names prefixed (e.g. {@code "khepera0."}).
     *
     * @throws XodeException when the document has errors, a (prefixed) name already loaded among
     *                       them; nothing is added then
     */
    public LoadedModel load(XodeSource source, String prefix) throws XodeException {
        return load(source, prefix, Pose.identity());
    }

    /**
     * Like {@link #load(XodeSource, String)}, with the document's root placed at {@code placement}
     * (a robot's initial pose).
     */
    public LoadedModel load(XodeSource source, String prefix, Pose placement) throws XodeException {
        lock.lock();
        try {
            checkOpen();
            LoadedModel model = loader.load(source, prefix,
                    LoadTarget.into(world, space).placedAt(placement).excludingNames(names));
            bodies.putAll(model.bodies());
            joints.putAll(model.joints());
            names.addAll(model.bodies().keySet());
            names.addAll(model.joints().keySet());
            names.addAll(model.geoms().keySet());
            return model;
        } finally {
            lock.unlock();
        }
    }

    /**
     * Advances the world by one step (lock-step mode).
     *
     * @throws IllegalStateException while the world runs on its own thread, or after {@link #close()}
     */
    public void step() {
        if (running) {
            throw new IllegalStateException("the world is stepping on its own thread; stop() it first");
        }
        lock.lock();
        try {
            checkOpen();
            stepLocked();
        } finally {
            lock.unlock();
        }
    }

    /** {@link #step()} {@code count} times. */
    public void step(int count) {
        for (int i = 0; i < count; i++) {
            step();
        }
    }

    /** Simulated seconds since creation: steps taken × step size. */
    public double simulatedTime() {
        return steps * settings.stepSize();
    }

    public long stepCount() {
        return steps;
    }

    /**
     * Starts stepping on a thread of its own, paced by the settings' real-time factor.
     *
     * @throws IllegalStateException when already running or closed
     */
    public synchronized void start() {
        if (stepper != null) {
            throw new IllegalStateException("already running");
        }
        lock.lock();
        try {
            checkOpen();
        } finally {
            lock.unlock();
        }
        failure = null;
        running = true;
        stepper = new Thread(this::runSteps, "masl-physics");
        stepper.setDaemon(true);
        stepper.start();
    }

    /**
     * Stops the stepping thread and waits until it has ended; a no-op when not running.
     *
     * @throws IllegalStateException when the thread died of an exception (the cause)
     */
    public synchronized void stop() {
        if (stepper == null) {
            return;
        }
        running = false;
        LockSupport.unpark(stepper);
        boolean interrupted = false;
        while (stepper.isAlive()) {
            try {
                stepper.join();
            } catch (InterruptedException e) {
                interrupted = true;
            }
        }
        stepper = null;
        if (interrupted) {
            Thread.currentThread().interrupt();
        }
        if (failure != null) {
            throw new IllegalStateException("the physics thread failed", failure);
        }
    }

    public boolean isRunning() {
        return running;
    }

    /**
     * Waits until the simulated time reaches {@code time} or the wall-clock {@code timeout} passes.
     *
     * @return whether the time was reached (false also when the world is not running)
     * @throws InterruptedException when interrupted while waiting
     */
    public boolean awaitSimulatedTime(double time, Duration timeout) throws InterruptedException {
        long remaining = timeout.toNanos();
        lock.lock();
        try {
            while (simulatedTime() < time && running && remaining > 0) {
                remaining = stepped.awaitNanos(remaining);
            }
            return simulatedTime() >= time;
        } finally {
            lock.unlock();
        }
    }

    /**
     * Sets a joint's motor command (velocity or position servo), in force from the next step
     * until replaced. Does not wait for the lock.
     *
     * @throws NoSuchElementException   when no loaded joint has that name
     * @throws IllegalArgumentException when the joint has no motor
     */
    public void command(String jointName, MotorCommand command) {
        motors.command(joint(jointName), command);
    }

    /** Shorthand for a {@link MotorCommand.Velocity} command. */
    public void driveJoint(String jointName, double velocity, double maxForce) {
        command(jointName, new MotorCommand.Velocity(velocity, maxForce));
    }

    /** A copy of a body's pose between steps. @throws NoSuchElementException for an unknown body */
    public BodyPose bodyPose(String bodyName) {
        return withLock(() -> {
            DBody body = lookup(bodies, bodyName, "body");
            DVector3C p = body.getPosition();
            DQuaternionC q = body.getQuaternion();
            return new BodyPose(p.get0(), p.get1(), p.get2(), q.get0(), q.get1(), q.get2(), q.get3());
        });
    }

    /** The names of all loaded bodies (a copy). */
    public Set<String> bodyNames() {
        return Set.copyOf(bodies.keySet());
    }

    /** A joint's first-axis position (angle in radians; slider: metres) between steps. */
    public double jointPosition(String jointName) {
        return withLock(() -> JointMotors.position(lookup(joints, jointName, "joint")));
    }

    /** Runs {@code action} between two steps with exclusive access to the ode4j objects. */
    public <T> T withLock(Supplier<T> action) {
        lock.lock();
        try {
            return action.get();
        } finally {
            lock.unlock();
        }
    }

    /** Stops the thread if running and destroys the ode4j world; later calls but this one fail. */
    @Override
    public void close() {
        try {
            stop();
        } finally {
            lock.lock();
            try {
                if (!closed) {
                    closed = true;
                    contactJoints.destroy();
                    space.destroy();
                    world.destroy();
                }
            } finally {
                lock.unlock();
            }
        }
    }

    private void runSteps() {
        long stepNanos = settings.realTimeFactor() > 0 ? (long) (settings.stepSize() / settings.realTimeFactor() * 1e9) : 0;
        long next = System.nanoTime();
        try {
            while (running) {
                lock.lock();
                try {
                    stepLocked();
                } finally {
                    lock.unlock();
                }
                if (stepNanos > 0) {
                    next += stepNanos;
                    long wait = next - System.nanoTime();
                    if (wait > 0) {
                        LockSupport.parkNanos(wait);
                    } else if (-wait > TimeUnit.SECONDS.toNanos(1)) {
                        // Far behind real time (a slow machine): do not race to catch up a whole backlog.
                        next = System.nanoTime();
                    }
                }
            }
        } catch (RuntimeException | Error e) {
            failure = e;
        } finally {
            lock.lock();
            try {
                running = false;
                stepped.signalAll();
            } finally {
                lock.unlock();
            }
        }
    }

    private void stepLocked() {
        motors.apply();
        synchronized (ODE_GLOBAL_STATE) {
            DMisc.dRandSetSeed(stepSeed());
            contacts.collide(space);
            world.quickStep(settings.stepSize());
        }
        contactJoints.empty();
        steps++;
        stepped.signalAll();
    }

    /** A different reordering per step, fixed by seed and step number; ODE's generator keeps 32 bits. */
    private long stepSeed() {
        long mixed = settings.seed() * 0x9E3779B97F4A7C15L + steps;
        mixed ^= mixed >>> 31;
        return mixed & 0xFFFFFFFFL;
    }

    private DJoint joint(String name) {
        return lookup(joints, name, "joint");
    }

    private void checkOpen() {
        if (closed) {
            throw new IllegalStateException("the physics world is closed");
        }
    }

    private static <T> T lookup(Map<String, T> map, String name, String kind) {
        T found = map.get(name);
        if (found == null) {
            throw new NoSuchElementException("no " + kind + " named '" + name + "' in this world");
        }
        return found;
    }
}
