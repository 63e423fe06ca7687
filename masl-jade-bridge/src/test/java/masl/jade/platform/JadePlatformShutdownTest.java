package masl.jade.platform;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jade.core.AID;
import jade.lang.acl.ACLMessage;
import java.lang.reflect.Constructor;
import java.lang.reflect.Field;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.logging.Handler;
import java.util.logging.LogRecord;
import java.util.logging.Logger;
import masl.jade.Probe;
import masl.testing.jade.ThreadSnapshot;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * JADE 4.3's AMS sometimes fails to end its own main container: it reads the container's agent
 * table while an agent is being removed, meets an empty row, logs "Cannot kill container
 * Main-Container" and never tries again. Here that row is put there on purpose (through JADE's
 * internals: the race itself cannot be forced) and taken away once the AMS has failed: closing the
 * platform must still end it whole, and the next platform of the JVM must start and end as usual.
 */
@Timeout(120)
@Tag("slow")
class JadePlatformShutdownTest {

    @Test
    void aPlatformWhoseAmsFailsOnceToEndItsContainerIsEndedAndTheNextOneToo() throws Exception {
        ThreadSnapshot before = ThreadSnapshot.take();
        JadePlatform platform = JadePlatform.start(JadeOptions.mainContainer());
        CountDownLatch amsFailed = new CountDownLatch(1);
        Handler watcher = new Handler() {
            @Override
            public void publish(LogRecord record) {
                if (String.valueOf(record.getMessage()).contains("Cannot kill container")) {
                    amsFailed.countDown();
                }
            }

            @Override
            public void flush() {
            }

            @Override
            public void close() {
            }
        };
        Logger jade = Logger.getLogger("jade");
        jade.addHandler(watcher);
        try {
            AgentTable table = AgentTable.of(platform);
            AID ghost = new AID("being-removed", AID.ISLOCALNAME);
            table.putEmptyRow(ghost);
            // A thread of the test's own, joined before the threads are counted (on two cores
            // CompletableFuture.runAsync starts a thread per task, which may outlive its task's end).
            CompletableFuture<Void> closed = new CompletableFuture<>();
            Thread closing = new Thread(() -> {
                try {
                    platform.close();
                    closed.complete(null);
                } catch (Throwable failure) {
                    closed.completeExceptionally(failure);
                }
            }, "closing");
            closing.start();
            assertTrue(amsFailed.await(60, TimeUnit.SECONDS), "the AMS met the empty row");
            table.remove(ghost);
            closing.join(TimeUnit.SECONDS.toMillis(60));
            assertFalse(closing.isAlive(), "the platform closed within 60 s");
            closed.join(); // throws what close threw
        } finally {
            jade.removeHandler(watcher);
        }
        assertEquals(List.of(), before.startedSince(), "no thread of the failed shutdown is left");

        try (JadePlatform next = JadePlatform.start(JadeOptions.mainContainer())) {
            Probe sender = new Probe();
            Probe receiver = new Probe();
            next.container().acceptNewAgent("sender", sender).start();
            next.container().acceptNewAgent("receiver", receiver).start();
            ACLMessage hello = new ACLMessage(ACLMessage.INFORM);
            hello.addReceiver(receiver.getAID());
            hello.setContent("hello");
            sender.sendMessage(hello);
            assertEquals("hello", receiver.next().getContent(), "the next platform carries messages");
        }
        assertEquals(List.of(), before.startedSince(), "the next platform ends whole");
    }

    /** The main container's table of local agents (JADE's {@code LADT}), reached by reflection. */
    private record AgentTable(Object rows) {

        static AgentTable of(JadePlatform platform) throws ReflectiveOperationException {
            Object container = field(jade.wrapper.ContainerController.class, "myImpl").get(platform.container());
            Object ladt = field(container.getClass(), "localAgents").get(container);
            return new AgentTable(field(ladt.getClass(), "agents").get(ladt));
        }

        /** A row without its agent: what the AMS meets while an agent is half removed. */
        void putEmptyRow(AID aid) throws ReflectiveOperationException {
            Constructor<?> row = Class.forName("jade.core.LADT$Row").getDeclaredConstructor(jade.core.Agent.class);
            row.setAccessible(true);
            synchronized (rows) {
                rows.getClass().getMethod("put", Object.class, Object.class)
                        .invoke(rows, aid, row.newInstance((Object) null));
            }
        }

        void remove(AID aid) throws ReflectiveOperationException {
            synchronized (rows) {
                rows.getClass().getMethod("remove", Object.class).invoke(rows, aid);
            }
        }

        private static Field field(Class<?> type, String name) throws NoSuchFieldException {
            for (Class<?> c = type; c != null; c = c.getSuperclass()) {
                try {
                    Field field = c.getDeclaredField(name);
                    field.setAccessible(true);
                    return field;
                } catch (NoSuchFieldException notHere) {
                    // declared higher up
                }
            }
            throw new NoSuchFieldException(type.getName() + "." + name);
        }
    }
}
