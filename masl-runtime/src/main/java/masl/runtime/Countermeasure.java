package masl.runtime;

import java.util.concurrent.Callable;
import java.util.concurrent.CompletableFuture;

/**
 * A countermeasure armed by the launch of an asynchronous primitive (MASL §9): primitive
 * {@code name} of {@code target}, to be invoked if the launching agent leaves {@code block} while
 * it is armed. Firing it also completes the launch with its default value if it is still running,
 * so a label waiting for the launch counts it as completed (§10).
 */
record Countermeasure(EntryDefinition block, Agent target, String name, Callable<?> call,
        CompletableFuture<?> launch, Object launchDefault) {

    @SuppressWarnings("unchecked")
    void completeLaunch() {
        ((CompletableFuture<Object>) launch).complete(launchDefault);
    }
}
