package masl.runtime.examples;

import masl.runtime.AgentContext;
import masl.runtime.AgentProgram;
import masl.runtime.ESequence;
import masl.runtime.EntryDefinition;
import masl.runtime.Event;
import masl.runtime.Mode;
import masl.runtime.Reaction;
import masl.runtime.SharedDeclaration;
import masl.runtime.testing.TestAgent;

/**
 * E4 of examples.md, translated by hand. Both loops are busy-waits: {@code ready} is a shared
 * variable, and {@code started} a local the loop does not assign (the reaction that assigns it runs
 * at the loop's iteration, which then counts as progress); an event perceived by a parked worker
 * wakes it.
 * <pre>
 *  3 asynchronous entry main (true) {
 *  4   shared event go;
 *  5   shared int ready = 0;
 *  6   local boolean started = false;
 *  7   asynchronous entry lead (.getProxyID() == 0) {
 *  8     while (ready &lt; 3) {}
 *  9     emitWithMessage(go, "now");
 * 10   }
 * 11   asynchronous entry work (.getProxyID() != 0) {
 * 12     ready++;
 * 13     while (!started) {}
 * 14     .logln("worker " + .getProxyID());
 * 15   }
 * 16   react (go) {
 * 17     started = true;
 * 18     .logln("heard " + getMessageFromEvent(go));
 * 19     resume;
 * 20   }
 * 21 }
 * </pre>
 * Kept by hand as a worked example of the generated-code contract: {@link HandTranslationTest}
 * holds it equal to what the translator makes of examples.md.
 */
final class E4Events extends AgentProgram {

    static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.ASYNCHRONOUS);
    static final Event MAIN_GO = MAIN.declareSharedEvent("go");
    static final SharedDeclaration<Integer> MAIN_READY = MAIN.declareShared("ready", 0);
    static final ESequence LEAD_WORK = MAIN.newSequence();
    static final EntryDefinition LEAD = LEAD_WORK.block("lead", Mode.ASYNCHRONOUS);
    static final EntryDefinition WORK = LEAD_WORK.block("work", Mode.ASYNCHRONOUS);
    static final Reaction MAIN_REACT_GO = MAIN.react(MAIN_GO);

    private final TestAgent self;
    private boolean main$started;

    E4Events(TestAgent self) {
        this.self = self;
    }

    @Override
    protected int reactionPc(Reaction reaction) {
        if (reaction == MAIN_REACT_GO) {
            return 15;
        }
        return super.reactionPc(reaction);
    }

    @Override
    @SuppressWarnings("fallthrough") // resumption points fall through into the next one
    protected void resume(AgentContext ctx) {
        while (true) {
            switch (pc) {
                case 0: // 3: asynchronous entry main (true)
                    pc = 1;
                    switch (ctx.enter(MAIN, true)) {
                        case SKIPPED -> { pc = 13; continue; }
                        case WAITING -> { return; }
                        case ENTERED -> { }
                    }
                case 1: // 4-6: declarations (an event declaration generates no code here)
                    ctx.shared(MAIN_READY).initialise(() -> 0);
                    main$started = false;
                case 2: // 7: asynchronous entry lead (.getProxyID() == 0)
                    pc = 3;
                    switch (ctx.enter(LEAD, self.getProxyID() == 0)) {
                        case SKIPPED -> { pc = 6; continue; }
                        case WAITING -> { return; }
                        case ENTERED -> { }
                    }
                case 3: // 8: while (ready < 3) {}
                    if (!(ctx.shared(MAIN_READY).get() < 3)) {
                        pc = 4;
                        continue;
                    }
                    if (!ctx.busyWaitIteration()) return;
                    continue;
                case 4: // 9: emitWithMessage(go, "now");
                    ctx.emit(MAIN_GO, "now");
                    pc = 5;
                    if (!ctx.stepBoundary()) return;
                case 5: // 10: end of lead
                    pc = 6;
                    if (!ctx.leave(LEAD)) return;
                case 6: // 11: asynchronous entry work (.getProxyID() != 0)
                    pc = 7;
                    switch (ctx.enter(WORK, self.getProxyID() != 0)) {
                        case SKIPPED -> { pc = 11; continue; }
                        case WAITING -> { return; }
                        case ENTERED -> { }
                    }
                case 7: // 12: ready++;
                    ctx.shared(MAIN_READY).getAndUpdate(ready -> ready + 1);
                    pc = 8;
                    if (!ctx.stepBoundary()) return;
                case 8: // 13: while (!started) {}
                    if (!(!main$started)) {
                        pc = 9;
                        continue;
                    }
                    if (!ctx.busyWaitIteration()) return;
                    continue;
                case 9: // 14: .logln("worker " + .getProxyID());
                    self.logln("worker " + self.getProxyID());
                    pc = 10;
                    if (!ctx.stepBoundary()) return;
                case 10: // 15: end of work
                    pc = 11;
                    if (!ctx.leave(WORK)) return;
                case 11: // 15: end of the e-sequence {lead, work}
                    pc = 12;
                    if (!ctx.endOfSequence(LEAD_WORK)) return;
                case 12: // 21: end of main
                    pc = 13;
                    if (!ctx.leave(MAIN)) return;
                case 13: // after main
                    pc = 14;
                    if (!ctx.endOfSequence(MAIN.sequence())) return;
                case 14:
                    ctx.finish();
                    return;
                case 15: // 16: react (go) {  17: started = true;
                    main$started = true;
                    // 18: .logln("heard " + getMessageFromEvent(go));  (no step boundary in a reaction)
                    self.logln("heard " + ctx.messageOf(MAIN_GO));
                    // 19: resume;
                    if (!ctx.endReaction()) return;
                    if (!ctx.resumeInterrupted()) return;
                    continue;
                default:
                    throw new IllegalStateException("pc " + pc);
            }
        }
    }
}
