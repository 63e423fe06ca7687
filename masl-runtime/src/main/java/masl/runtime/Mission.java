package masl.runtime;

import java.time.Duration;
import java.util.ArrayList;
import java.util.Collections;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.BiFunction;
import java.util.function.Function;
import masl.runtime.descriptor.AgentType;
import masl.runtime.entry.Entry;
import masl.runtime.entry.EntryCoordinator;
import masl.runtime.event.EventOccurrence;
import masl.runtime.invocation.PendingInvocation;
import masl.runtime.invocation.PrimitiveCalls;
import masl.runtime.scheduling.ChangeEpoch;
import masl.runtime.scheduling.PoolScheduler;
import masl.runtime.scheduling.Scheduler;
import masl.runtime.scheduling.WakeUps;
import masl.runtime.trace.Trace;
import masl.runtime.trace.TraceEvent;

/**
 * One run of a MASL program: its agents (proxy ids 0, 1, 2, … in declaration order, each with its
 * implementation bound to its {@link AgentServices} and its program), the state of its e-blocks,
 * its journal and trace, and the scheduler that runs it. The mission ends when every agent's
 * program has finished (MASL §6.5) and no asynchronous primitive is still running, when a program
 * fails, when no agent can make progress any
 * more (deadlock), on timeout or on {@link #stop()}.
 *
 * <pre>{@code
 * MissionOutcome outcome = Mission.builder()
 *         .main(E2.MAIN)
 *         .agent("a", new Default(), E2::new)
 *         .agent("b", new Default(), E2::new)
 *         .journal(System.out)
 *         .build()
 *         .run(Duration.ofMinutes(1));
 * }</pre>
 *
 * <p>Its deadlock watchdog ({@link DeadlockWatchdog}) ends a mission in which no agent will ever run
 * again unless something outside the mission acts.
 */
public final class Mission {

    /** How often the deadlock watchdog looks; a deadlock is reported after two looks agree. */
    public static final Duration WATCHDOG_PERIOD = Duration.ofMillis(100);
    /** The emitter of an event raised from outside the mission ({@link #emitFromOutside}): no agent. */
    public static final int OUTSIDE = -1;

    private final List<Agent> agents;
    /** The agents' MASL names by proxy id, for the trace. */
    private final List<String> agentNames;
    private final Map<EntryDefinition, Entry> entries;
    private final Scheduler scheduler;
    private final Journal journal;
    private final ChangeEpoch changes = new ChangeEpoch();
    private final Trace trace;
    private final EntryCoordinator coordinator;
    private final AtomicBoolean started = new AtomicBoolean();
    private final AtomicInteger running;
    private final CountDownLatch ended = new CountDownLatch(1);
    private final AtomicReference<Throwable> failure = new AtomicReference<>();
    /** The first agent whose program died; the mission went on without it, and fails once over. */
    private final AtomicReference<Throwable> firstDeath = new AtomicReference<>();
    private volatile boolean stopped;
    /** Why {@link #stop(String)} stopped the mission, for its {@code mission-ended} record; null if not said. */
    private volatile String stopReason;
    /** Wake-ups counted and pending, for the deadlock watchdog. */
    private final WakeUps wakeUps;
    private final DeadlockWatchdog watchdog;
    /** Made with the mission: when it is written, the heap may have no room. */
    private final MissionEnd end;
    /** {@link #run} has seen the end (whatever it was) and is stopping the scheduler. */
    private volatile boolean over;
    /** Asynchronous primitives running: the mission completes when they and every program are over. */
    private final AtomicInteger runningPrimitives = new AtomicInteger();
    private final PrimitiveCalls primitiveCalls;

