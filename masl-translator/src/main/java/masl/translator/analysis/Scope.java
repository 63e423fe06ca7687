package masl.translator.analysis;

import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.Map;
import java.util.Optional;
import java.util.Set;

/**
 * The names a block declares, chained to the enclosing block's scope (MASL §3: names are resolved from
 * the innermost block outwards). The outermost scope holds the agents and the system events.
 */
final class Scope {

    private final Scope enclosing;
    private final Map<String, Symbol> names = new HashMap<>();

    Scope(Scope enclosing) {
        this.enclosing = enclosing;
    }

    Optional<Symbol> resolve(String name) {
        for (Scope scope = this; scope != null; scope = scope.enclosing) {
            Symbol symbol = scope.names.get(name);
            if (symbol != null) {
                return Optional.of(symbol);
            }
        }
        return Optional.empty();
    }

    /** Every name visible here, innermost first: the candidates of a hint for a name not found. */
    Set<String> visibleNames() {
        Set<String> visible = new LinkedHashSet<>();
        for (Scope scope = this; scope != null; scope = scope.enclosing) {
            visible.addAll(scope.names.keySet());
        }
        return visible;
    }

    /** Declares {@code name} here; false (and nothing changes) when it is already visible. */
    boolean declare(String name, Symbol symbol) {
        if (resolve(name).isPresent()) {
            return false;
        }
        names.put(name, symbol);
        return true;
    }
}
