package masl.jade.deployment;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.ForkJoinTask;
import java.util.concurrent.ForkJoinWorkerThread;
import java.util.concurrent.ThreadFactory;
import java.util.concurrent.TimeUnit;
import masl.runtime.AgentImplementation;
import masl.runtime.DeployedPrograms;
import masl.runtime.MissionProgram;
import masl.runtime.RemotePrimitiveException;
import masl.runtime.descriptor.AgentType;

/**
 * The deployed agents of one container: their programs, made here from the program this container
 * translated itself, each running its steps when the mission says {@code resume}, against a
 * {@link RemoteContext}; the Java code the programs hand over, run when the mission asks; and what
 * their primitives write to the journal, sent with the container's next message. The mission
 * ({@link Coordination}) decides everything else.
 */
public final class DeployedTeam implements AutoCloseable {

    /** No agent runs here to begin with: each waits for its first step. */
    private final Outbox outbox;
    private final List<AgentImplementation> agents;
    /** The context of each agent that runs here, by proxy id (null for the others): fixed once made. */
    private final RemoteContext[] hosted;
    private final Callbacks callbacks = new Callbacks();
    private final Requests requests = new Requests();
    private final TeamMembers members = new TeamMembers();
    private final TeamJournal journal = new TeamJournal();
    /**
     * The agents' steps: a thread per core, a step holding one only while it runs, since a program
     * returns from the calls after which it waits for the mission's resumption (RemoteContext); a step
     * waiting for a value in a call has another thread stand in for it meanwhile ({@link #await}).
     */
    private final ExecutorService steps = new ForkJoinPool(Runtime.getRuntime().availableProcessors(),
            DeployedTeam::stepThread, null, true, 0, MAX_STEP_THREADS, 1, pool -> true, 30, TimeUnit.SECONDS);
    private final ExecutorService calls = Executors.newCachedThreadPool(daemon("masl-deployed-call"));
    private volatile String lost;
    /** The most threads the steps' pool has, standing in for steps that wait in a call: its limit. */
    private static final int MAX_STEP_THREADS = 0x7fff;

    /**
     * Makes the programs of {@code program}'s agents named in {@code names}, with implementations
     * {@code implementations} gives (every agent's: a program may name any agent), bound to this
     * container's services.
     */
    public DeployedTeam(MissionProgram program, Set<String> names, MissionProgram.ImplementationFactory implementations,
            Wire toMission) {
        this.outbox = new Outbox(toMission, 0);
        this.agents = new ArrayList<>();
        List<AgentType> types = Coordination.typesOf(program, implementations);
        DeployedPrograms.Made made = DeployedPrograms.outsideAMission(program, spec -> {
            int id = agents.size();
            // The agents that run elsewhere are stubs here: invoking them names the primitive.
            AgentImplementation implementation = members.implementation(id, types.get(id),
                    implementations.create(spec), names.contains(spec.name()));
            implementation.bind(journal.servicesOf(id));
            agents.add(implementation);
            return implementation;
        });
        List<MissionProgram.AgentSpec> specs = program.agents();
        this.hosted = new RemoteContext[specs.size()];
        for (int id = 0; id < specs.size(); id++) {
            if (names.contains(specs.get(id).name())) {
                hosted[id] = new RemoteContext(id, made.programs().get(id), new OwnPermeability(made.types().get(id)), this);
            }
        }
    }

    List<AgentImplementation> agents() {
        return agents;
    }

    Callbacks callbacks() {
        return callbacks;
    }

    Requests requests() {
        return requests;
    }

    TeamMembers members() {
        return members;
    }

    /** The context of agent {@code proxyId} if it runs here, else null. */
    RemoteContext context(int proxyId) {
        return proxyId >= 0 && proxyId < hosted.length ? hosted[proxyId] : null;
    }

    /**
     * A message from the mission: a step to run, an answer to a request, a call to run; or a batch of
     * them, in the order the mission made them. The steps a batch lets go on start once it is all
     * taken.
     */
    public void receive(ObjectNode message) {
        List<ObjectNode> each = Batch.each(message);
        // Every agent let go runs from now on: counted before any runs, so that none sends alone.
        int goingOn = 0;
        for (ObjectNode inner : each) {
            if (letsGoOn(inner)) {
                goingOn++;
            }
        }
        if (goingOn > 0) {
            outbox.busy(goingOn);
        }
        List<Runnable> wave = new ArrayList<>();
        each.forEach(inner -> take(inner, wave));
        start(wave);
    }