    private Mission(Builder builder) {
        scheduler = builder.scheduler != null ? builder.scheduler : new PoolScheduler();
        journal = new Journal(builder.journalSink);
        trace = builder.trace;
        primitiveCalls = new PrimitiveCalls(scheduler, builder.callTimeout);
        wakeUps = builder.wakeUps;
        coordinator = new EntryCoordinator(this, trace, scheduler::nanoTime, changes);
        Map<EntryDefinition, Entry> blocks = new IdentityHashMap<>();
        if (builder.main != null) {
            addEntries(builder.main, null, blocks);
        }
        entries = Collections.unmodifiableMap(blocks);
        List<Agent> created = new ArrayList<>();
        for (Builder.AgentDeclaration declaration : builder.agents) {
            created.add(declaration.create(created.size(), this, builder.around));
        }
        agents = Collections.unmodifiableList(created);
        agentNames = builder.agents.stream().map(Builder.AgentDeclaration::name).toList();
        running = new AtomicInteger(agents.size());
        coordinator.addAgents(agents);
        watchdog = new DeadlockWatchdog(agents, wakeUps, running, builder.openToOutsideInvocations);
        end = new MissionEnd(agents, coordinator, trace, scheduler::nanoTime);
        MemoryReserve.hold();
    }

    private void addEntries(EntryDefinition definition, Entry parent, Map<EntryDefinition, Entry> blocks) {
        Entry entry = new Entry(definition, parent, coordinator);
        blocks.put(definition, entry);
        for (EntryDefinition child : definition.children()) {
            addEntries(child, entry, blocks);
        }
    }

    public static Builder builder() {
        return new Builder();
    }

    /**
     * Starts every agent's program and waits until the mission ends or {@code timeout} elapses,
     * then stops the scheduler's threads. Runs once per mission.
     *
     * @throws InterruptedException if the calling thread is interrupted while waiting
     */
    public MissionOutcome run(Duration timeout) throws InterruptedException {
        if (!started.compareAndSet(false, true)) {
            throw new IllegalStateException("a mission runs once");
        }
        if (agents.isEmpty()) {
            ended.countDown();
        }
        trace.record(new TraceEvent.MissionStarted(scheduler.nanoTime(), agentNames));
        MemoryReserve.watch(outOfMemory);
        MissionOutcome.Status status;
        try {
            scheduler.start(agents);
            status = awaitEnd(timeout);
        } catch (OutOfMemoryError exhausted) {
            MemoryReserve.exhausted();
            status = MissionOutcome.Status.FAILED;
        } finally {
            MemoryReserve.forget(outOfMemory);
        }
        // Decided: the agents park at their next yield, so that none takes the room the end is written
        // in, and what fails from now on does not change the outcome.
        over = true;
        halted = true;
        Throwable cause = failure.get() != null ? failure.get() : firstDeath.get();
        String report = end.write(status, stopReason);
        scheduler.shutdown();
        primitiveCalls.shutdownNow();
        journal.flush();
        return new MissionOutcome(status, journal.text(), Optional.ofNullable(cause), report);
    }

    /**
     * Waits for the end, looking for a deadlock every {@link #WATCHDOG_PERIOD} ({@link DeadlockWatchdog}). A pending sleep or awaited future holds the verdict off: what
     * ends it is unknown, so it is given the benefit of the doubt.
     */
    private MissionOutcome.Status awaitEnd(Duration timeout) throws InterruptedException {
        long deadline = System.nanoTime() + timeout.toNanos();
        while (true) {
            long left = deadline - System.nanoTime();
            boolean ended = this.ended.await(Math.min(left, WATCHDOG_PERIOD.toNanos()), TimeUnit.NANOSECONDS);
            if (failure.get() != null) {
                return MissionOutcome.Status.FAILED;
            }
            if (stopped) {
                return MissionOutcome.Status.STOPPED;
            }
            if (ended) {
                return firstDeath.get() == null ? MissionOutcome.Status.COMPLETED : MissionOutcome.Status.FAILED;
            }
            if (deadline - System.nanoTime() <= 0) {
                return MissionOutcome.Status.TIMED_OUT;
            }
            if (watchdog.deadlocked()) {
                return firstDeath.get() == null ? MissionOutcome.Status.DEADLOCKED : MissionOutcome.Status.FAILED;
            }
        }
    }

