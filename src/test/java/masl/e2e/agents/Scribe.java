package masl.e2e.agents;

/** The end-to-end tests' Scribe (workers/Scribe.xml): a Worker whose descriptor redefines logln with an id of its own. */
public class Scribe extends Worker {
}
