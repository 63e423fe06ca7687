package masl.jade.placement;

import masl.runtime.MissionProgram;

/**
 * How a container makes the program of the agents deployed to it: translates and compiles the
 * source the coordinator sent with its own masl, along its own agent path (where the agents'
 * implementation classes come from). No class travels between JVMs.
 */
@FunctionalInterface
public interface ProgramTranslator {

    /** The program translated here, how its agents' implementations are made here, and the key of its translation. */
    record Translated(MissionProgram program, MissionProgram.ImplementationFactory implementations, String key) {
    }

    /**
     * @throws Refusal with the translation's diagnostics ({@code file:line:column: error: …}) when the
     *     program cannot be translated here
     */
    Translated translate(DeployedSource source) throws Refusal;

    /** The program cannot be translated here: the message says why, positioned. */
    final class Refusal extends Exception {
        private static final long serialVersionUID = 1L;

        public Refusal(String message) {
            super(message);
        }
    }
}
