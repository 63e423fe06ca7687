package masl.runtime.invocation;

import masl.runtime.Agent;

/**
 * An external invocation queued at its callee (MASL §9): who asked, for which primitive, what runs
 * it and what answers a denial (§11). Both actions run on the callee's behalf, on whichever thread
 * serves it, and only touch the requester through its thread-safe side ({@link Agent#raise}) and
 * the future it awaits.
 *
 * <p><b>Internal:</b> not part of the API; public only for the other packages of the runtime (Java has no
 * friend packages), and may change without notice.
 */
public final class PendingInvocation {

    /** The requester's proxy id when the invocation comes from outside the mission's agents. */
    static final int OUTSIDE = -1;

    private final Agent requester;
    private final String primitive;
    private final Runnable run;
    private final Runnable deny;

    /**
     * @param requester the invoking agent, null from outside the mission (then the requester is "other")
     * @param primitive the primitive's name, null for an invocation that permeability does not filter
     */
    public PendingInvocation(Agent requester, String primitive, Runnable run, Runnable deny) {
        this.requester = requester;
        this.primitive = primitive;
        this.run = run;
        this.deny = deny;
    }

    /** An invocation from outside the mission that permeability does not filter (the JADE bridge's). */
    public static PendingInvocation unfiltered(Runnable run) {
        return new PendingInvocation(null, null, run, () -> { });
    }

    public Agent requester() {
        return requester;
    }

    public int requesterId() {
        return requester == null ? OUTSIDE : requester.id();
    }

    public String primitive() {
        return primitive;
    }

    public void run() {
        run.run();
    }

    public void deny() {
        deny.run();
    }
}