    /** Made before it is needed: when it is, the heap has no room. */
    private final MissionOutOfMemory heapExhausted = new MissionOutOfMemory();
    /** The heap was exhausted, or the mission's end decided: agents stop at their next yield, allocating no more. */
    private volatile boolean halted;
    /** The heap is exhausted ({@link MemoryReserve}): the mission fails at once. */
    private final Runnable outOfMemory = () -> {
        halted = true;
        if (failure.compareAndSet(null, heapExhausted)) {
            ended.countDown();
        }
    };

    /** Whether its agents run no more: the heap was exhausted, or the mission's end is decided. */
    boolean halted() {
        return halted;
    }

    /** Stops the mission from outside: {@link #run} returns {@link MissionOutcome.Status#STOPPED}. */
    public void stop() {
        stopped = true;
        ended.countDown();
    }

    /**
     * Stops the mission as {@link #stop()} does, saying why: the {@code mission-ended} record of the
     * trace carries {@code reason} (the first one given, if stopped more than once).
     */
    public void stop(String reason) {
        if (stopReason == null) {
            stopReason = Objects.requireNonNull(reason, "reason");
        }
        stop();
    }

    public Journal journal() {
        return journal;
    }

    /**
     * Queues an invocation of one of agent {@code proxyId}'s primitives made from outside the
     * mission's agents (the JADE bridge serves a FIPA agent's {@code REQUEST} so). It runs as MASL §5
     * has external invocations run: at the agent's next step boundary or loop iteration, or at once
     * on its behalf if the agent is blocked or has finished; a busy-waiting agent sees it as a
     * change. {@code invocation} runs the primitive only, and must not block for long. Invocations
     * queued after the mission has ended are never run.
     *
     * @throws IndexOutOfBoundsException if no agent has that proxy id
     */
    public void submitInvocation(int proxyId, Runnable invocation) {
        Agent callee = agents.get(proxyId);
        PendingInvocation pending = PendingInvocation.unfiltered(Objects.requireNonNull(invocation, "invocation"));
        fromOutside(() -> callee.submitInvocation(pending));
    }

    /**
     * The agent running {@code implementation}. <b>Internal:</b> not part of the API.
     *
     * @throws IllegalArgumentException if it runs no agent of this mission
     */
    public Agent agentOf(AgentImplementation implementation) {
        int proxyId = implementation.services().proxyId();
        if (proxyId < 0 || proxyId >= agents.size() || agents.get(proxyId).implementation != implementation) {
            throw new IllegalArgumentException(implementation + " is no agent of this mission");
        }
        return agents.get(proxyId);
    }

    /**
     * The current permeability state's name of agent {@code proxyId} ({@code getAcceptState(a)},
     * MASL §11), {@code ""} if its type has no states: for requesters outside the mission, such as
     * the JADE bridge, which filter their own requests as an "other" (o).
     *
     * @throws IndexOutOfBoundsException if no agent has that proxy id
     */
    public String acceptState(int proxyId) {
        return agents.get(proxyId).getAcceptState();
    }

    /**
     * Queues an invocation of primitive {@code primitive} of agent {@code proxyId} from outside the
     * mission's agents, filtered by permeability as a requester of the kind "other" (o, MASL §11):
     * when the agent serves it, by its state then, either {@code invocation} runs or {@code denial}
     * does (the primitive did not run). Otherwise as {@link #submitInvocation(int, Runnable)}.
     *
     * @throws IndexOutOfBoundsException if no agent has that proxy id
     */
    public void submitInvocation(int proxyId, String primitive, Runnable invocation, Runnable denial) {
        Agent callee = agents.get(proxyId);
        PendingInvocation pending = fromOther(primitive, invocation, denial);
        fromOutside(() -> callee.submitInvocation(pending));
    }

