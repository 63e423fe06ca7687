package masl.jade.deployment;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import java.time.Duration;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;
import masl.jade.TestPrograms;
import masl.runtime.AgentContext;
import masl.runtime.AgentImplementation;
import masl.runtime.EntryDefinition;
import masl.runtime.Event;
import masl.runtime.Mission;
import masl.runtime.Mode;
import masl.runtime.Reaction;
import masl.runtime.testing.CompactProgram;
import masl.runtime.testing.TestAgent;
import masl.runtime.trace.Trace;
import masl.testing.jade.DeployedInMemory;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * A deployed agent's boundaries with nothing to do (a loop head, a step boundary that meets no
 * barrier) are passed in its container, with no message; an event or an invocation that arrives for
 * the agent is still taken at the boundary where it is in-process, and what a step wrote is in the
 * journal when its boundary is passed.
 */
@Timeout(60)
class QuietBoundariesTest {

    private static final Duration TIMEOUT = Duration.ofSeconds(20);

    @Test
    void aLoopHeadWithNothingToDoCostsNoMessage() throws Exception {
        InMemoryDeployment.Run run = InMemoryDeployment.run(
                () -> TestPrograms.of(Counting.LOCK_STEP, 1, self -> new Counting(self, Counting.LOCK_STEP)),
                Map.of("a0", "c2"), TIMEOUT);
        assertEquals("done\n", run.outcome().journal(), run.outcome().toString());
        // A request for each step's barrier, and a few to enter and leave; a loop head's own would be one more a step.
        assertTrue(run.messagesFromContainer() < Counting.STEPS + 10,
                run.messagesFromContainer() + " messages from the container");
    }

    @Test
    void aStepBoundaryThatMeetsNoBarrierCostsNoMessage() throws Exception {
        InMemoryDeployment.Run run = InMemoryDeployment.run(
                () -> TestPrograms.of(Counting.FREE, 1, self -> new Counting(self, Counting.FREE)),
                Map.of("a0", "c2"), TIMEOUT);
        assertEquals("done\n", run.outcome().journal(), run.outcome().toString());
        // Entering, leaving and finishing; a step's own would be one more a step.
        assertTrue(run.messagesFromContainer() < 10, run.messagesFromContainer() + " messages from the container");
    }

    @Test
    void aStepThatPassesItsBoundariesForLongHoldsItsContainersMessagesNoMore() {
        QuietBoundaries quiet = new QuietBoundaries();
        quiet.told(JsonNodeFactory.instance.objectNode().put("seq", 1).set("atRest",
                JsonNodeFactory.instance.objectNode().put("latest", 0).put("barrier", false)));
        for (int pass = 1; pass < QuietBoundaries.LONG_RUN; pass++) {
            assertTrue(quiet.passLoopHead(3));
            assertFalse(quiet.lettingGo(), "after " + pass + " boundaries");
        }
        assertTrue(quiet.passLoopHead(3));
        assertTrue(quiet.lettingGo());
        assertTrue(quiet.passLoopHead(3));
        assertFalse(quiet.lettingGo(), "once");
        // Its next message leaves the count of busy steps as it is, and the one after takes one off.
        assertEquals(0, quiet.busyChangeOfNext());
        assertEquals(-1, quiet.busyChangeOfNext());
    }

    @Test
    void whatAStepWroteIsInTheJournalOnceItsBoundaryIsPassed() throws Exception {
        AtomicInteger said = new AtomicInteger();
        AtomicBoolean released = new AtomicBoolean();
        InMemoryDeployment.Run run = InMemoryDeployment.run(
                () -> TestPrograms.of(Says.MAIN, 2, self -> new Says(self, said, released)), Map.of("a0", "c2"),
                TIMEOUT);
        assertEquals("a0 says\na1 heard a0\n", run.outcome().journal(), run.outcome().toString());
    }

    @Test
    void anEventEndsALoopWhoseHeadsArePassedInTheContainer() throws Exception {
        AtomicInteger iterations = new AtomicInteger();
        InMemoryDeployment.Run run = InMemoryDeployment.run(
                () -> TestPrograms.of(Woken.MAIN, 2, self -> new Woken(self, iterations)), Map.of("a0", "c2"), TIMEOUT);
        assertEquals("a0 heard\n", run.outcome().journal(), run.outcome().toString());
    }

