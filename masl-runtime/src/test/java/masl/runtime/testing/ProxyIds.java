package masl.runtime.testing;

import java.util.Arrays;
import java.util.List;

/**
 * The proxy ids of an entry list (MASL §6.7), sorted: a test program prints a list as
 * {@code masl.runtime.testing.ProxyIds.of(gate.getList())}, the same whatever order the members came in.
 */
public final class ProxyIds {

    private ProxyIds() {
    }

    public static List<Integer> of(Object[] agents) {
        return Arrays.stream(agents).map(agent -> ((TestAgent) agent).getProxyID()).sorted().toList();
    }
}
