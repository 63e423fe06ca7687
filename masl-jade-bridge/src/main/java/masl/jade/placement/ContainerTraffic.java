package masl.jade.placement;

import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.LongAdder;

/**
 * The messages the coordinator sent to and took from each container, counted as they cross the wire:
 * deployed agents' coordination messages ({@code masl-deployed}, one ACL message however many
 * requests it carries) and placed bodies' primitive calls ({@code masl-body}, a request and its
 * answer). What a mission's steps cost on the network. Counting is an addition per message; reading
 * is for after (or between) missions.
 */
public final class ContainerTraffic {

    private final Map<String, LongAdder> sent = new ConcurrentHashMap<>();
    private final Map<String, LongAdder> received = new ConcurrentHashMap<>();

    void sentTo(String container) {
        sent.computeIfAbsent(container, c -> new LongAdder()).increment();
    }

    void receivedFrom(String container) {
        received.computeIfAbsent(container, c -> new LongAdder()).increment();
    }

    /** Messages sent to each container so far, by container name. */
    public Map<String, Long> sent() {
        return snapshot(sent);
    }

    /** Messages taken from each container so far (refused ones left out), by container name. */
    public Map<String, Long> received() {
        return snapshot(received);
    }

    private static Map<String, Long> snapshot(Map<String, LongAdder> counts) {
        Map<String, Long> snapshot = new TreeMap<>();
        counts.forEach((container, count) -> snapshot.put(container, count.sum()));
        return snapshot;
    }
}
