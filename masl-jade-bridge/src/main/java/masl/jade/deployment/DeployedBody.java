package masl.jade.deployment;

import java.lang.reflect.Method;
import java.util.List;
import java.util.function.Supplier;
import masl.jade.stub.BodyStub;
import masl.runtime.AgentImplementation;

/**
 * What a deployed agent's object in the mission's JVM does (a stub of its class): its primitives run
 * in its container, on its real object, and the runtime's reads and writes of its attributes (by
 * programs that run here: in-process, placed) go there too. Only the member's name and values travel.
 */
final class DeployedBody implements BodyStub {

    private final int proxyId;
    private final Members members;
    private final List<String> primitives;
    private final NamedCalls named;
    private volatile AgentImplementation self;

    DeployedBody(int proxyId, Members members, NamedCalls named) {
        this.proxyId = proxyId;
        this.members = members;
        this.primitives = members.methods().stream().map(Method::getName).toList();
        this.named = named;
    }

    /** The stub this body is the body of. */
    void of(AgentImplementation stub) {
        this.self = stub;
    }

    @Override
    public Object call(int method, Object[] args) {
        return named.inContainer(proxyId, primitives.get(method), args);
    }

    @Override
    public Object readAttribute(String attribute, Supplier<?> read) {
        return read instanceof Relayed ? read.get() : named.read(proxyId, attribute);
    }

    /** A program's write ({@code () -> owner.x = v}) is run on the stub for its value, which goes to the container. */
    @Override
    public void writeAttribute(String attribute, Runnable write) {
        if (write instanceof Relayed) {
            write.run();
            return;
        }
        named.write(proxyId, attribute, Values.toJson(members.written(self, attribute, write)));
    }
}
