package masl.runtime.invocation;

import java.util.concurrent.Callable;
import java.util.concurrent.CompletableFuture;
import masl.runtime.Agent;
import masl.runtime.EntryDefinition;

/**
 * A countermeasure armed by the launch of an asynchronous primitive (MASL §9): primitive
 * {@code name} of {@code target}, to be invoked if the launching agent leaves {@code block} while
 * it is armed. Firing it also completes the launch with its default value if it is still running,
 * so a label waiting for the launch counts it as completed (§10).
 *
 * <p><b>Internal:</b> not part of the API; public only for the other packages of the runtime (Java has no
 * friend packages), and may change without notice.
 */
public record Countermeasure(EntryDefinition block, Agent target, String name, Callable<?> call,
        CompletableFuture<?> launch, Object launchDefault) {

    @SuppressWarnings("unchecked")
    public void completeLaunch() {
        ((CompletableFuture<Object>) launch).complete(launchDefault);
    }
}