    /** An invocation whose requester is an <em>other</em> (MASL §11), filtered when it is served. */
    private static PendingInvocation fromOther(String primitive, Runnable invocation, Runnable denial) {
        return new PendingInvocation(null, Objects.requireNonNull(primitive, "primitive"),
                Objects.requireNonNull(invocation, "invocation"), Objects.requireNonNull(denial, "denial"));
    }

    /** The caller runs no agent's slice: its wake-ups (serving, busy-waits) are pending until it returns. */
    private void fromOutside(Runnable submission) {
        outsideWakeUpStarted();
        try {
            submission.run();
        } finally {
            outsideWakeUpEnded();
        }
    }

    /**
     * Submits an invocation as {@link #submitInvocation(int, String, Runnable, Runnable)} does, but
     * if agent {@code proxyId} is blocked or has finished, serves it at once on the calling thread
     * (MASL §5 serves such an agent's invocations on its behalf at once), filtered by its state then,
     * with the agent's serving exclusion: its program does not resume until the invocation has run.
     * Once the mission has ended, it is never run, as a queued one is not. A running agent still
     * serves it at its next step boundary or loop iteration, on its own thread. For a requester
     * whose thread may run the primitive (the JADE bridge's message thread of the agent answers so
     * without a hop to the agent's thread); {@code invocation} and {@code denial} must not wait for
     * the calling thread.
     *
     * @throws IndexOutOfBoundsException if no agent has that proxy id
     */
    public void serveOrQueueInvocation(int proxyId, String primitive, Runnable invocation, Runnable denial) {
        Agent callee = agents.get(proxyId);
        PendingInvocation pending = fromOther(primitive, invocation, denial);
        fromOutside(() -> callee.submitInvocationServingInline(pending));
    }

    /**
     * Whether block {@code block} declares {@code eventName} as a shared event: not a local event
     * (perceived by its emitter alone) nor a system event. Any thread.
     */
    public boolean declaresSharedEvent(String block, String eventName) {
        for (EntryDefinition definition : entries.keySet()) {
            if (definition.name().equals(block) && definition.sharedEvent(eventName).isPresent()) {
                return true;
            }
        }
        return false;
    }

    /**
     * A shared event raised from outside the mission (a FIPA agent, through the JADE bridge): every
     * member of each block declaring a shared event {@code eventName} perceives it now, as if one of
     * them had emitted it with {@code message}; its emitter is no agent ({@link #OUTSIDE}). Any thread.
     *
     * @return how many agents perceived it (0: no block declares it, or none has members now)
     */
    public int emitFromOutside(String eventName, String message) {
        int perceived = 0;
        for (Map.Entry<EntryDefinition, Entry> block : entries.entrySet()) {
            Optional<Event> event = block.getKey().sharedEvent(eventName);
            if (event.isEmpty()) {
                continue;
            }
            Agent[] receivers = block.getValue().perceivers();
            trace.record(new TraceEvent.EventEmitted(System.nanoTime(), OUTSIDE, eventName, block.getValue().name(),
                    message, receivers.length, null));
            EventOccurrence occurrence = new EventOccurrence(event.get(), message, OUTSIDE);
            fromOutside(() -> {
                for (Agent receiver : receivers) {
                    receiver.perceive(occurrence);
                }
            });
            perceived += receivers.length;
        }
        return perceived;
    }

    /**
     * Whether agent {@code proxyId}'s current permeability state lets an agent outside the mission (an
     * <em>other</em>, MASL §11) read its attribute {@code attribute}; a type without states allows it.
     */
    public boolean othersMayRead(int proxyId, String attribute) {
        return agents.get(proxyId).othersMayRead(attribute);
    }

