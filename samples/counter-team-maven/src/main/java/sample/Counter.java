package sample;

import masl.agents.Default;

/** A tally counter: each agent of type Counter (Counter.xml) clicks its own. */
public class Counter extends Default {

    private int clicks;

    /** Clicks once and tells how many clicks this counter has had. */
    public synchronized int click() {
        return ++clicks;
    }
}