    @Test
    void anInvocationIsServedAtALoopHeadPassedInTheContainer() throws Exception {
        AtomicInteger iterations = new AtomicInteger();
        AtomicBoolean released = new AtomicBoolean();
        InMemoryDeployment.Run run = InMemoryDeployment.run(
                () -> TestPrograms.of(Invoked.MAIN, 2, self -> new Invoked(self, iterations, released)),
                Map.of("a0", "c2"), TIMEOUT);
        assertEquals("a1 called a0\na0 went on\n", run.outcome().journal(), run.outcome().toString());
    }

    @Test
    void anEventPerceivedAtTheBarrierIsHandledAtTheNextLoopHead() throws Exception {
        String inProcess = atTheBarrier(Map.of());
        assertEquals("a1 heard after 0\na0 heard after 1\ndone\n", inProcess);
        assertEquals(inProcess, atTheBarrier(Map.of("a0", "c2")));
    }

    private static String atTheBarrier(Map<String, String> deployed) throws InterruptedException {
        DeployedInMemory.Wires wires = new DeployedInMemory.Wires();
        AtomicInteger counted = new AtomicInteger();
        InMemoryDeployment.Run run = InMemoryDeployment.run(
                () -> TestPrograms.of(AtTheBarrier.MAIN, 2, self -> new AtTheBarrier(self, wires, counted)),
                deployed, Trace.NONE, wires, TIMEOUT);
        assertTrue(run.outcome().completed(), run.outcome().toString());
        return run.outcome().journal();
    }

    /**
     * {@code synchronous entry main (true) { local int i = 0; while (i < STEPS) { i++; } .logln("done"); }},
     * or with an asynchronous {@code main}.
     */
    private static final class Counting extends CompactProgram {
        static final EntryDefinition LOCK_STEP = EntryDefinition.main("main", Mode.SYNCHRONOUS);
        static final EntryDefinition FREE = EntryDefinition.main("main", Mode.ASYNCHRONOUS);
        static final int STEPS = 40;
        private final EntryDefinition main;
        private int i;

        Counting(TestAgent self, EntryDefinition main) {
            super(self);
            this.main = main;
        }

        @Override
        protected void resume(AgentContext ctx) {
            while (true) {
                switch (pc) {
                    case 0:
                        if (!arrive(ctx, main, true, 1, 5)) return;
                        continue;
                    case 1:
                        pc = i < STEPS ? 2 : 4;
                        continue;
                    case 2:
                        i++;
                        if (!step(ctx, 3)) return;
                        continue;
                    case 3:
                        if (!loop(ctx, 1)) return;
                        continue;
                    case 4:
                        self.logln("done");
                        if (!leave(ctx, main, 5)) return;
                        continue;
                    case 5:
                        pc = 6;
                        if (!ctx.endOfSequence(main.sequence())) return;
                        continue;
                    case 6:
                        ctx.finish();
                        return;
                    default:
                        throw new IllegalStateException("pc " + pc);
                }
            }
        }
    }

    /**
     * <pre>
     * asynchronous entry main (true) {
     *   shared event go; local boolean heard = false;
     *   a0: while (!heard) { if (false) { … } } .logln("a0 heard");
     *   a1: emit(go);      (once a0 has passed a thousand of its loop heads)
     *   react (go) { heard = true; resume; }
     * }
     * </pre>
     * {@code a0}'s loop runs no instruction and meets no barrier: only the event can end it, which
     * arrives while a0's container passes its loop heads itself.
     */
    private static final class Woken extends CompactProgram {
        static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.ASYNCHRONOUS);
        static final Event GO = MAIN.declareSharedEvent("go");
        static final Reaction REACT_GO = MAIN.react(GO);
        /** a0's loop heads, wherever its program runs: a1 reads them. */
        private final AtomicInteger iterations;
        private boolean heard;

        Woken(TestAgent self, AtomicInteger iterations) {
            super(self);
            this.iterations = iterations;
        }

        @Override
        protected int reactionPc(Reaction reaction) {
            return reaction == REACT_GO ? 10 : super.reactionPc(reaction);
        }

