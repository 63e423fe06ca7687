package masl.missions.fipa;

import masl.agents.Default;

/**
 * Calculator.xml's class: inside JADE a stand-in whose primitives the bridge sends to the FIPA agent
 * offering the service "calculator" (CalculatorAgent); run in-process, it answers divide and square
 * itself and has no secret to refuse, nothing to ponder on.
 */
public class Calculator extends Default {

    public int divide(int a, int b) {
        return a / b;
    }

    public int square(int x) {
        return x * x;
    }

    public int secret() {
        throw new UnsupportedOperationException("only the FIPA calculator keeps a secret");
    }

    public int ponder() {
        throw new UnsupportedOperationException("only the FIPA calculator ponders");
    }

    public int garbled() {
        throw new UnsupportedOperationException("only the FIPA calculator garbles");
    }
}
