package masl.jade.deployment;

import java.util.List;
import java.util.concurrent.CompletableFuture;
import masl.jade.Counter;
import masl.jade.TestPrograms;
import masl.runtime.AgentContext;
import masl.runtime.AgentImplementation;
import masl.runtime.AgentProgram;
import masl.runtime.EntryDefinition;
import masl.runtime.Mission;
import masl.runtime.MissionProgram;
import masl.runtime.Mode;

/**
 * A mission of two {@link Counter}s: {@code owner} enters {@code main} and leaves it at once, held by
 * the exit barrier; {@code caller} waits (sleeping) until the barrier holds the owner, then invokes
 * its {@code count(1)} three times, each awaited (if {@code secondThrows}, the second is {@code
 * count(-1)}, which throws: the caller perceives {@code uncaught_exception} and counts 0), and leaves;
 * the owner then says its total. The owner is blocked at each call, so the runtime serves each at
 * once on its behalf. Journal: {@link #JOURNAL}, or {@link #JOURNAL_WITH_THROW}.
 */
record CallsAtTheBarrier(boolean secondThrows) implements MissionProgram {

    static final String JOURNAL = "count 1\ncount 2\ncount 3\nowner's total 3\n";
    static final String JOURNAL_WITH_THROW = "count 1\ncount 0\ncount 2\nowner's total 2\n";

    private static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.SYNCHRONOUS);
    private static final List<AgentSpec> AGENTS = List.of(new AgentSpec("owner", Counter.class.getName()),
            new AgentSpec("caller", Counter.class.getName()));

    @Override
    public List<AgentSpec> agents() {
        return AGENTS;
    }

    @Override
    public Mission.Builder configure(Mission.Builder builder, ImplementationFactory implementations) {
        builder.main(MAIN);
        AgentImplementation[] population = new AgentImplementation[AGENTS.size()];
        for (int i = 0; i < population.length; i++) {
            try {
                population[i] = implementations.create(AGENTS.get(i));
            } catch (ReflectiveOperationException e) {
                throw new IllegalStateException(e);
            }
        }
        for (int i = 0; i < population.length; i++) {
            builder.agent(AGENTS.get(i).name(), (Counter) population[i], TestPrograms.type(AGENTS.get(i)),
                    self -> new Calls(self, (Counter) population[0], secondThrows));
        }
        return builder;
    }

    /**
     * <pre>
     * synchronous entry main (true) {
     *   if (me == caller) {
     *     while (main.getWaitingOutCount() == 0) sleep(5);
     *     repeat 3: .logln("count " + owner.count(1));  // count(-1) the second time if secondThrows
     *   }
     * }
     * if (me == owner) .logln("owner's total " + total);
     * </pre>
     */
    private static final class Calls extends AgentProgram {
        private final Counter self;
        private final Counter owner;
        private int calls;
        private final boolean secondThrows;
        private CompletableFuture<Integer> counted;

        Calls(Counter self, Counter owner, boolean secondThrows) {
            this.self = self;
            this.owner = owner;
            this.secondThrows = secondThrows;
        }

        private void logln(AgentContext ctx, String line) {
            ctx.invokeSelf("logln", null, () -> {
                self.logln(line);
                return null;
            });
        }

        @Override
        protected void resume(AgentContext ctx) {
            while (true) {
                switch (pc) {
                    case 0:
                        pc = 1;
                        switch (ctx.enter(MAIN, true)) {
                            case SKIPPED -> { pc = 5; continue; }
                            case WAITING -> { return; }
                            case ENTERED -> { }
                        }
                        continue;
                    case 1:
                        if (ctx.proxyId() == 0 || calls == 3) {
                            pc = 4;
                            continue;
                        }
                        if (ctx.entry(MAIN).getWaitingOutCount() == 0) {
                            if (!ctx.sleep(5)) return;
                            continue;
                        }
                        int by = secondThrows && calls == 1 ? -1 : 1;
                        counted = ctx.invoke(owner, "count", 0, () -> owner.count(by));
                        pc = 2;
                        if (!ctx.await(counted)) return;
                        continue;
                    case 2:
                        calls++;
                        logln(ctx, "count " + counted.join());
                        pc = 1;
                        continue;
                    case 4:
                        pc = 5;
                        if (!ctx.leave(MAIN)) return;
                        continue;
                    case 5:
                        pc = 6;
                        if (!ctx.endOfSequence(MAIN.sequence())) return;
                        continue;
                    case 6:
                        if (ctx.proxyId() == 0) {
                            logln(ctx, "owner's total " + ctx.readAttribute(self, "total", -1, () -> self.total));
                        }
                        ctx.finish();
                        return;
                    default:
                        throw new IllegalStateException("pc " + pc);
                }
            }
        }
    }
}
