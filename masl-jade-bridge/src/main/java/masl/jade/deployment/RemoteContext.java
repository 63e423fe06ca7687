package masl.jade.deployment;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.IntNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.ArrayList;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.Callable;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionStage;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Function;
import java.util.function.Supplier;
import masl.runtime.AgentContext;
import masl.runtime.AgentImplementation;
import masl.runtime.AgentProgram;
import masl.runtime.Arrival;
import masl.runtime.AttributeStore;
import masl.runtime.DeployedPrograms;
import masl.runtime.ESequence;
import masl.runtime.EntryDefinition;
import masl.runtime.Event;
import masl.runtime.Label;
import masl.runtime.RemotePrimitiveException;
import masl.runtime.SharedDeclaration;
import masl.runtime.SharedVariable;
import masl.runtime.descriptor.PermeabilityState;
import masl.runtime.entry.Entry;

/**
 * The {@link AgentContext} of a deployed agent's program in its container. The program and the
 * Java code it hands over (its primitives' calls, attribute accesses, update functions) run here;
 * its own primitives and attributes with no message when its own permeability state allows them
 * ({@link OwnPermeability}). What the mission owns (blocks, barriers, waves, shared variables,
 * events, others' permeability, the agent's place in the journal) is a request to the mission,
 * answered by the mission's runtime on the thread running the agent's step there, so that the
 * runtime's rules hold as in-process. Each
 * request carries the program's resumption point and each answer brings back the one the runtime
 * left (it redirects the program to reactions).
 */
final class RemoteContext implements AgentContext, Values.Labels {

    private static final JsonNodeFactory JSON = JsonNodeFactory.instance;

    /** A future the program holds for a call the mission queued or launched. */
    private record Mirror(CompletableFuture<Object> future, long call, Object defaultValue) {
    }

    private final int id;
    private final AgentProgram program;
    private final OwnPermeability own;
    private final DeployedTeam team;
    private final BlockingQueue<ObjectNode> answers = new LinkedBlockingQueue<>();
    private final Map<Long, Mirror> mirrors = new ConcurrentHashMap<>();
    private final Map<CompletionStage<?>, Long> callOf = new IdentityHashMap<>();
    /** This program's calls that return from its step to be resumed: at once, or once answered. */
    private final ReturningCalls returning = new ReturningCalls();
    /** This program's views of the mission's labels, by key; the labels it made are numbered here. */
    private final Map<String, RemoteLabel> labels = new ConcurrentHashMap<>();
    private final AtomicLong labelNumbers = new AtomicLong();
    private final QuietBoundaries quiet = new QuietBoundaries();
    /** When this container may serve this agent an invocation of another agent of it, there. */
    private final CalleeTurn turn = new CalleeTurn();
    /** This agent's invocations of the other agents of this container. */
    private final InvocationsHere here;

    RemoteContext(int id, AgentProgram program, OwnPermeability own, DeployedTeam team) {
        this.id = id;
        this.program = program;
        this.own = own;
        this.team = team;
        this.here = new InvocationsHere(this, team);
    }

    int id() {
        return id;
    }

    AgentProgram program() {
        return program;
    }

    /** This agent's boundaries passed here: what the mission's messages say of them. */
    QuietBoundaries quiet() {
        return quiet;
    }

    CalleeTurn turn() {
        return turn;
    }

    OwnPermeability own() {
        return own;
    }

    /** An answer of the mission to this agent's request. */
    void answered(ObjectNode answer) {
        answers.add(answer);
    }

    /** Completes the futures of the calls the mission says are over ({@code done} of its message). */
    void completeDone(JsonNode done) {
        if (done == null) {
            return;
        }
        for (JsonNode call : done) {
            Mirror mirror = mirrors.remove(call.get("call").longValue());
            if (mirror != null) {
                synchronized (callOf) {
                    callOf.remove(mirror.future());
                }
                mirror.future().complete(resultOf(mirror.call(), call, mirror.defaultValue(), true));
            }
        }
    }

