package masl.jade.deployment;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.NullNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.Iterator;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Function;
import masl.runtime.AgentContext;
import masl.runtime.AgentProgram;
import masl.runtime.DeployedPrograms;
import masl.runtime.Reaction;
import masl.runtime.RemotePrimitiveException;

/**
 * A deployed agent's program as its mission runs it: a step is the container's. {@link #resume}
 * tells the container to run the agent's program from here, then performs each request the program
 * makes on this agent's context, in the agent's slices, and answers it, until the container says the
 * step is over. While the step runs in its container, the agent waits for its next message parked,
 * holding no thread ({@link StepMessages#awaitElsewhere}), and the message's arrival makes it
 * runnable: the slice the mission's scheduler then runs takes the message up where the last left off. A call after which the program returns
 * from its step (a boundary that parks it at a barrier) gets no answer then: the program waits in it
 * until the mission resumes this step, and the answer says so, with the resumption point, so that a
 * step costs its container one request and one answer, and no message of the step's own. The program's reactions and MASL source are
 * those of the same generated class, made here too ({@code twin}), whose code never runs here.
 */
final class StandIn extends AgentProgram {

    /**
     * The calls after which generated code returns from its step when they answer false
     * ({@code if (!ctx.stepBoundary()) return;}): boundaries, waits and sleeps. No label request
     * ({@code label-…}) ends a step: waiting on a label is a busy-wait ({@code while
     * (!isFinished(l)) {}}, each iteration a {@code busyWaitIteration}), and a labelled synchronous
     * call ends in an {@code await} of the call's future, both listed. An {@code enter} that answers
     * {@code WAITING} ends the step too, but answers a name, not false, and is not listed: it is
     * answered, and the container ends its step.
     */
    private static final Set<String> SUSPENDING = Set.of("stepBoundary", "loopIteration", "busyWaitIteration",
            "endOfChild", "endOfSequence", "leave", "endReaction", "resumeInterrupted", "sleep", "await", "waitFor");

    private final int id;
    private final AgentProgram twin;
    private final Coordination coordination;
    /** Marks the answer of code run in the step coming in, after the requests that code made. */
    private static final ObjectNode RAN = JsonNodeFactory.instance.objectNode();

    private final StepMessages requests = new StepMessages();
    /** The futures of calls the program made that it has not been told the end of, by call number. */
    private final Map<Long, CompletableFuture<Object>> calls = new ConcurrentHashMap<>();
    /** Orders the messages to the step that say whether its boundaries are at rest, and numbers them. */
    private final Object toStep = new Object();
    /** The number of the latest message to the step; guarded by {@link #toStep}. */
    private long sent;
    /**
     * Whether the step runs in its container, passing its boundaries there, since the latest message
     * said they are at rest; guarded by {@link #toStep}.
     */
    private boolean passing;
    /** Whether the program waits in a call that suspended its step, confined to the agent's slices. */
    private boolean suspended;
    /**
     * Whether the step runs in its container, the agent parked until its next message: the next
     * slice takes it, telling the container nothing first. Confined to the agent's slices.
     */
    private boolean away;
    /**
     * Whether a call performed for the step parked the agent (an {@code enter} that waits) and the
     * slice returned before the step's end came: the next slice, once the agent is let go, takes that
     * {@code yield} first. Confined to the agent's slices.
     */
    private boolean endOwed;
    private boolean finished;
    /** Its container's outbox, once the mission named it ({@link Coordination}): the same from then on. */
    private volatile Outbox outbox;

    StandIn(int id, AgentProgram twin, Coordination coordination) {
        this.id = id;
        this.twin = twin;
        this.coordination = coordination;
    }

    int id() {
        return id;
    }

    Outbox outbox() {
        return outbox;
    }

    void outbox(Outbox outbox) {
        this.outbox = outbox;
    }

    void requested(ObjectNode request) {
        requests.add(request);
    }

    void track(long call, CompletableFuture<Object> future) {
        calls.put(call, future);
    }

    CompletableFuture<Object> call(long number) {
        return calls.get(number);
    }

    @Override
    protected void resume(AgentContext ctx) {
        if (endOwed) {
            ObjectNode end = requests.poll();
            if (end == null) {
                if (requests.awaitElsewhere(ctx)) {
                    return;
                }
                end = coordination.await(id, requests);
            }
            endOwed = false;
            if (!"yield".equals(end.path("kind").textValue())) {
                throw new IllegalStateException("agent " + id + "'s step went on after a call parked it: " + end);
            }
            endOfStep(ctx, taken(ctx, end));
        }
        if (away) {
            away = false;
        } else if (suspended) {
            // The program waits in the call that suspended it: the answer is its resumption, from pc.
            suspended = false;
            wakeUp(ctx, true);
        } else {
            wakeUp(ctx, false);
        }
        while (true) {
            ObjectNode message = requests.poll();
            if (message == null) {
                if (requests.awaitElsewhere(ctx)) {
                    away = true;
                    return;
                }
                // A call performed for the step parked the agent (an enter that waits): only the
                // step's end comes, and the slice that runs once the agent is let go takes it.
                endOwed = true;
                return;
            }
            ObjectNode request = taken(ctx, message);
            if ("yield".equals(request.get("kind").textValue())) {
                endOfStep(ctx, request);
                return;
            }
            String op = request.get("op").textValue();
            if ("finish".equals(op)) {
                // The program returns right after the answer (AgentContext#finish): its step's end
                // comes next, and the agent finishes here once it has, parked meanwhile, so that no
                // thread waits for it and the mission, which may end then, has every message of it.
                finished = true;
                answer(ctx, NullNode.getInstance());
                continue;
            }
            JsonNode value = coordination.calls().perform(this, ctx, request);
            if (SUSPENDING.contains(op) && !value.booleanValue()) {
                // The program returns from its step on false: it does here, and its container hears
                // nothing until the step is resumed (a barrier's trip, most often).
                suspended = true;
                return;
            }
            answer(ctx, value);
        }
    }