    /**
     * Starts the steps a message let go on. A wave's steps are forked by one task of the pool, which
     * wakes its idle threads once, where each submission from outside would signal the pool again.
     */
    private void start(List<Runnable> wave) {
        if (wave.size() == 1) {
            steps.execute(wave.get(0));
        } else if (!wave.isEmpty()) {
            steps.execute(() -> wave.forEach(step -> ForkJoinTask.adapt(step).fork()));
        }
    }

    private boolean letsGoOn(JsonNode message) {
        String kind = message.path("kind").asText();
        boolean goesOn = "resume".equals(kind) || "answer".equals(kind) || inStep(message);
        return goesOn && context(message.path("agent").intValue()) != null;
    }

    private void take(ObjectNode message, List<Runnable> wave) {
        RemoteContext agent = context(message.path("agent").intValue());
        switch (message.path("kind").textValue()) {
            case "resume" -> wave.add(() -> step(agent, message));
            case "answer" -> {
                if (agent.returning().resumption(message)) {
                    wave.add(() -> step(agent, message));
                } else {
                    agent.answered(message);
                }
            }
            case "attend" -> agent.quiet().attend(message.get("seq").longValue());
            case "run" -> {
                if (inStep(message)) {
                    // The agent's step waits for the mission and runs it: see RemoteContext#call.
                    agent.answered(message);
                } else {
                    calls.execute(() -> ran(agent, message, run(message)));
                }
            }
            case "primitive" -> calls.execute(() -> {
                // A primitive the mission served: never alongside one served here (CalleeTurn).
                agent.turn().missionRunBegins();
                try {
                    ran(agent, message, named(agent, message));
                } finally {
                    agent.turn().missionRunEnds();
                }
            });
            case "read", "write" -> calls.execute(() -> ran(agent, message, named(agent, message)));
            default -> throw new IllegalArgumentException("not a message of the mission: " + message);
        }
    }

    /** Whether {@code message} asks the step that waits for the mission to run code (a shared variable's function). */
    private static boolean inStep(JsonNode message) {
        return "run".equals(message.path("kind").asText()) && message.path("inStep").booleanValue();
    }

    private ObjectNode run(ObjectNode request) {
        return callbacks.run(request.get("call").longValue(), request.get("argument"));
    }

    /**
     * Runs the code {@code request} names on the thread of the step that waits for the mission (the
     * requests it makes are that step's), and answers; the step waits for the mission again.
     */
    void runInStep(RemoteContext agent, ObjectNode request) {
        ObjectNode answer = run(request);
        ran(agent, request, answer.put("inStep", true));
        outbox.busy(-1);
    }

    private void ran(RemoteContext agent, ObjectNode request, ObjectNode answer) {
        sendNow(answer.put("kind", "ran").put("agent", agent.id()).put("run", request.get("run").longValue()));
    }

    /** A primitive, read or write the mission asks of an agent's real object here, by name. */
    private ObjectNode named(RemoteContext agent, ObjectNode request) {
        try {
            return members.answer(agent.id(), agents.get(agent.id()), request, agents);
        } catch (RuntimeException | Error failure) {
            return Callbacks.threw(JsonNodeFactory.instance.objectNode(), failure);
        }
    }

    private void step(RemoteContext agent, ObjectNode resume) {
        agent.turn().programGoesOn();
        Throwable failed = null;
        try {
            agent.completeDone(resume.get("done"));
            agent.quiet().told(resume);
            DeployedPrograms.resume(agent.program(), resume.get("pc").intValue(), agent);
            // A call that suspended the step and was answered with its resumption: the step goes on here.
            while (agent.returning().resumedInCall()) {
                DeployedPrograms.resume(agent.program(), agent.program().pc(), agent);
            }
        } catch (MissionLost gone) {
            return;
        } catch (RuntimeException | Error failure) {
            failed = failure;
        }
        Batch.Held returnedFrom = failed != null ? null : agent.returning().taken();
        if (returnedFrom != null) {
            // The program returned from a call that waits for the mission's answer: no thread waits with it.
            if (CalleeTurn.restsDuring(returnedFrom.fields().get("op").textValue())) {
                agent.turn().programRests();
            }
            send(returnedFrom, agent.quiet().busyChangeOfNext());
            return;
        }
        agent.turn().programRests();
        // The step's end, made only now: most steps return from a call instead, which is their message.
        ObjectNode yield = resume.objectNode().put("kind", "yield").put("agent", agent.id());
        if (failed != null) {
            yield.put("failed", RemotePrimitiveException.classNameOf(failed)).put("message", String.valueOf(failed.getMessage()));
        }
        send(yield.put("pc", agent.program().pc()), agent.quiet().busyChangeOfNext());
    }

