package masl.runtime.invocation;

import java.util.concurrent.Callable;
import java.util.concurrent.CompletableFuture;
import java.util.function.Consumer;
import java.util.function.Supplier;
import masl.runtime.Agent;
import masl.runtime.AgentImplementation;
import masl.runtime.AttributesElsewhere;
import masl.runtime.Event;
import masl.runtime.descriptor.PermeabilityState;
import masl.runtime.descriptor.PermeabilityState.Requester;
import masl.runtime.trace.TraceEvent;

/**
 * An agent as a requester (MASL §9, §11): the invocations and launches it makes, its reads and
 * writes of attributes, filtered by the owner's permeability, the countermeasures its launches arm,
 * and the permeability state it sets. Owns the agent's {@link Countermeasures}; the agent's
 * {@link Permeability} it reads and sets. Called only by the agent's own slice (the requests' answers
 * arrive through the agent's thread-safe side, {@link Site#raise}).
 *
 * <p><b>Internal:</b> not part of the API; public only for the other packages of the runtime (Java has no
 * friend packages), and may change without notice.
 */
public final class Invoker {

    /** What a requester needs of its agent and mission beyond their public side. */
    public interface Site {

        /** The current runtime call is made from the case the program counter names. */
        void atCurrentCase();

        /** The mission clock, for trace timestamps. */
        long now();

        void record(TraceEvent event);

        /** The mission's agent that runs {@code implementation}. */
        Agent agentOf(AgentImplementation implementation);

        /** Makes the agent perceive a system event; safe from any thread. */
        void raise(Event systemEvent, String message);

        /** Queues an invocation of one of {@code target}'s primitives (see {@code Agent.submitInvocation}). */
        void submit(Agent target, PendingInvocation invocation);

        /**
         * Runs {@code call} for the agent: an exception becomes its {@code uncaught_exception}; a
         * refusal, or running past the mission's call timeout, its {@code timeout}.
         */
        <T> T runFor(String primitive, Callable<T> call, T defaultValue);

        /** Runs the body of an asynchronous primitive as the mission runs them. */
        void runAsynchronously(Runnable body);

        /** Something the agents can observe changed (a busy-wait may go on). */
        void changed();
    }

    private final Agent agent;
    private final Site site;
    private final Permeability permeability;
    private final Countermeasures countermeasures = new Countermeasures();
    // Made once: leaving blocks allocates nothing for it.
    private final Consumer<Countermeasure> fire = this::fire;

    public Invoker(Agent agent, Permeability permeability, Site site) {
        this.agent = agent;
        this.permeability = permeability;
        this.site = site;
    }

    public <T> CompletableFuture<T> invoke(AgentImplementation callee, String primitive, T defaultValue,
            Callable<T> call) {
        site.atCurrentCase();
        if (callee == null) {
            return CompletableFuture.completedFuture(nullAgent(defaultValue));
        }
        Agent target = site.agentOf(callee);
        countermeasures.disarm(target, primitive);
        if (target == agent) {
            return CompletableFuture.completedFuture(invokeSelf(primitive, defaultValue, call));
        }
        CompletableFuture<T> result = new CompletableFuture<>();
        site.record(new TraceEvent.InvocationMade(site.now(), agent.id(), target.id(), primitive, agent.source()));
        site.submit(target, new PendingInvocation(agent, primitive,
                () -> result.complete(site.runFor(primitive, call, defaultValue)),
                () -> {
                    site.raise(Event.TIMEOUT, primitive);
                    result.complete(defaultValue);
                }));
        return result;
    }

    public <T> T invokeSelf(String primitive, T defaultValue, Callable<T> call) {
        site.atCurrentCase();
        countermeasures.disarm(agent, primitive);
        if (!allowsOwn(primitive)) {
            return defaultValue;
        }
        return site.runFor(primitive, call, defaultValue);
    }

    /**
     * Whether the current state lets this agent invoke its own {@code primitive}; if not, the
     * denial's effects (§11): traced, and {@code timeout} perceived.
     */
    private boolean allowsOwn(String primitive) {
        PermeabilityState state = permeability.current();
        if (Permeability.allows(state, permeability.primitiveId(primitive), Requester.SELF, PermeabilityState.INVOKE)) {
            return true;
        }
        site.record(new TraceEvent.InvocationDenied(site.now(), agent.id(), agent.id(), primitive, state.name(),
                agent.source()));
        site.raise(Event.TIMEOUT, primitive);
        return false;
    }

