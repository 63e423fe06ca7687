package masl.jade.deployment;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.AbstractMap;
import java.util.AbstractSet;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Set;
import java.util.stream.Stream;

/**
 * The fields of one message of a {@link Batch}'s run: the run's shared fields, in their order, then
 * its agent and number, without a copy of the shared ones, which every message of a run of 500 would
 * otherwise make. A message is read, never changed, but one that is changed gets fields of its own,
 * copied then, and the run's other messages are untouched.
 */
final class RunMember extends AbstractMap<String, JsonNode> {

    private final Map<String, JsonNode> shared;
    private final JsonNode agent;
    private final JsonNode seq;
    /** This message's own fields once it was changed; null until then. */
    private Map<String, JsonNode> own;

    /** @param shared the run's shared fields, never changed; {@code agent} and {@code seq} null where the run has none */
    RunMember(Map<String, JsonNode> shared, JsonNode agent, JsonNode seq) {
        this.shared = shared;
        this.agent = agent;
        this.seq = seq;
    }

    @Override
    public JsonNode get(Object key) {
        if (own != null) {
            return own.get(key);
        }
        if ("agent".equals(key)) {
            return agent;
        }
        if ("seq".equals(key)) {
            return seq;
        }
        return shared.get(key);
    }

    @Override
    public boolean containsKey(Object key) {
        return get(key) != null;
    }

    @Override
    public int size() {
        return own != null ? own.size() : shared.size() + (agent == null ? 0 : 1) + (seq == null ? 0 : 1);
    }

    @Override
    public JsonNode put(String key, JsonNode value) {
        return own().put(key, value);
    }

    @Override
    public JsonNode remove(Object key) {
        return own().remove(key);
    }

    @Override
    public void clear() {
        own().clear();
    }

    private Map<String, JsonNode> own() {
        if (own == null) {
            Map<String, JsonNode> copy = new LinkedHashMap<>();
            entrySet().forEach(field -> copy.put(field.getKey(), field.getValue()));
            own = copy;
        }
        return own;
    }

    @Override
    public Set<Entry<String, JsonNode>> entrySet() {
        if (own != null) {
            return own.entrySet();
        }
        return new AbstractSet<>() {
            @Override
            public Iterator<Entry<String, JsonNode>> iterator() {
                Stream<Entry<String, JsonNode>> columns = Stream.of(
                        agent == null ? null : Map.entry("agent", agent), seq == null ? null : Map.entry("seq", seq));
                return Stream.concat(shared.entrySet().stream(), columns.filter(field -> field != null)).iterator();
            }

            @Override
            public int size() {
                return RunMember.this.size();
            }
        };
    }
}
