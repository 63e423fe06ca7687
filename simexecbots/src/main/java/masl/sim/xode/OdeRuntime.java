package masl.sim.xode;

import org.ode4j.ode.OdeHelper;

/** Initialises ode4j once per JVM; its collision code (trimeshes in particular) needs it. */
public final class OdeRuntime {

    private static boolean initialised;

    private OdeRuntime() {
    }

    /** Idempotent and thread-safe. */
    public static synchronized void ensureInitialised() {
        if (!initialised) {
            OdeHelper.initODE2(0);
            initialised = true;
        }
    }
}