        @Override
        protected void resume(AgentContext ctx) {
            while (true) {
                switch (pc) {
                    case 0:
                        if (!arrive(ctx, MAIN, true, 1, 8)) return;
                        continue;
                    case 1:
                        pc = self.getProxyID() == 0 ? 3 : 5;
                        continue;
                    case 3:
                        if (heard) {
                            pc = 4;
                            continue;
                        }
                        iterations.incrementAndGet();
                        if (!loop(ctx, 3)) return;
                        continue;
                    case 4:
                        self.logln("a0 heard");
                        if (!step(ctx, 7)) return;
                        continue;
                    case 5:
                        while (iterations.get() < 1000) {
                            Thread.onSpinWait();
                        }
                        ctx.emit(GO);
                        if (!step(ctx, 7)) return;
                        continue;
                    case 7:
                        if (!leave(ctx, MAIN, 8)) return;
                        continue;
                    case 8:
                        pc = 9;
                        if (!ctx.endOfSequence(MAIN.sequence())) return;
                        continue;
                    case 9:
                        ctx.finish();
                        return;
                    case 10:
                        heard = true;
                        if (!resumeAfterReaction(ctx)) return;
                        continue;
                    default:
                        throw new IllegalStateException("pc " + pc);
                }
            }
        }
    }

    /**
     * {@code asynchronous entry main (true) { … }}: a0 says something, then loops, running no
     * instruction, until a1 has said that it heard a0, once a0 has passed the boundary of its saying.
     */
    private static final class Says extends CompactProgram {
        static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.ASYNCHRONOUS);
        /** Whether a0 has passed the boundary of its saying, wherever its program runs: a1 reads it. */
        private final AtomicInteger said;
        private final AtomicBoolean released;

        Says(TestAgent self, AtomicInteger said, AtomicBoolean released) {
            super(self);
            this.said = said;
            this.released = released;
        }

        @Override
        protected void resume(AgentContext ctx) {
            while (true) {
                switch (pc) {
                    case 0:
                        if (!arrive(ctx, MAIN, true, 1, 7)) return;
                        continue;
                    case 1:
                        pc = self.getProxyID() == 0 ? 2 : 5;
                        continue;
                    case 2:
                        self.logln("a0 says");
                        if (!step(ctx, 3)) return;
                        continue;
                    case 3:
                        said.set(1);
                        pc = 4;
                        continue;
                    case 4:
                        if (released.get()) {
                            pc = 6;
                            continue;
                        }
                        if (!loop(ctx, 4)) return;
                        continue;
                    case 5:
                        while (said.get() < 1) {
                            Thread.onSpinWait();
                        }
                        self.logln("a1 heard a0");
                        released.set(true);
                        if (!step(ctx, 6)) return;
                        continue;
                    case 6:
                        if (!leave(ctx, MAIN, 7)) return;
                        continue;
                    case 7:
                        pc = 8;
                        if (!ctx.endOfSequence(MAIN.sequence())) return;
                        continue;
                    case 8:
                        ctx.finish();
                        return;
                    default:
                        throw new IllegalStateException("pc " + pc);
                }
            }
        }
    }

    /**
     * {@code asynchronous entry main (true) { … }}: a0 loops, running no instruction, until a1 has
     * invoked its {@code logln}, which a0 serves at a loop head, and been answered.
     */
    private static final class Invoked extends CompactProgram {
        static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.ASYNCHRONOUS);
        private final AtomicInteger iterations;
        private final AtomicBoolean released;
        private CompletableFuture<Void> call;

        Invoked(TestAgent self, AtomicInteger iterations, AtomicBoolean released) {
            super(self);
            this.iterations = iterations;
            this.released = released;
        }

        @Override
        protected void resume(AgentContext ctx) {
            while (true) {
                switch (pc) {
                    case 0:
                        if (!arrive(ctx, MAIN, true, 1, 7)) return;
                        continue;
                    case 1:
                        pc = self.getProxyID() == 0 ? 2 : 4;
                        continue;
                    case 2:
                        if (released.get()) {
                            pc = 3;
                            continue;
                        }
                        iterations.incrementAndGet();
                        if (!loop(ctx, 2)) return;
                        continue;
                    case 3:
                        self.logln("a0 went on");
                        if (!step(ctx, 6)) return;
                        continue;
                    case 4:
                        while (iterations.get() < 1000) {
                            Thread.onSpinWait();
                        }
                        TestAgent a0 = (TestAgent) ctx.entry(MAIN).getList().stream()
                                .filter(agent -> AgentImplementation.proxyIdOf(agent) == 0).findFirst().orElseThrow();
                        call = ctx.invoke(a0, "logln", null, () -> {
                            a0.logln("a1 called a0");
                            return null;
                        });
                        pc = 5;
                        if (!ctx.await(call)) return;
                        continue;
                    case 5:
                        released.set(true);
                        if (!step(ctx, 6)) return;
                        continue;
                    case 6:
                        if (!leave(ctx, MAIN, 7)) return;
                        continue;
                    case 7:
                        pc = 8;
                        if (!ctx.endOfSequence(MAIN.sequence())) return;
                        continue;
                    case 8:
                        ctx.finish();
                        return;
                    default:
                        throw new IllegalStateException("pc " + pc);
                }
            }
        }
    }

    /**
     * <pre>
     * synchronous entry main (true) {
     *   shared event go; local int i = 0;
     *   a0: while (i &lt; 3) { i++; } .logln("done");
     *   a1: emit(go);      (once a0 waits at the barrier of its first step)
     *   react (go) { .logln(.getName() + " heard after " + i); resume; }
     * }
     * </pre>
     * {@code a0} perceives {@code go} while it waits at the barrier: in-process, the loop head that
     * follows the barrier's trip handles it, before the second {@code i++}.
     */
    private static final class AtTheBarrier extends CompactProgram {
        static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.SYNCHRONOUS);
        static final Event GO = MAIN.declareSharedEvent("go");
        static final Reaction REACT_GO = MAIN.react(GO);
        private final DeployedInMemory.Wires wires;
        /** a0's {@code i}, wherever its program runs: a1 reads it. */
        private final AtomicInteger counted;
        private int i;

        AtTheBarrier(TestAgent self, DeployedInMemory.Wires wires, AtomicInteger counted) {
            super(self);
            this.wires = wires;
            this.counted = counted;
        }

        @Override
        protected int reactionPc(Reaction reaction) {
            return reaction == REACT_GO ? 9 : super.reactionPc(reaction);
        }

        @Override
        protected void resume(AgentContext ctx) {
            while (true) {
                switch (pc) {
                    case 0:
                        if (!arrive(ctx, MAIN, true, 1, 7)) return;
                        continue;
                    case 1:
                        pc = self.getProxyID() == 0 ? 2 : 5;
                        continue;
                    case 2:
                        pc = i < 3 ? 3 : 10;
                        continue;
                    case 3:
                        counted.set(++i);
                        if (!step(ctx, 4)) return;
                        continue;
                    case 4:
                        if (!loop(ctx, 2)) return;
                        continue;
                    case 5:
                        awaitFirstArrival(ctx);
                        ctx.emit(GO);
                        if (!step(ctx, 6)) return;
                        continue;
                    case 6:
                        if (!leave(ctx, MAIN, 7)) return;
                        continue;
                    case 7:
                        pc = 8;
                        if (!ctx.endOfSequence(MAIN.sequence())) return;
                        continue;
                    case 8:
                        ctx.finish();
                        return;
                    case 9:
                        self.logln("a" + self.getProxyID() + " heard after " + i);
                        if (!resumeAfterReaction(ctx)) return;
                        continue;
                    case 10:
                        self.logln("done");
                        if (!leave(ctx, MAIN, 7)) return;
                        continue;
                    default:
                        throw new IllegalStateException("pc " + pc);
                }
            }
        }

        /**
         * Waits, within a1's first step, until a0 waits at the barrier of its first: it counted its
         * first step, and it is parked (a1 not having arrived, a0's arrival cannot trip the barrier).
         */
        private void awaitFirstArrival(AgentContext ctx) {
            Mission mission = wires.mission();
            AgentImplementation a0 = ctx.entry(MAIN).getList().stream()
                    .filter(agent -> AgentImplementation.proxyIdOf(agent) == 0).findFirst().orElseThrow();
            while (counted.get() < 1 || mission.agentOf(a0).pendingTicket() == 0) {
                Thread.onSpinWait();
            }
        }
    }
}
