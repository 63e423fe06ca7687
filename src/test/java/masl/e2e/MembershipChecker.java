package masl.e2e;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.atomic.LongAdder;
import masl.runtime.trace.Trace;
import masl.runtime.trace.TraceEvent;

/**
 * A trace that checks membership as it streams by, without keeping it: it replays every agent's
 * chain of blocks (active, or held by an entry or exit barrier) from the membership records, and
 * checks each barrier trip against the participants that replay gives (the active agents in a block
 * of the domain, MASL §6.3). Membership records and trips come under the runtime's one membership
 * lock, in the order they happened, so the replay is exact. Other records are only counted.
 */
final class MembershipChecker implements Trace {

    private record Membership(String block, boolean active) { }

    /** The barrier domain (its outermost synchronous block's name) of each synchronous block. */
    private final Map<String, String> domainOfBlock = new HashMap<>();
    private final Map<Integer, Deque<Membership>> chains = new HashMap<>();
    /** The participants of each domain, kept up to date as chains change. */
    private final Map<String, Integer> participants = new HashMap<>();
    private final Map<String, Integer> trips = new HashMap<>();
    private final Map<String, Integer> joins = new HashMap<>();
    private final Map<String, Integer> leaves = new HashMap<>();
    private final List<String> violations = new ArrayList<>();
    final LongAdder eventsEmitted = new LongAdder();
    final LongAdder eventsReacted = new LongAdder();

    /** @param domains the synchronous blocks of each barrier domain, by the domain's name */
    MembershipChecker(Map<String, Set<String>> domains) {
        domains.forEach((domain, blocks) -> blocks.forEach(block -> domainOfBlock.put(block, domain)));
    }

    @Override
    public void record(TraceEvent event) {
        if (event instanceof TraceEvent.EventReacted) {
            eventsReacted.increment();
        } else if (event instanceof TraceEvent.EventEmitted) {
            eventsEmitted.increment();
        } else {
            replay(event);
        }
    }

    private synchronized void replay(TraceEvent event) {
        if (event instanceof TraceEvent.BarrierTripped e) {
            int expected = participants.getOrDefault(e.domain(), 0);
            trips.merge(e.domain(), 1, Integer::sum);
            if (e.agents() != expected || expected == 0) {
                violations.add(event + " but " + expected + " agents take part in " + e.domain());
            }
            return;
        }
        int agent = agentOf(event);
        if (agent < 0) {
            return;
        }
        Set<String> before = domainsOf(chain(agent));
        change(event);
        Set<String> after = domainsOf(chain(agent));
        before.stream().filter(domain -> !after.contains(domain)).forEach(domain -> participants.merge(domain, -1, Integer::sum));
        after.stream().filter(domain -> !before.contains(domain)).forEach(domain -> participants.merge(domain, 1, Integer::sum));
    }

    private static int agentOf(TraceEvent event) {
        if (event instanceof TraceEvent.Entered e) {
            return e.agent();
        } else if (event instanceof TraceEvent.WaitingIn e) {
            return e.agent();
        } else if (event instanceof TraceEvent.Released e) {
            return e.agent();
        } else if (event instanceof TraceEvent.WaitingOut e) {
            return e.agent();
        } else if (event instanceof TraceEvent.Left e) {
            return e.agent();
        }
        return -1;
    }

    /** The domains the agent takes part in: those of its blocks, unless a barrier holds it (§6.3). */
    private Set<String> domainsOf(Deque<Membership> chain) {
        Set<String> domains = new HashSet<>();
        if (!chain.isEmpty() && chain.peek().active()) {
            for (Membership membership : chain) {
                String domain = domainOfBlock.get(membership.block());
                if (domain != null) {
                    domains.add(domain);
                }
            }
        }
        return domains;
    }

    private void change(TraceEvent event) {
        if (event instanceof TraceEvent.Entered e) {
            chain(e.agent()).push(new Membership(e.block(), true));
            joins.merge(e.block(), 1, Integer::sum);
        } else if (event instanceof TraceEvent.WaitingIn e) {
            chain(e.agent()).push(new Membership(e.block(), false));
            joins.merge(e.block(), 1, Integer::sum);
        } else if (event instanceof TraceEvent.Released e) {
            expectInnermost(e.agent(), e.block(), false, event);
            chain(e.agent()).pop();
            chain(e.agent()).push(new Membership(e.block(), true));
        } else if (event instanceof TraceEvent.WaitingOut e) {
            expectInnermost(e.agent(), e.block(), true, event);
            chain(e.agent()).pop();
            chain(e.agent()).push(new Membership(e.block(), false));
        } else if (event instanceof TraceEvent.Left e) {
            Membership innermost = chain(e.agent()).peek();
            if (innermost == null || !innermost.block().equals(e.block())) {
                violations.add(event + " but agent " + e.agent() + " is in " + chain(e.agent()));
            } else {
                chain(e.agent()).pop();
                leaves.merge(e.block(), 1, Integer::sum);
            }
        }
    }

    private void expectInnermost(int agent, String block, boolean active, TraceEvent event) {
        Membership innermost = chain(agent).peek();
        if (innermost == null || !innermost.block().equals(block) || innermost.active() != active) {
            violations.add(event + " but agent " + agent + " is in " + chain(agent));
        }
    }

    private Deque<Membership> chain(int agent) {
        return chains.computeIfAbsent(agent, id -> new ArrayDeque<>());
    }

    synchronized List<String> violations() {
        return new ArrayList<>(violations);
    }

    /** The agents still in a block, with their chains (innermost first). */
    synchronized Map<Integer, String> membersLeft() {
        Map<Integer, String> left = new HashMap<>();
        chains.forEach((agent, chain) -> {
            if (!chain.isEmpty()) {
                left.put(agent, chain.toString());
            }
        });
        return left;
    }

    synchronized int trips(String domain) {
        return trips.getOrDefault(domain, 0);
    }

    synchronized int joins(String block) {
        return joins.getOrDefault(block, 0);
    }

    synchronized int leaves(String block) {
        return leaves.getOrDefault(block, 0);
    }
}
