package masl.translator.analysis;

/**
 * One agent of the population (MASL §4): {@code Khepera k1, k2 = newAgent(Khepera);} declares two.
 *
 * @param name the agent's name in the program
 * @param declaredType the type left of the names: what the program may use on it
 * @param instantiatedType the type in {@code newAgent(…)}, the declared type when the parentheses are empty
 * @param proxyId 0, 1, 2, … in declaration order
 */
public record AgentDecl(String name, ImportedType declaredType, ImportedType instantiatedType, int proxyId)
        implements Symbol {
}
