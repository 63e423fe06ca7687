package masl.missions.fipa;

import masl.agents.Default;

/** Greeter.xml's class: inside JADE a stand-in for the FIPA agent "greeter" (GreeterAgent); in-process it greets itself. */
public class Greeter extends Default {

    public String greet(String name) {
        return "hello " + name;
    }
}
