package masl.jade;

import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.function.Function;
import masl.jade.platform.JadePlatform;
import masl.runtime.AgentContext;
import masl.runtime.AgentProgram;
import masl.runtime.EntryDefinition;
import masl.runtime.Mission;
import masl.runtime.MissionOutcome;
import masl.runtime.MissionProgram;
import masl.runtime.descriptor.AgentPath;
import masl.runtime.descriptor.AgentType;
import masl.runtime.descriptor.DescriptorLoader;
import masl.runtime.testing.CompactProgram;
import masl.runtime.testing.TestAgent;

/**
 * Test missions as {@link MissionProgram}s, as the translator generates them, their agent types, and
 * a mission run in the background while the test talks to its agents.
 */
public final class TestPrograms {

    private static final Path DESCRIPTORS = descriptors();
    private static final DescriptorLoader LOADER = new DescriptorLoader(AgentPath.parse(DESCRIPTORS.toString()), null);

    private TestPrograms() {
    }

    /**
     * Runs {@code launcher}'s mission on {@code platform} in a thread of its own, so that the test
     * can talk to its agents meanwhile; completes with the mission's outcome.
     */
    public static CompletableFuture<MissionOutcome> runInBackground(JadeLauncher launcher, JadePlatform platform,
            Duration timeout) {
        return CompletableFuture.supplyAsync(() -> {
            try {
                return launcher.run(platform, timeout);
            } catch (InterruptedException e) {
                throw new IllegalStateException(e);
            }
        });
    }

    /** Agents {@code a0 … a(n-1)} of type {@code TestAgent}, each running {@code program} from {@code main}. */
    public static MissionProgram of(EntryDefinition main, int agents, Function<TestAgent, AgentProgram> program) {
        List<MissionProgram.AgentSpec> specs = new ArrayList<>();
        for (int i = 0; i < agents; i++) {
            specs.add(new MissionProgram.AgentSpec("a" + i, TestAgent.class.getName()));
        }
        return of(main, specs, program);
    }

    /** The given agents, each running {@code program} from {@code main} (null: no main block). */
    public static MissionProgram of(EntryDefinition main, List<MissionProgram.AgentSpec> agents,
            Function<TestAgent, AgentProgram> program) {
        return new MissionProgram() {
            @Override
            public List<AgentSpec> agents() {
                return agents;
            }

            @Override
            public Mission.Builder configure(Mission.Builder builder, ImplementationFactory implementations) {
                if (main != null) {
                    builder.main(main);
                }
                for (AgentSpec agent : agents) {
                    try {
                        builder.agent(agent.name(), (TestAgent) implementations.create(agent), type(agent), program);
                    } catch (ReflectiveOperationException e) {
                        throw new IllegalStateException("cannot create agent " + agent.name(), e);
                    }
                }
                return builder;
            }
        };
    }

    /** The descriptor of an agent's type, from this module's test resources. */
    public static AgentType type(MissionProgram.AgentSpec agent) {
        String simpleName = agent.typeClassName().substring(agent.typeClassName().lastIndexOf('.') + 1);
        return LOADER.load(DESCRIPTORS.resolve(simpleName + ".xml"));
    }

    /**
     * A program without a main block: the agent waits until its {@code release()} is invoked. It
     * awaits a future, which the deadlock watchdog counts as a wake-up to come: a busy-wait on a
     * flag would look like a deadlock once no agent had run for 200 ms.
     */
    static final class UntilReleased extends CompactProgram {
        UntilReleased(TestAgent self) {
            super(self);
        }

        @Override
        protected void resume(AgentContext ctx) {
            while (true) {
                switch (pc) {
                    case 0:
                        pc = 1;
                        if (!ctx.await(((ServiceAgent) self).released())) return;
                        continue;
                    case 1:
                        ctx.finish();
                        return;
                    default:
                        throw new IllegalStateException("pc " + pc);
                }
            }
        }
    }

    /** What a test and {@link ClosesWhenAsked} tell each other, in the coordinator's JVM. */
    public record Signals(CompletableFuture<Void> closeRequested, CompletableFuture<Void> closed,
            CompletableFuture<Void> finishRequested) {
        public Signals() {
            this(new CompletableFuture<>(), new CompletableFuture<>(), new CompletableFuture<>());
        }
    }

    /**
     * Java-driven: once the test asks ({@link Signals#closeRequested}), sets the state
     * {@code nothing}, which denies others every primitive, tells the test ({@link Signals#closed}),
     * and finishes when the test says ({@link Signals#finishRequested}); blocked meanwhile, so
     * requests are served on its behalf at once, filtered by its state.
     */
    public static final class ClosesWhenAsked extends CompactProgram {
        private final Signals signals;

        public ClosesWhenAsked(TestAgent self, Signals signals) {
            super(self);
            this.signals = signals;
        }

        @Override
        protected void resume(AgentContext ctx) {
            while (true) {
                switch (pc) {
                    case 0:
                        pc = 1;
                        if (!ctx.await(signals.closeRequested())) return;
                        continue;
                    case 1:
                        ctx.setAcceptState("nothing");
                        pc = 2;
                        if (!ctx.stepBoundary()) return;
                        continue;
                    case 2:
                        signals.closed().complete(null);
                        pc = 3;
                        if (!ctx.await(signals.finishRequested())) return;
                        continue;
                    case 3:
                        ctx.finish();
                        return;
                    default:
                        throw new IllegalStateException("pc " + pc);
                }
            }
        }
    }

    /** {@code while (!released) {}}: a busy-wait that only a FIPA agent's {@code release()} ends. */
    static final class BusyUntilReleased extends CompactProgram {
        BusyUntilReleased(TestAgent self) {
            super(self);
        }

        @Override
        protected void resume(AgentContext ctx) {
            while (!((ServiceAgent) self).released().isDone()) {
                if (!ctx.busyWaitIteration()) {
                    return;
                }
            }
            self.log("released");
            ctx.finish();
        }
    }

    private static Path descriptors() {
        try {
            return Path.of(TestPrograms.class.getResource("TestAgent.xml").toURI()).getParent();
        } catch (java.net.URISyntaxException e) {
            throw new IllegalStateException(e);
        }
    }
}