    /**
     * The step ended ({@code yield}): throws what failed it; a program that finished in it finishes
     * here, and its container no longer waits for it.
     */
    private void endOfStep(AgentContext ctx, ObjectNode end) {
        if (end.has("failed")) {
            coordination.ended(this);
            throw new RemotePrimitiveException(end.get("failed").textValue(), end.path("message").textValue());
        }
        if (finished) {
            ctx.finish();
            coordination.ended(this);
        }
    }

    private void answer(AgentContext ctx, JsonNode value) {
        toStep(ctx, rest -> {
            ObjectNode answer = JsonNodeFactory.instance.objectNode().put("kind", "answer").put("pc", pc);
            answer.set("value", value);
            return WakeUps.withRest(answer, rest);
        });
    }

    /** Lets the step go on with nothing to give it ({@link WakeUps}): the call's resumption if {@code resumed}, else the start of a step. */
    private void wakeUp(AgentContext ctx, boolean resumed) {
        toStep(ctx, rest -> coordination.wakeUps().of(resumed, pc, rest));
    }

    /**
     * Sends the message that lets the step go on in its container, made by {@code fields} of whether
     * its boundaries are at rest ({@link QuietBoundaries}; null if not), read after what arrived
     * before the lock; numbered.
     */
    private void toStep(AgentContext ctx, Function<DeployedPrograms.AtRest, ObjectNode> fields) {
        synchronized (toStep) {
            DeployedPrograms.AtRest rest = DeployedPrograms.atRest(ctx);
            passing = rest != null;
            coordination.send(this, withDone(fields.apply(rest)), ++sent);
        }
    }

    /**
     * An event or invocation arrived for the agent (any thread): if its step runs in its container
     * passing its boundaries there, the next one comes here ({@code attend}). Otherwise the step
     * waits for a message of the mission, which says so.
     */
    void boundaryWork() {
        synchronized (toStep) {
            if (passing) {
                passing = false;
                coordination.push(this, JsonNodeFactory.instance.objectNode().put("kind", "attend").put("seq", ++sent));
            }
        }
    }

    /**
     * A message of the step: it waits for the mission from now on; the boundaries it passed in its
     * container since its last request count as the runtime's own, before the request is performed.
     */
    private ObjectNode taken(AgentContext ctx, ObjectNode request) {
        synchronized (toStep) {
            passing = false;
        }
        pc = request.path("pc").intValue();
        if (request.has("passed")) {
            DeployedPrograms.passedElsewhere(ctx, request.get("passed").longValue(),
                    request.get("latest").intValue());
        }
        return request;
    }

    /**
     * Runs the program's code {@code call} on {@code argument} (a shared variable's initialiser or
     * update function) in the step that waits in its container for the request being performed, and
     * performs the requests that code makes meanwhile on this thread, which may hold the variable's
     * lock: the code's answer ({@code ran}), or what it threw.
     */
    ObjectNode runInStep(AgentContext ctx, long call, JsonNode argument) {
        CompletableFuture<ObjectNode> ran = coordination.runInStep(id, call, argument);
        ran.whenComplete((answer, failed) -> requests.add(RAN));
        while (true) {
            ObjectNode request = coordination.await(id, requests);
            if (request == RAN) {
                return Coordination.outcome(ran.join());
            }
            if (!"call".equals(request.path("kind").textValue())) {
                throw new IllegalStateException("agent " + id + "'s step ended while it ran code for the mission");
            }
            answer(ctx, coordination.calls().perform(this, ctx, taken(ctx, request)));
        }
    }

    /**
     * {@code message} with the calls that are over since the last message, so that the program's
     * futures complete: {@code "done"}, absent if none is (most messages of a wave); a copy of it if
     * it has some, since a wake-up's fields are shared.
     */
    private ObjectNode withDone(ObjectNode message) {
        if (calls.isEmpty()) {
            return message;
        }
        ObjectNode withDone = message;
        ArrayNode done = null;
        for (Iterator<Map.Entry<Long, CompletableFuture<Object>>> it = calls.entrySet().iterator(); it.hasNext(); ) {
            Map.Entry<Long, CompletableFuture<Object>> call = it.next();
            if (call.getValue().isDone()) {
                if (done == null) {
                    withDone = message.deepCopy();
                    done = withDone.putArray("done");
                }
                done.add(ended(call.getValue().join()).put("call", call.getKey()));
                it.remove();
            }
        }
        return withDone;
    }

    /**
     * How a call of the program that ended with {@code result} ended, as the container learns it: whether
     * it ran, and the result of a call that named its primitive, which goes to the program that made it.
     */
    static ObjectNode ended(Object result) {
        ObjectNode ended = JsonNodeFactory.instance.objectNode().put("ran", result != ContextCalls.DENIED);
        if (result instanceof ContextCalls.Result named) {
            ended.set("value", named.value());
        }
        return ended;
    }

    @Override
    protected int reactionPc(Reaction reaction) {
        return DeployedPrograms.reactionPc(twin, reaction);
    }

    @Override
    protected String sourceAt(int resumptionPoint) {
        return DeployedPrograms.sourceAt(twin, resumptionPoint);
    }

    @Override
    protected String sourceOfCallIn(int resumptionPoint) {
        return DeployedPrograms.sourceOfCallIn(twin, resumptionPoint);
    }
}
