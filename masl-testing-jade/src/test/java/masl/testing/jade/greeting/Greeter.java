package masl.testing.jade.greeting;

import masl.agents.Default;

/** Greeter.xml's class: inside JADE a stand-in for the JADE agent "greeter"; in-process it greets by itself. */
public class Greeter extends Default {

    public String greet(String name) {
        return "hello " + name;
    }
}