    /**
     * The value call {@code call} gives the program, the mission saying how it {@code ended}: the result
     * that came with it (a call that named its primitive), the one kept here (the others'), forgotten if
     * {@code forget}, or {@code defaultValue} if it did not run.
     */
    Object resultOf(long call, JsonNode ended, Object defaultValue, boolean forget) {
        boolean ran = ended.get("ran").booleanValue();
        JsonNode value = ended.get("value");
        if (value != null) {
            return ran ? Values.fromJson(value, team.agents()) : defaultValue;
        }
        if (forget) {
            return team.callbacks().result(call, ran, defaultValue);
        }
        return ran ? team.callbacks().kept(call) : defaultValue;
    }

    /** Request {@code op} to the mission, answered with its value (a label's view asks the mission's label so). */
    JsonNode call(String op, ObjectNode request) {
        request(op, request);
        ObjectNode answer = turn.during(op, () -> {
            team.send(request, quiet.busyChangeOfNext());
            return team.await(answers);
        });
        // The mission performs the request holding a lock (a shared variable's) and has this step run
        // the variable's function meanwhile, whose own requests to the mission nest in this one.
        while ("run".equals(answer.path("kind").asText())) {
            team.runInStep(this, answer);
            answer = team.await(answers);
        }
        completeDone(answer.get("done"));
        quiet.told(answer);
        DeployedPrograms.jump(program, answer.get("pc").intValue());
        returning.answered(answer);
        return answer.get("value");
    }

    /** {@code request} made the program's request {@code op}, with the boundaries it passed here. */
    private ObjectNode request(String op, ObjectNode request) {
        return Requests.written(request.put("agent", id), op, program.pc(), quiet);
    }

    private JsonNode call(String op) {
        return call(op, JSON.objectNode());
    }

    private boolean bool(String op, ObjectNode request) {
        return ReturningCalls.returns(op) ? returning.returned(returnRequest(op, request))
                : call(op, request).booleanValue();
    }

    /**
     * The request of the call {@code op} the program returns from, with {@code arguments}: with none
     * (a step boundary, a loop's iteration), fields the container's alike requests share.
     */
    private Batch.Held returnRequest(String op, ObjectNode arguments) {
        if (!arguments.isEmpty()) {
            return Batch.Held.of(request(op, arguments));
        }
        return new Batch.Held(team.requests().of(op, program.pc(), quiet), IntNode.valueOf(id), null);
    }

    ReturningCalls returning() {
        return returning;
    }

    private ObjectNode block(EntryDefinition block) {
        return JSON.objectNode().put("block", Blocks.name(block));
    }

    private static int proxyId(AgentImplementation agent) {
        return agent == null ? -1 : AgentImplementation.proxyIdOf(agent);
    }

    Object sharedCall(String op, SharedDeclaration<?> declaration, Function<Object, Object> function, Object value) {
        ObjectNode request = JSON.objectNode().put("shared", Blocks.name(declaration));
        Class<?> type = declaration.arrayType();
        if (function != null) {
            request.put("call", team.callbacks().function(
                    json -> Values.toJson(function.apply(Values.fromJson(json, team.agents(), this, type)), this)));
        }
        if ("set".equals(op)) {
            request.set("value", Values.toJson(value, this));
        }
        JsonNode answer = call("shared-" + op, request);
        return answer == null || answer.isNull() ? null : Values.fromJson(answer, team.agents(), this, type);
    }

    /** Has the mission store {@code element} at {@code path} of the array the shared variable holds there. */
    void storeElement(SharedDeclaration<?> declaration, Object element, int... path) {
        ObjectNode request = JSON.objectNode().put("shared", Blocks.name(declaration));
        ArrayNode indices = request.putArray("path");
        for (int index : path) {
            indices.add(index);
        }
        request.set("value", Values.toJson(element, this));
        call("shared-stored", request);
    }

    /** The number of the call whose future the program holds, or null if the program did not make it here. */
    Long callNumber(CompletionStage<?> future) {
        synchronized (callOf) {
            return callOf.get(future);
        }
    }

    /** The value the program's future of call {@code call} gives if the call does not run. */
    Object defaultValue(long call) {
        return mirrors.get(call).defaultValue();
    }

    Callbacks callbacks() {
        return team.callbacks();
    }

