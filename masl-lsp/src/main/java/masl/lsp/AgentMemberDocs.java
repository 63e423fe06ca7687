package masl.lsp;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.BiPredicate;
import masl.runtime.descriptor.AgentType;
import masl.runtime.descriptor.Attribute;
import masl.runtime.descriptor.Parameter;
import masl.runtime.descriptor.PermeabilityState;
import masl.runtime.descriptor.PermeabilityState.Requester;
import masl.runtime.descriptor.Primitive;

/**
 * How the editor shows a primitive or an attribute of an agent type: its signature as a MASL programmer
 * writes the call, and a Markdown description with what the descriptor says about it (agent-types.md):
 * synchronous or not, accessor, countermeasure, exceptions, and which permeability states let the agent
 * itself (user), its group or the others call, read or write it (MASL §11).
 */
final class AgentMemberDocs {

    private AgentMemberDocs() {
    }

    /** {@code void log(String message)}. */
    static String signature(Primitive primitive) {
        List<String> parameters = new ArrayList<>();
        for (Parameter parameter : primitive.parameters()) {
            parameters.add(simple(parameter.type()) + " " + parameter.name());
        }
        return (primitive.isStatic() ? "static " : "") + simple(primitive.returnType()) + " " + primitive.name()
                + "(" + String.join(", ", parameters) + ")";
    }

    /** {@code int battery}, {@code static final double MAX_SPEED = 0.5}. */
    static String signature(Attribute attribute) {
        return (attribute.isStatic() ? "static " : "") + (attribute.isFinal() ? "final " : "") + simple(attribute.type())
                + " " + attribute.name() + (attribute.value() != null ? " = " + attribute.value() : "");
    }

    /** The Markdown of a primitive as each of {@code owners} (MASL type name -> type) has it. */
    static String describe(Primitive primitive, Map<String, AgentType> owners) {
        StringBuilder text = new StringBuilder("```masl\n").append(signature(primitive)).append("\n```\n\n");
        text.append("Primitive of ").append(String.join(", ", owners.keySet())).append(": ")
                .append(primitive.synchronous() ? "**synchronous** (the caller waits for its result)"
                        : "**asynchronous** (the call returns at once; its result is a future)");
        if (primitive.accessor()) {
            text.append(", accessor (zero duration, no barrier after it)");
        }
        text.append(".\n\n");
        if (primitive.countermeasure() != null) {
            text.append("Countermeasure: `").append(primitive.countermeasure()).append("`.\n\n");
        }
        text.append(primitive.exceptions().isEmpty() ? "Throws nothing."
                : "Throws " + String.join(", ", primitive.exceptions().stream().map(name -> "`" + name + "`").toList())
                        + " (an `uncaught_exception` event in the caller).");
        text.append("\n\n");
        appendRights(text, primitive.memberId(), owners, "call", (state, requester) ->
                state.allows(primitive.memberId(), requester, PermeabilityState.INVOKE));
        return text.toString();
    }

    /** The Markdown of an attribute as each of {@code owners} has it. */
    static String describe(Attribute attribute, Map<String, AgentType> owners) {
        StringBuilder text = new StringBuilder("```masl\n").append(signature(attribute)).append("\n```\n\n");
        text.append("Attribute of ").append(String.join(", ", owners.keySet())).append(".\n\n");
        appendRights(text, attribute.memberId(), owners, "read", (state, requester) ->
                state.allows(attribute.memberId(), requester, PermeabilityState.READ));
        if (!attribute.isFinal()) {
            appendRights(text, attribute.memberId(), owners, "write", (state, requester) ->
                    state.allows(attribute.memberId(), requester, PermeabilityState.WRITE));
        }
        return text.toString();
    }

    /**
     * One line per requester naming the states that give it the right, for each group of owner types whose
     * states say the same (a type without states allows everything, MASL §11).
     */
    private static void appendRights(StringBuilder text, String memberId, Map<String, AgentType> owners, String verb,
            BiPredicate<PermeabilityState, Requester> allows) {
        Map<String, List<String>> ownersByRights = new LinkedHashMap<>();
        owners.forEach((name, type) ->
                ownersByRights.computeIfAbsent(rights(type, verb, allows), rights -> new ArrayList<>()).add(name));
        boolean several = ownersByRights.size() > 1;
        ownersByRights.forEach((rights, names) -> {
            if (several) {
                text.append("In ").append(String.join(", ", names)).append(":\n\n");
            }
            text.append(rights);
        });
    }

    private static String rights(AgentType type, String verb, BiPredicate<PermeabilityState, Requester> allows) {
        if (type.states().isEmpty()) {
            return "No permeability states: anyone may " + verb + " it.\n\n";
        }
        StringBuilder text = new StringBuilder("Who may ").append(verb).append(" it, by permeability state:\n\n");
        for (Requester requester : Requester.values()) {
            List<String> states = type.states().stream().filter(state -> allows.test(state, requester))
                    .map(PermeabilityState::name).toList();
            text.append("- *").append(requesterName(requester)).append("*: ")
                    .append(states.isEmpty() ? "in no state" : String.join(", ", states)).append('\n');
        }
        return text.append('\n').toString();
    }

    private static String requesterName(Requester requester) {
        return switch (requester) {
            case SELF -> "user (the agent itself)";
            case GROUP -> "group (an agent in the same innermost block)";
            case OTHER -> "other";
        };
    }

    /** {@code java.lang.String} as a MASL program writes it: {@code String}. */
    static String simple(String javaType) {
        return javaType.startsWith("java.lang.") && javaType.indexOf('.', "java.lang.".length()) < 0
                ? javaType.substring("java.lang.".length()) : javaType;
    }

    /** The type among {@code type} and its supertypes whose descriptor declares the primitive. */
    static AgentType declaringType(AgentType type, Primitive primitive) {
        for (AgentType candidate = type; candidate != null; candidate = candidate.supertype()) {
            if (candidate.declaredPrimitives().contains(primitive)) {
                return candidate;
            }
        }
        return type;
    }

    /** The type among {@code type} and its supertypes whose descriptor declares the attribute. */
    static AgentType declaringType(AgentType type, Attribute attribute) {
        for (AgentType candidate = type; candidate != null; candidate = candidate.supertype()) {
            if (candidate.declaredAttributes().contains(attribute)) {
                return candidate;
            }
        }
        return type;
    }
}
