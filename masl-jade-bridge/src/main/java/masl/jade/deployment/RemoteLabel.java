package masl.jade.deployment;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.concurrent.CompletableFuture;
import java.util.function.Consumer;
import java.util.function.Function;
import masl.runtime.AgentImplementation;
import masl.runtime.AttributeStore;
import masl.runtime.Label;
import masl.runtime.scheduling.ChangeEpoch;

/**
 * A label (§10) as a deployed agent's program sees it: the mission holds the label and alone counts
 * ({@link MissionLabels}); each method here is a request to it. A registration names the call the
 * program made (the mission holds its future); the store of its result stays here, run when the
 * mission's label counts the call, and the program's future of the call completes only after that,
 * so a program that saw the label finished, or awaited a labelled synchronous call, reads the result
 * stored, as in-process. A store into an attribute of an agent that runs elsewhere ({@code l.b.x = b.m()})
 * makes its value here and the mission writes it where {@code b} runs.
 */
final class RemoteLabel extends Label {

    private final String key;
    private final RemoteContext context;

    RemoteLabel(String key, RemoteContext context) {
        super(new ChangeEpoch());
        this.key = key;
        this.context = context;
    }

    String key() {
        return key;
    }

    /**
     * A call already over (a {@code nop()} for an addressee whose type lacks the primitive, or one the
     * mission has said is over) counts as done at once, in-process too: it is stored here, with no message,
     * unless it stores into an agent that runs elsewhere (then the mission writes it there).
     */
    @Override
    public <T> CompletableFuture<T> register(CompletableFuture<T> invocation, Consumer<? super T> store) {
        return registered(invocation, store);
    }

    /** {@code l.a.m()}: nothing to store, so nothing for the mission to ask back. */
    @Override
    public <T> CompletableFuture<T> register(CompletableFuture<T> invocation) {
        return registered(invocation, null);
    }

    @SuppressWarnings("unchecked")
    private <T> CompletableFuture<T> registered(CompletableFuture<T> invocation, Consumer<? super T> store) {
        if (invocation.isDone()) {
            if (store instanceof AttributeStore<?> into && context.runsElsewhere(into.owner())) {
                storeElsewhere(into, invocation.join());
            } else if (store != null) {
                store.accept(invocation.join());
            }
            return invocation;
        }
        Long call = context.callNumber(invocation);
        if (call == null) {
            throw new UnsupportedOperationException("a deployed agent registers with a label only the calls it made");
        }
        ObjectNode request = request().put("call", call);
        if (store != null) {
            Object defaultValue = context.defaultValue(call);
            Function<JsonNode, Object> result = ended -> context.resultOf(call, ended, defaultValue, false);
            if (store instanceof AttributeStore<?> into && context.runsElsewhere(into.owner())) {
                // The result is here, the attribute where its owner runs: the value goes to the mission,
                // which writes it there.
                request.put("store", context.callbacks().function(ended -> context.stored(into, result.apply(ended))))
                        .put("owner", AgentImplementation.proxyIdOf(into.owner())).put("attribute", into.attribute());
            } else {
                request.put("store", context.callbacks().store(result, value -> store.accept((T) value)));
            }
        }
        context.call("label-register", request);
        return invocation;
    }

    /** A store into an agent that runs elsewhere of a call already over: the mission writes it there. */
    private void storeElsewhere(AttributeStore<?> into, Object value) {
        ObjectNode request = request().put("owner", AgentImplementation.proxyIdOf(into.owner()))
                .put("attribute", into.attribute());
        try {
            request.set("value", context.stored(into, value));
        } catch (IllegalArgumentException cannotTravel) {
            // A value of a type that does not travel: as a primitive that throws, in-process.
            context.uncaughtException(cannotTravel);
            return;
        }
        context.call("label-store", request);
    }

    @Override
    public boolean isFinished() {
        return context.call("label-isFinished", request()).booleanValue();
    }

    @Override
    public int getRemainingInvocations() {
        return context.call("label-remaining", request()).intValue();
    }

    @Override
    public void free() {
        context.call("label-free", request());
    }

    private ObjectNode request() {
        return JsonNodeFactory.instance.objectNode().put("label", key);
    }

    @Override
    public String toString() {
        return "label " + key;
    }
}
