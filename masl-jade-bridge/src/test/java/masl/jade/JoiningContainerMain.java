package masl.jade;

import jade.core.AID;
import jade.core.Agent;
import jade.core.behaviours.OneShotBehaviour;
import jade.lang.acl.ACLMessage;
import java.util.concurrent.CountDownLatch;
import masl.jade.platform.JadeOptions;
import masl.jade.platform.JadePlatform;
import masl.jade.platform.TwoJvmTest;

/**
 * Run in a second JVM by {@link TwoJvmTest}: joins the platform at {@code host port}, says hello to
 * agent {@code probe-main} and waits for its answer, then closes its container and returns from
 * {@code main} without {@code System.exit}: the JVM ends by itself only if no thread is left.
 */
public final class JoiningContainerMain {

    private JoiningContainerMain() {
    }

    public static void main(String[] args) throws Exception {
        try (JadePlatform platform = JadePlatform.start(JadeOptions.join(args[0], Integer.parseInt(args[1])))) {
            Greeter greeter = new Greeter();
            platform.container().acceptNewAgent("remote-greeter", greeter).start();
            greeter.answered.await();
            System.out.println("answered: " + greeter.answer);
        }
    }

    /** Sends a greeting and waits, in its own thread, for the answer. */
    private static final class Greeter extends Agent {
        private static final long serialVersionUID = 1L;
        private final transient CountDownLatch answered = new CountDownLatch(1);
        private transient volatile String answer;

        @Override
        protected void setup() {
            addBehaviour(new OneShotBehaviour(this) {
                private static final long serialVersionUID = 1L;

                @Override
                public void action() {
                    ACLMessage hello = new ACLMessage(ACLMessage.INFORM);
                    hello.addReceiver(new AID("probe-main", AID.ISLOCALNAME));
                    hello.setContent("hello from another JVM");
                    send(hello);
                    answer = blockingReceive().getContent();
                    answered.countDown();
                }
            });
        }
    }
}
