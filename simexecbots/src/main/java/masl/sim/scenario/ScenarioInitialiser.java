package masl.sim.scenario;

/**
 * The initialisation class a scenario names ({@code <initialisation class="…"/>}): public, with a
 * public no-argument constructor; run once, after the world and the robots are loaded and before
 * any agent's program starts (for example to place obstacles or to drain a battery).
 */
@FunctionalInterface
public interface ScenarioInitialiser {

    /** Prepares the simulation; an exception aborts the run. */
    void initialise(Simulation simulation) throws Exception;
}
