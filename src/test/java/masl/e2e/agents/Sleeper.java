package masl.e2e.agents;

import java.util.concurrent.CountDownLatch;
import masl.agents.Default;

/**
 * An agent whose primitives sleep through its services (mission time): {@code doze} is
 * asynchronous, {@code nap} synchronous; each logs when it wakes and returns how long it slept.
 * {@code stall}, asynchronous, waits for what never comes, until interrupted.
 */
public class Sleeper extends Default {

    public int doze(int ms) throws InterruptedException {
        return sleepAndLog("dozed", ms);
    }

    public int nap(int ms) throws InterruptedException {
        return sleepAndLog("napped", ms);
    }

    public int stall() throws InterruptedException {
        new CountDownLatch(1).await();
        return 1;
    }

    private int sleepAndLog(String what, int ms) throws InterruptedException {
        services().sleep(ms);
        logln(getProxyID() + " " + what + " " + ms);
        return ms;
    }
}
