package masl.jade.deployment;

import java.util.Set;
import java.util.concurrent.Callable;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentHashMap;
import masl.runtime.AgentImplementation;

/**
 * A deployed agent's invocations of the other agents of its container: served there, on the
 * caller's thread, with no message of their own, when the runtime would serve them the same way at
 * that moment (MASL §5, §9, §11); the mission then traces them with the container's next message.
 * The others go to the mission as every invocation does, and run here, on the callee's object, when
 * the mission serves them.
 */
final class InvocationsHere {

    private final RemoteContext caller;
    private final DeployedTeam team;
    /** The callee and primitive ({@code "3 move"}) of each countermeasure a launch of the caller armed. */
    private final Set<String> armedOn = ConcurrentHashMap.newKeySet();

    InvocationsHere(RemoteContext caller, DeployedTeam team) {
        this.caller = caller;
        this.team = team;
    }

    /** A launch of the caller armed a countermeasure on {@code callee}'s {@code primitive}: the mission disarms it. */
    void armed(AgentImplementation callee, String primitive) {
        armedOn.add(proxyId(callee) + " " + primitive);
    }

    /**
     * The caller's invocation of {@code callee}'s {@code primitive}, served here now, or null if the
     * mission must serve it: served here if {@code callee} is another agent of this container at rest
     * ({@link CalleeTurn}), its state lets any other agent invoke {@code primitive}, the caller has no
     * call in the mission ({@code noCallInTheMission}; the callee serves a caller's calls in order)
     * and no countermeasure armed on that primitive (which the call disarms in the mission). A
     * primitive that throws makes the caller perceive {@code uncaught_exception}, as in-process.
     */
    <T> CompletableFuture<T> served(AgentImplementation callee, String primitive, T defaultValue, Callable<T> call,
            boolean noCallInTheMission) {
        RemoteContext here = callee == null ? null : team.context(proxyId(callee));
        if (here == null || here == caller || !noCallInTheMission || armedOn.contains(here.id() + " " + primitive)
                || !here.turn().take()) {
            return null;
        }
        // Read with the turn taken: only the callee's program changes its state, and it rests.
        if (!here.own().letsOthersInvoke(primitive)) {
            here.turn().release();
            return null;
        }
        Exception threw = null;
        T result = defaultValue;
        try {
            result = call.call();
        } catch (Exception thrown) {
            threw = thrown;
        } finally {
            here.turn().release();
        }
        team.invokedHere(caller.id(), here.id(), primitive, caller.program().pc());
        if (threw != null) {
            caller.uncaughtException(threw);
        }
        return CompletableFuture.completedFuture(result);
    }

    /**
     * {@code call} of a primitive of {@code callee}, kept here for the mission to run when it serves
     * it: for another agent of this container, run as the primitives the mission asks for are
     * ({@link CalleeTurn#missionRunBegins}), never alongside an invocation served here.
     */
    <T> Callable<T> onItsObject(AgentImplementation callee, Callable<T> call) {
        RemoteContext here = callee == null ? null : team.context(proxyId(callee));
        if (here == null || here == caller) {
            return call;
        }
        return () -> {
            here.turn().missionRunBegins();
            try {
                return call.call();
            } finally {
                here.turn().missionRunEnds();
            }
        };
    }

    private static int proxyId(AgentImplementation agent) {
        return agent == null ? -1 : AgentImplementation.proxyIdOf(agent);
    }
}