    /** Whether {@code agent} runs elsewhere than this container: its attributes are written by name. */
    boolean runsElsewhere(AgentImplementation agent) {
        return agent != null && team.members().accessedByName(proxyId(agent));
    }

    /** The value (tagged) {@code store} writes when it stores {@code value}, found on its owner's stub here. */
    @SuppressWarnings("unchecked")
    JsonNode stored(AttributeStore<?> store, Object value) {
        AgentImplementation owner = store.owner();
        return team.members().written(proxyId(owner), owner, store.attribute(),
                ((AttributeStore<Object>) store).writing(value));
    }

    Object entryCall(EntryDefinition block, String op, int n) {
        JsonNode answer = call("entry-" + op, block(block).put("n", n));
        return answer == null || answer.isNull() ? null : answer.isTextual() ? answer.textValue() : answer.intValue();
    }

    List<AgentImplementation> entryAgents(EntryDefinition block, String op) {
        List<AgentImplementation> agents = new ArrayList<>();
        for (JsonNode proxyId : call("entry-" + op, block(block))) {
            agents.add(team.agents().get(proxyId.intValue()));
        }
        return agents;
    }

    @Override
    public int proxyId() {
        return id;
    }

    /** Passed here, with no message, while nothing waits for it in the mission ({@link QuietBoundaries}). */
    @Override
    public boolean stepBoundary() {
        team.requireMission();
        if (quiet.passStep(program.pc(), team.written())) {
            return passed();
        }
        return bool("stepBoundary", JSON.objectNode());
    }

    /** Passed here, with no message, while nothing waits for it in the mission ({@link QuietBoundaries}). */
    @Override
    public boolean loopIteration() {
        team.requireMission();
        if (quiet.passLoopHead(program.pc())) {
            return passed();
        }
        return bool("loopIteration", JSON.objectNode());
    }

    @Override
    public boolean busyWaitIteration() {
        return bool("busyWaitIteration", JSON.objectNode());
    }

    /** A boundary passed here: true, the step going on; one that runs long lets its container's messages go. */
    private boolean passed() {
        if (quiet.lettingGo()) {
            team.letGo();
        }
        return true;
    }

    @Override
    public Arrival enter(EntryDefinition block, boolean test) {
        return Arrival.valueOf(call("enter", block(block).put("test", test)).textValue());
    }

    @Override
    public boolean leave(EntryDefinition block) {
        return bool("leave", block(block));
    }

    @Override
    public boolean endOfChild(EntryDefinition block) {
        return bool("endOfChild", block(block));
    }

    /** Passed here, with no message, while nothing waits for it in the mission ({@link QuietBoundaries}). */
    @Override
    public boolean endOfSequence(ESequence sequence) {
        team.requireMission();
        if (quiet.passEndOfSequence()) {
            return passed();
        }
        return bool("endOfSequence", JSON.objectNode().put("sequence", Blocks.name(sequence)));
    }

    @Override
    public void breakOut(EntryDefinition outermost) {
        call("breakOut", block(outermost));
    }

    @Override
    public void reelect(EntryDefinition block) {
        call("reelect", block(block));
    }

    @Override
    public void restart(EntryDefinition block) {
        call("restart", block(block));
    }

    @Override
    public <T> SharedVariable<T> shared(SharedDeclaration<T> declaration) {
        return new RemoteShared<>(declaration, this);
    }

    @Override
    public Entry entry(EntryDefinition block) {
        return new RemoteEntry(block, this);
    }

    @Override
    public boolean sleep(long ms) {
        return bool("sleep", JSON.objectNode().put("ms", ms));
    }

    @Override
    public boolean await(CompletionStage<?> result) {
        Long call;
        synchronized (callOf) {
            call = callOf.get(result);
        }
        if (call == null) {
            if (result.toCompletableFuture().isDone()) {
                return true;
            }
            throw new UnsupportedOperationException("a deployed agent awaits only the calls it made");
        }
        return bool("await", JSON.objectNode().put("call", call));
    }

    @Override
    public void emit(Event event) {
        emit(event, "");
    }