    /**
     * Sends {@code message}, after which its agent waits for the mission, with what was written to
     * the journal since the last message; {@code busyChange} to the steps running here (-1, or 0 for
     * one that counts as running no more, {@link #letGo}).
     */
    void send(ObjectNode message, int busyChange) {
        send(Batch.Held.of(message), busyChange);
    }

    /** Sends {@code message} as {@link #send(ObjectNode, int)} does; its fields are not changed, and may be shared. */
    synchronized void send(Batch.Held message, int busyChange) {
        if (journal.written()) {
            // The journal text goes in a copy: the message's fields may be shared.
            message = new Batch.Held(withJournal(message.fields().deepCopy()), message.agent(), message.seq());
        }
        outbox.add(message, busyChange);
    }

    /**
     * A step that passes its boundaries here for long ({@link QuietBoundaries#LONG_RUN}) counts as
     * busy no more: the others' messages go without waiting for it, as they would for a step that
     * waits for the mission.
     */
    void letGo() {
        outbox.busy(-1);
    }

    /**
     * Agent {@code requester} invoked {@code callee}'s {@code primitive} from the case {@code pc} of
     * its program, and this container served it: the mission traces it, with the container's next
     * message, in order with the journal text the primitive wrote.
     */
    synchronized void invokedHere(int requester, int callee, String primitive, int pc) {
        outbox.add(withJournal(JsonNodeFactory.instance.objectNode().put("kind", "invoked").put("agent", requester)
                .put("callee", callee).put("primitive", primitive).put("pc", pc)), 0);
    }

    /** Sends {@code message}, which the mission waits for, at once, with what was written to the journal. */
    private synchronized void sendNow(ObjectNode message) {
        outbox.now(withJournal(message));
    }

    private ObjectNode withJournal(ObjectNode message) {
        String written = journal.drain();
        if (!written.isEmpty()) {
            message.put("journal", written);
        }
        return message;
    }

    /**
     * The next answer in {@code answers}; throws {@link MissionLost} once the mission is gone. A step's
     * thread waits as a blocker of its pool, which starts another meanwhile for the steps to run.
     */
    ObjectNode await(BlockingQueue<ObjectNode> answers) {
        Answer answer = new Answer(answers);
        try {
            ForkJoinPool.managedBlock(answer);
        } catch (InterruptedException interrupted) {
            Thread.currentThread().interrupt();
            throw new MissionLost("interrupted");
        }
        return answer.taken;
    }

    /** Waiting for the next answer in a queue, checking every 100 ms that the mission is still there. */
    private final class Answer implements ForkJoinPool.ManagedBlocker {
        private final BlockingQueue<ObjectNode> answers;
        private ObjectNode taken;

        Answer(BlockingQueue<ObjectNode> answers) {
            this.answers = answers;
        }

        @Override
        public boolean block() throws InterruptedException {
            while (taken == null) {
                taken = answers.poll(100, TimeUnit.MILLISECONDS);
                if (taken == null && lost != null) {
                    throw new MissionLost(lost);
                }
            }
            return true;
        }

        @Override
        public boolean isReleasable() {
            if (taken == null) {
                taken = answers.poll();
            }
            return taken != null;
        }
    }

    /**
     * Throws {@link MissionLost} once the mission is gone: a step that passes its boundaries here
     * without a message ({@link QuietBoundaries}) ends then, as one waiting for an answer does.
     */
    void requireMission() {
        String why = lost;
        if (why != null) {
            throw new MissionLost(why);
        }
    }

    /** Whether this container's agents wrote to the journal since its last message. */
    boolean written() {
        return journal.written();
    }

    /** The mission is gone ({@code why}): steps waiting for it end, and no step starts. */
    public void lose(String why) {
        lost = why;
        steps.shutdownNow();
        calls.shutdownNow();
    }

    @Override
    public void close() {
        lose("the mission has ended");
    }

    private static ForkJoinWorkerThread stepThread(ForkJoinPool pool) {
        ForkJoinWorkerThread thread = ForkJoinPool.defaultForkJoinWorkerThreadFactory.newThread(pool);
        thread.setName("masl-deployed-step-" + thread.getPoolIndex());
        return thread;
    }

    private static ThreadFactory daemon(String name) {
        return work -> {
            Thread thread = new Thread(work, name);
            thread.setDaemon(true);
            return thread;
        };
    }

    /** The mission is gone while a step waited for its answer: the step ends without one. */
    static final class MissionLost extends RuntimeException {
        private static final long serialVersionUID = 1L;

        MissionLost(String why) {
            super(why);
        }
    }
}