    /** The mission state of a block of this mission's program. */
    public Entry entry(EntryDefinition definition) {
        Entry entry = entries.get(definition);
        if (entry == null) {
            throw new IllegalArgumentException(definition + " is not a block of this mission's program");
        }
        return entry;
    }

    /** <b>Internal:</b> not part of the API. */
    public Scheduler scheduler() {
        return scheduler;
    }

    Trace trace() {
        return trace;
    }

    ChangeEpoch changes() {
        return changes;
    }

    EntryCoordinator coordinator() {
        return coordinator;
    }

    /**
     * Runs the body of an asynchronous primitive launched by {@code requester} as the scheduler
     * runs primitives ({@link Scheduler#runPrimitive}: on a thread of its own, or as a task it
     * orders); until it returns, the deadlock watchdog knows a wake-up may come. An {@code Error}
     * in it fails the mission; exceptions are the body's to turn into events.
     */
    void runAsynchronously(Agent requester, Runnable body) {
        outsideWakeUpStarted();
        runningPrimitives.incrementAndGet();
        try {
            scheduler.runPrimitive(() -> {
                try {
                    body.run();
                } catch (Throwable failure) {
                    agentFailed(requester, failure);
                } finally {
                    primitiveEnded();
                }
            }, primitiveCalls.threads());
        } catch (RejectedExecutionException missionEnded) {
            primitiveEnded();
        }
    }

    private void primitiveEnded() {
        outsideWakeUpEnded();
        // Decrement, then look at the other count; agentFinished does the converse: the later one sees both at 0.
        if (runningPrimitives.decrementAndGet() == 0 && running.get() == 0) {
            ended.countDown();
        }
    }

    /** Whether the mission has ended or is ending: an invocation submitted now is never run. */
    boolean hasEnded() {
        return over || ended.getCount() == 0;
    }

    /** <b>Internal:</b> not part of the API. */
    public void countSchedule() {
        wakeUps.counted();
    }

    /** <b>Internal:</b> not part of the API. A wake-up may come from outside the agents' slices until {@link #outsideWakeUpEnded}. */
    public void outsideWakeUpStarted() {
        wakeUps.pendingStarted();
    }

    /** <b>Internal:</b> not part of the API. */
    public void outsideWakeUpEnded() {
        wakeUps.pendingEnded();
    }

    void agentFinished(Agent agent) {
        if (running.decrementAndGet() == 0 && runningPrimitives.get() == 0) {
            ended.countDown();
        }
    }

    /** The agent's program died and it has left its blocks: the others go on, the mission will fail. */
    void agentDied(Agent agent, Throwable cause) {
        firstDeath.compareAndSet(null, new IllegalStateException(agent.describe() + " failed", cause));
        agentFinished(agent);
    }

    /** How the mission runs its primitives' Java code (the agents' invocations and launches). */
    PrimitiveCalls primitiveCalls() {
        return primitiveCalls;
    }

    void agentFailed(Agent agent, Throwable cause) {
        if (cause instanceof OutOfMemoryError) {
            MemoryReserve.exhausted();
        }
        if (failure.compareAndSet(null, new IllegalStateException(agent.describe() + " failed", cause))) {
            ended.countDown();
        }
    }

    /** Builds a mission: agents in declaration order, the program's {@code main}, and options. */
    public static final class Builder {

        private record AgentDeclaration(String name, AgentImplementation implementation, AgentType type,
                Function<AgentImplementation, ? extends AgentProgram> program) {

            Agent create(int id, Mission mission, BiFunction<String, AgentProgram, AgentProgram> around) {
                implementation.bind(new MissionServices(id, mission.journal));
                return new Agent(id, name, implementation, type, around.apply(name, program.apply(implementation)), mission);
            }
        }

        private final List<AgentDeclaration> agents = new ArrayList<>();
        private EntryDefinition main;
        private Scheduler scheduler;
        private Appendable journalSink;
        private Trace trace = Trace.NONE;
        private boolean openToOutsideInvocations;
        private Duration callTimeout;
        private WakeUps wakeUps = new WakeUps();
        private BiFunction<String, AgentProgram, AgentProgram> around = (name, program) -> program;

