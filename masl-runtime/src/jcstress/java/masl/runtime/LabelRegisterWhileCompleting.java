package masl.runtime;

import static org.openjdk.jcstress.annotations.Expect.ACCEPTABLE;
import static org.openjdk.jcstress.annotations.Expect.FORBIDDEN;

import java.util.concurrent.CompletableFuture;
import masl.runtime.scheduling.ChangeEpoch;
import org.openjdk.jcstress.annotations.Actor;
import org.openjdk.jcstress.annotations.Arbiter;
import org.openjdk.jcstress.annotations.Description;
import org.openjdk.jcstress.annotations.JCStressTest;
import org.openjdk.jcstress.annotations.Outcome;
import org.openjdk.jcstress.annotations.State;
import org.openjdk.jcstress.infra.results.IZ_Result;

/**
 * The program registers a second invocation with its label while the first completes on a serving
 * thread: the label counts both, so one stays pending and the label is not finished.
 */
@JCStressTest
@Description("Registering while another invocation completes loses no count")
@Outcome(id = "1, false", expect = ACCEPTABLE, desc = "the second invocation is pending")
@Outcome(expect = FORBIDDEN, desc = "a count lost or doubled")
@State
public class LabelRegisterWhileCompleting {

    private final Label label = new Label(new ChangeEpoch());
    private final CompletableFuture<Integer> first = new CompletableFuture<>();

    public LabelRegisterWhileCompleting() {
        label.register(first);
    }

    @Actor
    public void servingThread() {
        first.complete(1);
    }

    @Actor
    public void program() {
        label.register(new CompletableFuture<Integer>());
    }

    @Arbiter
    public void remaining(IZ_Result r) {
        r.r1 = label.getRemainingInvocations();
        r.r2 = label.isFinished();
    }
}
