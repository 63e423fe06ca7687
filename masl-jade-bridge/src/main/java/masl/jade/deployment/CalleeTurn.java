package masl.jade.deployment;

import java.util.Set;
import java.util.function.Supplier;

/**
 * When a deployed agent's container may serve it an invocation made by another agent of the same
 * container, there, with no message (MASL §5, §9): while the agent's program is at rest as a blocked
 * agent is (its step waits for the mission at a boundary, a barrier, a sleep or an await, or is
 * over), and no invocation the mission served it runs on its object. The runtime serves a blocked
 * agent's invocations so too, one at a time and never while its program runs; the step that goes on
 * waits for the invocation served here to end, as the runtime's serving slice delays a wake-up.
 * Any thread; the program's own thread says when it rests and goes on.
 */
final class CalleeTurn {

    /**
     * The requests during which the program rests as a blocked agent does (at a boundary, a barrier,
     * a sleep, an await): its container may serve it an invocation meanwhile. Not a {@code
     * waitFor(state)}, which only the mission ends when it serves an invocation.
     */
    private static final Set<String> RESTING = Set.of("stepBoundary", "loopIteration", "busyWaitIteration",
            "endOfChild", "endOfSequence", "enter", "leave", "sleep", "await");

    /**
     * {@code request}'s answer, which the program waits for: resting meanwhile if it rests during a
     * request {@code op}, and going on, once the invocation served here meanwhile has ended.
     */
    <T> T during(String op, Supplier<T> request) {
        boolean rests = restsDuring(op);
        if (rests) {
            programRests();
        }
        try {
            return request.get();
        } finally {
            if (rests) {
                programGoesOn();
            }
        }
    }

    /** Whether the program rests as a blocked agent does while the mission performs its request {@code op}. */
    static boolean restsDuring(String op) {
        return RESTING.contains(op);
    }

    /** Whether the program runs: from the start, so that nothing is served before its first step. */
    private boolean programRuns = true;
    /** Calls of the agent's primitives the mission asked for, running. */
    private int missionRuns;
    private boolean servingHere;

    /** Takes the turn to serve an invocation here, if the agent is at rest and nothing runs on it: true if taken. */
    synchronized boolean take() {
        if (programRuns || missionRuns > 0 || servingHere) {
            return false;
        }
        servingHere = true;
        return true;
    }

    /** The invocation served here has ended. */
    synchronized void release() {
        servingHere = false;
        notifyAll();
    }

    /** The program rests: its step waits for the mission, or is over. */
    synchronized void programRests() {
        programRuns = false;
    }

    /** The program goes on, once the invocation served here meanwhile has ended. */
    synchronized void programGoesOn() {
        awaitNoServing();
        programRuns = true;
    }

    /**
     * A primitive of the agent the mission asked for (an invocation or a launch it served) starts
     * here: after any invocation served here, and keeping others from being served here until it ends.
     */
    synchronized void missionRunBegins() {
        awaitNoServing();
        missionRuns++;
    }

    /** A primitive the mission asked for has ended. */
    synchronized void missionRunEnds() {
        missionRuns--;
    }

    private void awaitNoServing() {
        boolean interrupted = false;
        while (servingHere) {
            try {
                wait();
            } catch (InterruptedException e) {
                interrupted = true;
            }
        }
        if (interrupted) {
            Thread.currentThread().interrupt();
        }
    }
}
