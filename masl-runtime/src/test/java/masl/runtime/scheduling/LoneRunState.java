package masl.runtime.scheduling;

/**
 * A run state with no agent around it, for the tests of its transitions (and the jcstress tests of
 * its races): it describes itself as "agent" and counts its wake-ups where the test says.
 */
public final class LoneRunState extends RunState {

    private final Runnable countWakeUp;

    public LoneRunState() {
        this(() -> { });
    }

    public LoneRunState(Runnable countWakeUp) {
        this.countWakeUp = countWakeUp;
    }

    @Override
    public String describe() {
        return "agent";
    }

    @Override
    protected void countWakeUp() {
        countWakeUp.run();
    }
}