    @Override
    public void emit(Event event, String message) {
        call("emit", JSON.objectNode().put("event", Blocks.name(event)).put("message", message));
    }

    @Override
    public void uncaughtException(Throwable thrown) {
        call("uncaughtException", JSON.objectNode().put("class", RemotePrimitiveException.classNameOf(thrown))
                .put("message", String.valueOf(thrown.getMessage())));
    }

    @Override
    public String messageOf(Event event) {
        return call("messageOf", JSON.objectNode().put("event", Blocks.name(event))).textValue();
    }

    @Override
    public boolean endReaction() {
        return bool("endReaction", JSON.objectNode());
    }

    @Override
    public boolean resumeInterrupted() {
        return bool("resumeInterrupted", JSON.objectNode());
    }

    @Override
    public void clearEvents() {
        call("clearEvents");
    }

    @Override
    public void finish() {
        call("finish");
    }

    @Override
    public <T> CompletableFuture<T> invoke(AgentImplementation callee, String primitive, T defaultValue,
            Callable<T> call) {
        CompletableFuture<T> served = here.served(callee, primitive, defaultValue, call, mirrors.isEmpty());
        if (served != null) {
            return served;
        }
        return queued("invoke", callee, primitive, defaultValue, call, JSON.objectNode());
    }

    @SuppressWarnings("unchecked")
    private <T> CompletableFuture<T> queued(String op, AgentImplementation callee, String primitive, T defaultValue,
            Callable<T> call, ObjectNode request) {
        long number;
        if (byName(callee, primitive)) {
            try {
                request.set("args", args(Recording.of(call)));
            } catch (IllegalArgumentException cannotTravel) {
                // An argument of a type that does not travel: as a primitive that throws, in-process.
                uncaughtException(cannotTravel);
                return CompletableFuture.completedFuture(defaultValue);
            }
            number = team.callbacks().number();
        } else {
            number = team.callbacks().call(here.onItsObject(callee, call));
        }
        CompletableFuture<Object> future = new CompletableFuture<>();
        mirrors.put(number, new Mirror(future, number, defaultValue));
        synchronized (callOf) {
            callOf.put(future, number);
        }
        call(op, request.put("callee", proxyId(callee)).put("primitive", primitive).put("call", number));
        return (CompletableFuture<T>) future;
    }

    /**
     * Whether an invocation of {@code callee}'s {@code primitive} names it: {@code callee} runs
     * elsewhere than this container, so that the call runs on its real object there.
     */
    private boolean byName(AgentImplementation callee, String primitive) {
        return callee != null && team.members().invokedByName(proxyId(callee), primitive);
    }

    /** The arguments of a call the program made on a stub here, as they travel. */
    private static ArrayNode args(Recording.Call call) {
        if (call == null) {
            throw new IllegalStateException("the call handed over calls no primitive of its callee");
        }
        ArrayNode args = JSON.arrayNode();
        call.args().forEach(arg -> args.add(Values.toJson(arg)));
        return args;
    }

    /**
     * Runs here, with no message, when the agent's own state allows it; a primitive that throws is
     * then handed to the mission as a call that throws the same, so that the agent perceives
     * {@code uncaught_exception} as in-process.
     */
    @Override
    public <T> T invokeSelf(String primitive, T defaultValue, Callable<T> call) {
        if (!own.letsInvoke(primitive)) {
            return invokeSelfInTheMission(primitive, defaultValue, call);
        }
        try {
            return call.call();
        } catch (Exception thrown) {
            return invokeSelfInTheMission(primitive, defaultValue, () -> {
                throw thrown;
            });
        }
    }

    @SuppressWarnings("unchecked")
    private <T> T invokeSelfInTheMission(String primitive, T defaultValue, Callable<T> call) {
        long number = team.callbacks().call(call);
        boolean ran = bool("invokeSelf", JSON.objectNode().put("primitive", primitive).put("call", number));
        return (T) team.callbacks().result(number, ran, defaultValue);
    }

