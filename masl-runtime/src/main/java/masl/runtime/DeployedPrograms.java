package masl.runtime;

import java.util.List;
import masl.runtime.descriptor.AgentType;

/**
 * What the JADE bridge needs of generated programs to run an agent's program in another JVM than its
 * mission (a deployed agent): the programs made outside a mission, and the program's own methods,
 * called from the bridge's package. The container runs the real program against a context of its
 * own; the mission runs a stand-in whose steps are the container's, and which answers for the program
 * (its reactions' code, its MASL source) through the same generated class.
 */
public final class DeployedPrograms {

    /**
     * A program's top-level block (null if it has none), its agents' programs in proxy id order, and
     * their types (an element is null for an agent declared without one).
     */
    public record Made(EntryDefinition main, List<AgentProgram> programs, List<AgentType> types) {
    }

    /**
     * What the container of a deployed agent needs to pass its program's boundaries itself, as the
     * runtime would pass them without doing anything but count: the place of the program's latest
     * step, a loop's head or the case after an instruction ({@code latestStep}; an iteration of the
     * loop at head {@code h} ran no instruction if {@code latestStep <= h}), and whether the agent's
     * innermost block is synchronous and it active there ({@code barrierDue}): then a step boundary,
     * and an iteration that ran no instruction, meet the barrier and must come to the mission.
     */
    public record AtRest(int latestStep, boolean barrierDue) {
    }

    private DeployedPrograms() {
    }

    /**
     * The programs of every agent {@code program} declares, each made for the implementation
     * {@code implementations} gives (which the caller binds to its services), and its top-level block.
     */
    public static Made outsideAMission(MissionProgram program, MissionProgram.ImplementationFactory implementations) {
        Mission.Builder builder = Mission.builder();
        program.configure(builder, implementations);
        return builder.madeOutsideAMission();
    }

    /** The event {@code name} that {@code block} declares, or the system event of that name if block is null; else null. */
    public static Event event(EntryDefinition block, String name) {
        if (block != null) {
            return block.event(name).orElse(null);
        }
        for (Event system : List.of(Event.TIMEOUT, Event.UNCAUGHT_EXCEPTION, Event.FORBIDDEN_ACCESS)) {
            if (system.name().equals(name)) {
                return system;
            }
        }
        return null;
    }

    /** Runs {@code program} from {@code pc} until it must wait or has finished, as a mission would. */
    public static void resume(AgentProgram program, int pc, AgentContext ctx) {
        program.jump(pc);
        program.resume(ctx);
    }

    /**
     * What {@code agent}'s container needs to pass its boundaries itself until something arrives that
     * a boundary must act on, or null if its next boundary must come to the mission. Called by the
     * agent's slice; {@code agent} is the context the mission runs the stand-in's steps against.
     */
    public static AtRest atRest(AgentContext agent) {
        return ((SteppingAgent) agent).boundariesAtRest();
    }

    /**
     * Parks {@code agent}, whose step runs in its container, until {@link #arrivedElsewhere} with the
     * ticket returned (the step's next message has come), holding no thread meanwhile; the caller, the
     * stand-in's {@code resume}, then returns, and the agent's next slice resumes it. Not blocked
     * while so parked: its invocations wait for its boundaries, as while its step runs. 0, and
     * nothing done, if the slice has parked already or the program finished (a call performed for
     * the step did): the caller must wait on its thread. Called by the agent's slice.
     */
    public static long awaitElsewhere(AgentContext agent) {
        return ((SteppingAgent) agent).awaitElsewhere();
    }

    /**
     * The step's next message has come for {@code agent}, parked by {@link #awaitElsewhere} with
     * {@code ticket}: it runs again. Ignored if that park has ended. Any thread.
     */
    public static void arrivedElsewhere(AgentContext agent, long ticket) {
        ((SteppingAgent) agent).unpark(ticket);
    }

    /**
     * {@code count} boundaries (loop iterations, step boundaries, ends of e-sequences) {@code agent}'s
     * container passed itself since its last request, its program's latest step then at
     * {@code latestStep}: counted as the runtime counts its own. Called by the agent's slice.
     */
    public static void passedElsewhere(AgentContext agent, long count, int latestStep) {
        ((SteppingAgent) agent).boundariesPassedElsewhere(count, latestStep);
    }

    /**
     * Has {@code hook} run each time an occurrence or an invocation arrives for {@code agent}: its
     * container then brings its next boundary to the mission. Any thread runs it, the flag that the
     * boundary reads set before.
     */
    public static void onBoundaryWork(Agent agent, Runnable hook) {
        agent.onBoundaryWork(hook);
    }

    /**
     * {@code requester} invoked {@code callee}'s {@code primitive} from the case {@code pc} of its
     * program and {@code callee} served it, both in their container, which ran the call: recorded in
     * the trace as the runtime records an invocation it serves.
     */
    public static void invokedElsewhere(Agent requester, Agent callee, String primitive, int pc) {
        requester.invokedElsewhere(callee, primitive, pc);
    }

    /** Sets {@code program}'s resumption point: the mission's runtime moved it (a reaction, a resume). */
    public static void jump(AgentProgram program, int pc) {
        program.jump(pc);
    }

    /** Where {@code program}'s code for {@code reaction} starts. */
    public static int reactionPc(AgentProgram program, Reaction reaction) {
        return program.reactionPc(reaction);
    }

    /** The MASL source of resumption point {@code pc} of {@code program}, or null. */
    public static String sourceAt(AgentProgram program, int pc) {
        return program.sourceAt(pc);
    }

    /** The MASL source of the statement whose call ends the case {@code pc} of {@code program}, or null. */
    public static String sourceOfCallIn(AgentProgram program, int pc) {
        return program.sourceOfCallIn(pc);
    }
}
