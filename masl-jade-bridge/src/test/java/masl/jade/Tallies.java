package masl.jade;

import java.util.List;
import java.util.concurrent.CompletableFuture;
import masl.runtime.AgentContext;
import masl.runtime.AgentImplementation;
import masl.runtime.AgentProgram;
import masl.runtime.EntryDefinition;
import masl.runtime.Mission;
import masl.runtime.MissionProgram;
import masl.runtime.Mode;

/**
 * A mission of two {@link Counter}s, {@code owner} and {@code caller}: the caller invokes the owner's
 * {@code count(1)} three times (the second as the asynchronous {@code countAside(1)}), then, if {@code writes}, writes the owner's {@code total}, reads it
 * and counts once more; the owner then says its total. In-process its journal is {@link #COUNTS}, or
 * {@link #COUNTS_AND_WRITES}. Its agents are made first, each program given them all, as the
 * translator generates.
 */
public record Tallies(boolean writes) implements MissionProgram {

    public static final String COUNTS = "count 1\ncount 2\ncount 3\nowner's total 3\n";
    public static final String COUNTS_AND_WRITES = "count 1\ncount 2\ncount 3\nread 100\ncount 101\nowner's total 101\n";

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
                    self -> new Tally(self, (Counter) population[0], writes));
        }
        return builder;
    }

    /**
     * <pre>
     * synchronous entry main (true) {
     *   if (me == caller) {
     *     .logln("count " + owner.count(1)); .logln("count " + owner.countAside(1)); .logln("count " + owner.count(1));
     *     if (writes) { owner.total = 100; .logln("read " + owner.total); .logln("count " + owner.count(1)); }
     *   }
     * }
     * if (me == owner) .logln("owner's total " + total);
     * </pre>
     * The owner reads its total once the caller has left main (its exit barrier): after every call.
     */
    private static final class Tally extends AgentProgram {
        private final Counter self;
        private final Counter owner;
        private final boolean writes;
        private int calls;
        private CompletableFuture<Integer> counted;

        Tally(Counter self, Counter owner, boolean writes) {
            this.self = self;
            this.owner = owner;
            this.writes = writes;
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
                            case SKIPPED -> { pc = 7; continue; }
                            case WAITING -> { return; }
                            case ENTERED -> { }
                        }
                        continue;
                    case 1:
                        if (ctx.proxyId() == 0 || calls == 3 && !writes || calls == 4) {
                            pc = 6;
                            continue;
                        }
                        if (calls == 3) {
                            ctx.writeAttribute(owner, "total", () -> owner.total = 100);
                            logln(ctx, "read " + ctx.readAttribute(owner, "total", -1, () -> owner.total));
                        }
                        // The second count is asynchronous: launched, then awaited.
                        counted = calls == 1 ? ctx.launch(owner, "countAside", 0, () -> owner.countAside(1))
                                : ctx.invoke(owner, "count", 0, () -> owner.count(1));
                        pc = 2;
                        if (!ctx.await(counted)) return;
                        continue;
                    case 2:
                        calls++;
                        logln(ctx, "count " + counted.join());
                        pc = 1;
                        if (!ctx.stepBoundary()) return;
                        continue;
                    case 6:
                        pc = 7;
                        if (!ctx.leave(MAIN)) return;
                        continue;
                    case 7:
                        pc = 8;
                        if (!ctx.endOfSequence(MAIN.sequence())) return;
                        continue;
                    case 8:
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
