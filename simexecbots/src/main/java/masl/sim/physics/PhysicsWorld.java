package masl.sim.physics;

import java.time.Duration;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.NoSuchElementException;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.Condition;
import java.util.concurrent.locks.LockSupport;
import java.util.concurrent.locks.ReentrantLock;
import java.util.function.Supplier;
import masl.runtime.diagnostic.Diagnostic;
import masl.sim.xode.LoadTarget;
import masl.sim.xode.LoadedModel;
import masl.sim.xode.OdeRuntime;
import masl.sim.xode.Pose;
import masl.sim.xode.XodeException;
import masl.sim.xode.XodeLoader;
import masl.sim.xode.XodeSource;
import org.ode4j.math.DQuaternionC;
import org.ode4j.math.DVector3;
import org.ode4j.math.DVector3C;
import org.ode4j.ode.DBody;
import org.ode4j.ode.DFixedJoint;
import org.ode4j.ode.DHingeJoint;
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

    /** Told after every step, on the stepping thread, while the step's lock is still held. */
    @FunctionalInterface
    public interface StepListener {
        /** Must be quick and must not wait for another thread that needs the world. */
        void afterStep(PhysicsWorld world);
    }

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
    private final RayCaster rays = new RayCaster();
    private final List<StepListener> listeners = new CopyOnWriteArrayList<>();
    /** The step number (1-based) at which each body last touched a static geom. */
    private final Map<DBody, Long> lastEnvironmentContact = new HashMap<>();
    /** Concurrent so that commands can find their joint without waiting for a step to end. */
    private final Map<String, DBody> bodies = new ConcurrentHashMap<>();
    private final Map<String, DJoint> joints = new ConcurrentHashMap<>();
    private final Set<String> names = new HashSet<>();
    /** The warnings of every document loaded, each once: robots sharing a body file share its warnings. */
    private final Set<Diagnostic> warnings = new LinkedHashSet<>();
    /** Joints made by attachFixed, the only ones detach destroys. */
    private final Set<String> latches = new HashSet<>();
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
        world.setCFM(1e-5);
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
            model.warnings().forEach(warning -> warnings.add(warning.diagnostic()));
            return model;
        } finally {
            lock.unlock();
        }
    }

    /** The warnings of the documents loaded so far (unknown elements, ignored scale…), each with its file, line and column. */
    public List<Diagnostic> warnings() {
        lock.lock();
        try {
            return List.copyOf(warnings);
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

    /** A hinge's angular velocity (rad/s) between steps: what a wheel encoder measures. */
    public double jointRate(String jointName) {
        return withLock(() -> {
            DJoint joint = lookup(joints, jointName, "joint");
            if (!(joint instanceof DHingeJoint hinge)) {
                throw new IllegalArgumentException("joint '" + jointName + "' is not a hinge");
            }
            return hinge.getAngleRate();
        });
    }

    /**
     * Whether the body touched something static (ground, wall) during one of the latest
     * {@code steps} steps: a debounced contact switch, as resting contacts come and go between steps.
     */
    public boolean touchesEnvironment(String bodyName, int steps) {
        return withLock(() -> {
            Long last = lastEnvironmentContact.get(lookup(bodies, bodyName, "body"));
            return last != null && this.steps - last < steps;
        });
    }

    /** Adds a force (N, world coordinates) at the body's centre of mass for the next step only. */
    public void addForce(String bodyName, double fx, double fy, double fz) {
        withLock(() -> {
            lookup(bodies, bodyName, "body").addForce(fx, fy, fz);
            return null;
        });
    }

    /**
     * The distance from {@code origin} along {@code direction} (world coordinates, normalised here)
     * to the nearest geom within {@code length}, ignoring geoms of {@code ignoredBodies};
     * {@link Double#POSITIVE_INFINITY} when nothing is that close.
     */
    public double castRay(double[] origin, double[] direction, double length, Set<String> ignoredBodies) {
        DVector3 unit = new DVector3(direction[0], direction[1], direction[2]);
        if (!(unit.length() > 0)) {
            throw new IllegalArgumentException("ray direction is zero");
        }
        unit.normalize();
        return withLock(() -> {
            Set<DBody> ignored = new HashSet<>();
            ignoredBodies.forEach(name -> ignored.add(lookup(bodies, name, "body")));
            return rays.cast(space, new DVector3(origin[0], origin[1], origin[2]), unit, length, ignored);
        });
    }

    /**
     * Joins two bodies rigidly where they are now, with a fixed joint named {@code jointName}
     * (a latch); until {@link #detach} the bodies move as one and do not collide.
     *
     * @throws IllegalArgumentException when a joint or object of that name exists, or the bodies are one
     */
    public void attachFixed(String jointName, String body1, String body2) {
        withLock(() -> {
            checkOpen();
            if (names.contains(jointName)) {
                throw new IllegalArgumentException("a joint or object named '" + jointName + "' exists already");
            }
            DBody first = lookup(bodies, body1, "body");
            DBody second = lookup(bodies, body2, "body");
            if (first == second) {
                throw new IllegalArgumentException("cannot attach body '" + body1 + "' to itself");
            }
            DFixedJoint joint = OdeHelper.createFixedJoint(world);
            joint.attach(first, second);
            joint.setFixed();
            joint.setData(jointName);
            joints.put(jointName, joint);
            names.add(jointName);
            latches.add(jointName);
            return null;
        });
    }

    /** Destroys a joint made by {@link #attachFixed}; false when there is no joint of that name. */
    public boolean detach(String jointName) {
        return withLock(() -> {
            if (!latches.remove(jointName)) {
                return false;
            }
            names.remove(jointName);
            joints.remove(jointName).destroy();
            return true;
        });
    }

    /** Whether a joint of that name exists (loaded or attached). */
    public boolean hasJoint(String jointName) {
        return joints.containsKey(jointName);
    }

    /**
     * The top-down outlines of the static boxes (walls, obstacles) of the world: each the four
     * corners (x, y) of the box's face most nearly parallel to the ground, projected on it.
     */
    public List<double[][]> staticBoxOutlines() {
        return withLock(() -> StaticOutlines.of(space));
    }

    /** Adds a listener told after every later step (see {@link StepListener}). */
    public void addStepListener(StepListener listener) {
        listeners.add(listener);
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
        for (DBody body : contacts.touchingEnvironment()) {
            lastEnvironmentContact.put(body, steps);
        }
        stepped.signalAll();
        for (StepListener listener : listeners) {
            listener.afterStep(this);
        }
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
