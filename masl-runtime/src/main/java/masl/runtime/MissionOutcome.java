package masl.runtime;

import java.util.Optional;

/**
 * How a mission ended, with its journal. {@code report} describes every agent (program counter,
 * chain of blocks) when the mission did not complete, and is empty when it did.
 */
public record MissionOutcome(Status status, String journal, Optional<Throwable> failure, String report) {

    public enum Status {
        /** Every agent left {@code main} (or skipped it). */
        COMPLETED,
        /** An agent's program threw, or broke the generated-code contract: see {@code failure}. */
        FAILED,
        /**
         * No agent could make progress any more: all were parked (at barriers nobody will trip,
         * entry barriers nobody will release, busy-waits nothing will satisfy) or done, with no
         * sleep or awaited future pending. Detected within {@code 2 * Mission.WATCHDOG_PERIOD}.
         */
        DEADLOCKED,
        /** The timeout given to {@link Mission#run} elapsed first. */
        TIMED_OUT,
        /** {@link Mission#stop()} was called. */
        STOPPED
    }

    public boolean completed() {
        return status == Status.COMPLETED;
    }

    /** Returns this outcome if the mission completed. */
    public MissionOutcome requireCompleted() {
        if (!completed()) {
            throw new MissionFailedException(this);
        }
        return this;
    }

    /** Thrown by {@link #requireCompleted()}: the message names the status, failure and report. */
    public static final class MissionFailedException extends RuntimeException {
        private static final long serialVersionUID = 1L;
        private final transient MissionOutcome outcome;

        MissionFailedException(MissionOutcome outcome) {
            super("mission " + outcome.status() + outcome.failure().map(f -> ": " + f).orElse("")
                    + (outcome.report().isEmpty() ? "" : "\n" + outcome.report()), outcome.failure().orElse(null));
            this.outcome = outcome;
        }

        public MissionOutcome outcome() {
            return outcome;
        }
    }
}