        private Builder() { }

        /** Each agent runs {@code around(name, program)}: the JADE bridge stands in for programs it deploys. */
        public Builder programs(BiFunction<String, AgentProgram, AgentProgram> stand) {
            this.around = Objects.requireNonNull(stand, "stand");
            return this;
        }

        DeployedPrograms.Made madeOutsideAMission() {
            return new DeployedPrograms.Made(main,
                    agents.stream().<AgentProgram>map(a -> a.program.apply(a.implementation)).toList(),
                    agents.stream().map(AgentDeclaration::type).toList());
        }

        /**
         * Declares the next agent (its proxy id is the number of agents declared before it):
         * {@code implementation} is bound to the agent's services, then {@code program} makes the
         * agent's program for it.
         */
        public <T extends AgentImplementation> Builder agent(String name, T implementation,
                Function<? super T, ? extends AgentProgram> program) {
            return agent(name, implementation, null, program);
        }

        /**
         * Declares the next agent as {@link #agent(String, AgentImplementation, Function)} does, with
         * its type as loaded from its descriptor: its permeability states apply (MASL §11). An agent
         * declared without a type allows everything.
         */
        @SuppressWarnings("unchecked")
        public <T extends AgentImplementation> Builder agent(String name, T implementation, AgentType type,
                Function<? super T, ? extends AgentProgram> program) {
            Objects.requireNonNull(implementation, "implementation");
            Objects.requireNonNull(program, "program");
            agents.add(new AgentDeclaration(name, implementation, type,
                    impl -> program.apply((T) impl)));
            return this;
        }

        /** The program's top-level block; a program without one only creates its agents. */
        public Builder main(EntryDefinition main) {
            if (main.parent() != null) {
                throw new IllegalArgumentException(main + " is not a top-level block");
            }
            this.main = main;
            return this;
        }

        /** Who runs the agents: a {@link PoolScheduler} of one worker per core unless set. */
        public Builder scheduler(Scheduler scheduler) {
            this.scheduler = scheduler;
            return this;
        }

        /** Where the journal is written as it grows, besides {@link Journal#text()}. */
        public Builder journal(Appendable sink) {
            this.journalSink = sink;
            return this;
        }

        public Builder trace(Trace trace) {
            this.trace = Objects.requireNonNull(trace, "trace");
            return this;
        }

        /**
         * Declares that invocations may come from outside the mission's agents
         * ({@link Mission#submitInvocation}: FIPA agents, through the JADE bridge). An outside
         * invocation is a change a busy-wait observes, so while any agent is parked in a busy-wait
         * the deadlock watchdog does not end the mission: only its timeout or {@link #stop()} do.
         * Agents that all wait at barriers (or are done) are still a deadlock: an invocation served
         * on a blocked agent's behalf does not move it.
         */
        public Builder openToOutsideInvocations() {
            this.openToOutsideInvocations = true;
            return this;
        }

        /**
         * Bounds every primitive call of the mission's agents (internal, external, asynchronous): a
         * call that runs longer gives its caller the primitive's default value and {@code timeout}
         * (its message the primitive's name), and the mission goes on. Without it, calls are not bounded.
         */
        public Builder callTimeout(Duration timeout) {
            if (timeout.isNegative() || timeout.isZero()) {
                throw new IllegalArgumentException("a call timeout must be positive: " + timeout);
            }
            this.callTimeout = timeout;
            return this;
        }

        /** The watchdog's accounting: tests give one that stalls a wake-up. */
        Builder wakeUps(WakeUps wakeUps) {
            this.wakeUps = Objects.requireNonNull(wakeUps, "wakeUps");
            return this;
        }

        public Mission build() {
            return new Mission(this);
        }
    }
}
