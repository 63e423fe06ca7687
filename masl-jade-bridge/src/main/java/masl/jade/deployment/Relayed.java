package masl.jade.deployment;

import java.util.function.Supplier;

/**
 * Code the mission runs for a deployed agent's attribute access: it already reaches the attribute
 * where its agent runs (a callback in the container, a request by name), so a deployed agent's stub
 * here ({@link DeployedBody}) runs it as it is rather than sending the access on.
 */
record Relayed(Supplier<Object> code) implements Supplier<Object>, Runnable {

    @Override
    public Object get() {
        return code.get();
    }

    @Override
    public void run() {
        code.get();
    }
}
