package masl.runtime.examples;

import java.util.Objects;
import masl.runtime.AgentContext;
import masl.runtime.AgentProgram;
import masl.runtime.ESequence;
import masl.runtime.EntryDefinition;
import masl.runtime.Mode;
import masl.runtime.SharedDeclaration;
import masl.runtime.testing.TestAgent;

/**
 * E6 of examples.md, translated by hand; its two loops are busy-waits (their conditions read only
 * entry members and a shared variable), so they park instead of spinning:
 * <pre>
 *  4 asynchronous entry main (true) {
 *  5   shared int served = 0;
 *  6   scalar entry setup (true) { turn.lock(); }
 *  7   while (turn.getLockPolicy() == "free") {}
 *  8   asynchronous entry keep (.getProxyID() == 0) {
 *  9     while (served < 3) {
 * 10       if (turn.getActiveCount() == 0 &amp;&amp; turn.getWaitingInCount() > 0) turn.release(1);
 * 11     }
 * 12   }
 * 13   synchronous entry turn (.getProxyID() != 0) {
 * 14     .logln("in " + turn.getActiveCount());
 * 15     served++;
 * 16   }
 * 17 }
 * </pre>
 * Kept by hand as a worked example of the generated-code contract: {@link HandTranslationTest}
 * holds it equal to what the translator makes of examples.md.
 */
final class E6OneAtATime extends AgentProgram {

    static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.ASYNCHRONOUS);
    static final SharedDeclaration<Integer> MAIN_SERVED = MAIN.declareShared("served", 0);
    static final EntryDefinition SETUP = MAIN.child("setup", Mode.SCALAR);
    static final ESequence KEEP_TURN = MAIN.newSequence();
    static final EntryDefinition KEEP = KEEP_TURN.block("keep", Mode.ASYNCHRONOUS);
    static final EntryDefinition TURN = KEEP_TURN.block("turn", Mode.SYNCHRONOUS);

    private final TestAgent self;

    E6OneAtATime(TestAgent self) {
        this.self = self;
    }

    @Override
    @SuppressWarnings("fallthrough") // resumption points fall through into the next one
    protected void resume(AgentContext ctx) {
        while (true) {
            switch (pc) {
                case 0: // 4: asynchronous entry main (true)
                    pc = 1;
                    switch (ctx.enter(MAIN, true)) {
                        case SKIPPED -> { pc = 14; continue; }
                        case WAITING -> { return; }
                        case ENTERED -> { }
                    }
                case 1: // 5: shared int served = 0;
                    ctx.shared(MAIN_SERVED).initialise(() -> 0);
                    // 6: scalar entry setup (true)
                    pc = 2;
                    switch (ctx.enter(SETUP, true)) {
                        case SKIPPED -> { pc = 3; continue; }
                        case WAITING -> { return; }
                        case ENTERED -> { }
                    }
                case 2: // 6: turn.lock();  (an entry member: zero duration, no step boundary)
                    ctx.entry(TURN).lock();
                    pc = 3;
                    if (!ctx.leave(SETUP)) return;
                case 3: // 6: end of the e-sequence {setup}
                    pc = 4;
                    if (!ctx.endOfSequence(SETUP.sequence())) return;
                case 4: // 7: while (turn.getLockPolicy() == "free") {}
                    if (!Objects.equals(ctx.entry(TURN).getLockPolicy(), "free")) {
                        pc = 5;
                        continue;
                    }
                    if (!ctx.busyWaitIteration()) return;
                    continue;
                case 5: // 8: asynchronous entry keep (.getProxyID() == 0)
                    pc = 6;
                    switch (ctx.enter(KEEP, self.getProxyID() == 0)) {
                        case SKIPPED -> { pc = 8; continue; }
                        case WAITING -> { return; }
                        case ENTERED -> { }
                    }
                case 6: // 9: while (served < 3)
                    if (!(ctx.shared(MAIN_SERVED).get() < 3)) {
                        pc = 7;
                        continue;
                    }
                    // 10: if (…) turn.release(1);
                    if (ctx.entry(TURN).getActiveCount() == 0 && ctx.entry(TURN).getWaitingInCount() > 0) {
                        ctx.entry(TURN).release(1);
                    }
                    if (!ctx.busyWaitIteration()) return;
                    continue;
                case 7: // 12: end of keep
                    pc = 8;
                    if (!ctx.leave(KEEP)) return;
                case 8: // 13: synchronous entry turn (.getProxyID() != 0)
                    pc = 9;
                    switch (ctx.enter(TURN, self.getProxyID() != 0)) {
                        case SKIPPED -> { pc = 12; continue; }
                        case WAITING -> { return; }
                        case ENTERED -> { }
                    }
                case 9: // 14: .logln("in " + turn.getActiveCount());
                    self.logln("in " + ctx.entry(TURN).getActiveCount());
                    pc = 10;
                    if (!ctx.stepBoundary()) return;
                case 10: // 15: served++;
                    ctx.shared(MAIN_SERVED).getAndUpdate(served -> served + 1);
                    pc = 11;
                    if (!ctx.stepBoundary()) return;
                case 11: // 16: end of turn
                    pc = 12;
                    if (!ctx.leave(TURN)) return;
                case 12: // 16: end of the e-sequence {keep, turn}
                    pc = 13;
                    if (!ctx.endOfSequence(KEEP_TURN)) return;
                case 13: // 17: end of main
                    pc = 14;
                    if (!ctx.leave(MAIN)) return;
                case 14: // after main
                    pc = 15;
                    if (!ctx.endOfSequence(MAIN.sequence())) return;
                case 15:
                    ctx.finish();
                    return;
                default:
                    throw new IllegalStateException("pc " + pc);
            }
        }
    }
}
