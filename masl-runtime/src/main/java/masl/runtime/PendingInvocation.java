package masl.runtime;

/**
 * An external invocation queued at its callee (MASL §9): who asked, for which primitive, what runs
 * it and what answers a denial (§11). Both actions run on the callee's behalf, on whichever thread
 * serves it, and only touch the requester through its thread-safe side ({@link Agent#raise}) and
 * the future it awaits.
 */
final class PendingInvocation {

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
    PendingInvocation(Agent requester, String primitive, Runnable run, Runnable deny) {
        this.requester = requester;
        this.primitive = primitive;
        this.run = run;
        this.deny = deny;
    }

    /** An invocation from outside the mission that permeability does not filter (the JADE bridge's). */
    static PendingInvocation unfiltered(Runnable run) {
        return new PendingInvocation(null, null, run, () -> { });
    }

    Agent requester() {
        return requester;
    }

    int requesterId() {
        return requester == null ? OUTSIDE : requester.id();
    }

    String primitive() {
        return primitive;
    }

    void run() {
        run.run();
    }

    void deny() {
        deny.run();
    }
}