    public <T> CompletableFuture<T> launch(AgentImplementation callee, String primitive, T defaultValue,
            Callable<T> call, String countermeasure, Callable<?> countermeasureCall) {
        site.atCurrentCase();
        if (callee == null) {
            return CompletableFuture.completedFuture(nullAgent(defaultValue));
        }
        Agent target = site.agentOf(callee);
        countermeasures.disarm(target, primitive);
        CompletableFuture<T> result = start(target, primitive, defaultValue, call);
        if (countermeasure != null && !agent.memberships.isEmpty()) {
            countermeasures.arm(new Countermeasure(agent.innermost().entry.definition(), target, countermeasure,
                    countermeasureCall, result, defaultValue));
        }
        return result;
    }

    /** Launches an asynchronous primitive of {@code target}, filtered by permeability, without (dis)arming anything. */
    private <T> CompletableFuture<T> start(Agent target, String primitive, T defaultValue, Callable<T> call) {
        CompletableFuture<T> result = new CompletableFuture<>();
        Runnable start = () -> site.runAsynchronously(() -> result.complete(site.runFor(primitive, call, defaultValue)));
        if (target == agent) {
            if (allowsOwn(primitive)) {
                start.run();
            } else {
                result.complete(defaultValue);
            }
        } else {
            site.record(new TraceEvent.InvocationMade(site.now(), agent.id(), target.id(), primitive, agent.source()));
            site.submit(target, new PendingInvocation(agent, primitive, start, () -> {
                site.raise(Event.TIMEOUT, primitive);
                result.complete(defaultValue);
            }));
        }
        return result;
    }

    /** The agent is about to leave its blocks from the innermost to depth {@code outermostLeft} (0: outermost). */
    public void fireCountermeasures(int outermostLeft) {
        countermeasures.fireFor(agent.memberships, outermostLeft, fire);
    }

    private void fire(Countermeasure countermeasure) {
        site.record(new TraceEvent.CountermeasureFired(site.now(), agent.id(), countermeasure.target().id(),
                countermeasure.name(), countermeasure.block().name(), agent.source()));
        countermeasure.completeLaunch();
        // Not launch(): a fired countermeasure disarms no other armed one (of an outer block).
        start(countermeasure.target(), countermeasure.name(), null, countermeasure.call());
    }

    /**
     * A member of an agent variable holding {@code null} was used: as for a Java call that throws
     * (§8), the agent perceives {@code uncaught_exception} ({@code java.lang.NullPointerException})
     * and the value is the default.
     */
    public <T> T nullAgent(T defaultValue) {
        agent.uncaughtException(new NullPointerException());
        return defaultValue;
    }

    public <T> T readAttribute(AgentImplementation owner, String attribute, T defaultValue, Supplier<T> read) {
        if (owner == null) {
            return nullAgent(defaultValue);
        }
        if (!site.agentOf(owner).permeability().permitsAttribute(agent, attribute, PermeabilityState.READ)) {
            site.raise(Event.FORBIDDEN_ACCESS, attribute);
            return defaultValue;
        }
        if (owner instanceof AttributesElsewhere elsewhere) {
            try {
                @SuppressWarnings("unchecked")
                T value = (T) elsewhere.readAttribute(attribute, read);
                return value;
            } catch (RuntimeException unreachable) {
                // Where the owner runs could not answer (its JVM gone): as a primitive that throws.
                agent.uncaughtException(unreachable);
                return defaultValue;
            }
        }
        return read.get();
    }

    public boolean writeAttribute(AgentImplementation owner, String attribute, Runnable write) {
        if (owner == null) {
            nullAgent(null);
            return false;
        }
        if (!site.agentOf(owner).permeability().permitsAttribute(agent, attribute, PermeabilityState.WRITE)) {
            site.raise(Event.FORBIDDEN_ACCESS, attribute);
            return false;
        }
        if (owner instanceof AttributesElsewhere elsewhere) {
            try {
                elsewhere.writeAttribute(attribute, write);
            } catch (RuntimeException unreachable) {
                agent.uncaughtException(unreachable);
            }
            return true;
        }
        write.run();
        return true;
    }

    public void setAcceptState(String name) {
        PermeabilityState state = permeability.find(name).orElse(null);
        if (state == null) {
            agent.uncaughtException(new IllegalArgumentException("no permeability state " + name));
            return;
        }
        permeability.set(state);
        site.changed();
    }

    public String getAcceptState(AgentImplementation other) {
        if (other == null) {
            return nullAgent("");
        }
        return site.agentOf(other).permeability().currentName();
    }
}
