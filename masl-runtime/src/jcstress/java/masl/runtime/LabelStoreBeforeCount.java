package masl.runtime;

import static org.openjdk.jcstress.annotations.Expect.ACCEPTABLE;
import static org.openjdk.jcstress.annotations.Expect.FORBIDDEN;

import java.util.concurrent.CompletableFuture;
import masl.runtime.scheduling.ChangeEpoch;
import org.openjdk.jcstress.annotations.Actor;
import org.openjdk.jcstress.annotations.Description;
import org.openjdk.jcstress.annotations.JCStressTest;
import org.openjdk.jcstress.annotations.Outcome;
import org.openjdk.jcstress.annotations.State;
import org.openjdk.jcstress.infra.results.ZI_Result;

/**
 * {@code l.x = a.m()}: the invocation completes on the serving thread while the program reads
 * {@code l.isFinished()} and then {@code x}. A program that sees the label finished reads the
 * stored result: the store happens before the count.
 */
@JCStressTest
@Description("A label seen finished shows every stored result")
@Outcome(id = "true, 42", expect = ACCEPTABLE, desc = "finished, result stored")
@Outcome(id = {"false, 0", "false, 42"}, expect = ACCEPTABLE, desc = "not finished yet")
@Outcome(id = "true, 0", expect = FORBIDDEN, desc = "finished, but the result not visible")
@State
public class LabelStoreBeforeCount {

    private final Label label = new Label(new ChangeEpoch());
    private final CompletableFuture<Integer> invocation = new CompletableFuture<>();
    /** The program's variable {@code x}: a plain field, as the generated code's locals are. */
    private int stored;

    public LabelStoreBeforeCount() {
        label.register(invocation, value -> stored = value);
    }

    @Actor
    public void servingThread() {
        invocation.complete(42);
    }

    @Actor
    public void program(ZI_Result r) {
        r.r1 = label.isFinished();
        r.r2 = stored;
    }
}