    /** The agent's own attribute is read here when its state allows it, as {@link #invokeSelf}. */
    @Override
    @SuppressWarnings("unchecked")
    public <T> T readAttribute(AgentImplementation owner, String attribute, T defaultValue, Supplier<T> read) {
        if (proxyId(owner) == id && own.letsAccess(attribute, PermeabilityState.READ)) {
            return read.get();
        }
        if (owner != null && team.members().accessedByName(proxyId(owner))) {
            JsonNode value = call("readAttribute", JSON.objectNode().put("owner", proxyId(owner))
                    .put("attribute", attribute));
            return value == null || value.isNull() ? defaultValue : (T) Values.fromJson(value, team.agents());
        }
        long number = team.callbacks().call(read::get);
        boolean ran = bool("readAttribute",
                JSON.objectNode().put("owner", proxyId(owner)).put("attribute", attribute).put("call", number));
        return (T) team.callbacks().result(number, ran, defaultValue);
    }

    @Override
    public boolean writeAttribute(AgentImplementation owner, String attribute, Runnable write) {
        if (proxyId(owner) == id && own.letsAccess(attribute, PermeabilityState.WRITE)) {
            write.run();
            return true;
        }
        if (owner != null && team.members().accessedByName(proxyId(owner))) {
            ObjectNode request = JSON.objectNode().put("owner", proxyId(owner)).put("attribute", attribute);
            try {
                request.set("value", team.members().written(proxyId(owner), owner, attribute, write));
            } catch (IllegalArgumentException cannotTravel) {
                uncaughtException(cannotTravel);
                return false;
            }
            return bool("writeAttribute", request);
        }
        long number = team.callbacks().call(() -> {
            write.run();
            return null;
        });
        boolean ran = bool("writeAttribute",
                JSON.objectNode().put("owner", proxyId(owner)).put("attribute", attribute).put("call", number));
        team.callbacks().result(number, ran, null);
        return ran;
    }

    @Override
    public void setAcceptState(String name) {
        own.nowIn(call("setAcceptState", JSON.objectNode().put("state", name)).textValue());
    }

    @Override
    public String getAcceptState() {
        return call("getAcceptState", JSON.objectNode().put("of", id)).textValue();
    }

    @Override
    public String getAcceptState(AgentImplementation agent) {
        return call("getAcceptState", JSON.objectNode().put("of", proxyId(agent))).textValue();
    }

    @Override
    public boolean waitFor(String state) {
        return bool("waitFor", JSON.objectNode().put("state", state).put("ms", -1));
    }

    @Override
    public boolean waitFor(String state, long ms) {
        return bool("waitFor", JSON.objectNode().put("state", state).put("ms", ms));
    }

    @Override
    public <T> CompletableFuture<T> launch(AgentImplementation callee, String primitive, T defaultValue,
            Callable<T> call) {
        return queued("launch", callee, primitive, defaultValue, call, JSON.objectNode());
    }

    @Override
    public <T> CompletableFuture<T> launch(AgentImplementation callee, String primitive, T defaultValue,
            Callable<T> call, String countermeasure, Callable<?> countermeasureCall) {
        if (proxyId(callee) == id) {
            own.armed(primitive);
        }
        here.armed(callee, primitive);
        ObjectNode request = JSON.objectNode().put("countermeasure", countermeasure);
        if (byName(callee, countermeasure)) {
            request.set("countermeasureArgs", args(Recording.of(countermeasureCall)));
        } else {
            request.put("countermeasureCall", team.callbacks().call(here.onItsObject(callee, countermeasureCall)));
        }
        return queued("launch", callee, primitive, defaultValue, call, request);
    }

    /**
     * A view of a label the mission makes when this view first asks it something: named by this agent
     * and a number of its own, it costs no message (an {@code SLabel}'s first member makes it inside the
     * shared variable's initialisation, while the mission waits for that).
     */
    @Override
    public Label newLabel() {
        return label(id + "." + labelNumbers.incrementAndGet());
    }

    @Override
    public Label label(String key) {
        return labels.computeIfAbsent(key, made -> new RemoteLabel(made, this));
    }

    @Override
    public String key(Label label) {
        if (label instanceof RemoteLabel view) {
            return view.key();
        }
        throw new IllegalArgumentException("a label not made through the mission cannot travel to it");
    }
}
