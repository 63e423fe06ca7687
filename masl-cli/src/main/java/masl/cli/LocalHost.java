package masl.cli;

import java.net.InetAddress;
import java.net.NetworkInterface;
import java.net.SocketException;
import java.net.UnknownHostException;

/**
 * {@code --local-host}: the address a JADE container of masl binds to and gives the platform to reach
 * it at. Loopback unless asked (only this machine can join, docs/decisions.md, "Containers on a
 * network"); asked, it must be an address of one of this machine's interfaces, and not the
 * wildcard, which binds every interface but reaches none.
 */
final class LocalHost {

    private LocalHost() {
    }

    /** {@code host}, checked to be one of this machine's addresses; null stays null (loopback). */
    static String checked(String host) throws UsageException {
        if (host == null) {
            return null;
        }
        InetAddress address = resolved("--local-host", host);
        if (address.isAnyLocalAddress()) {
            throw new UsageException("--local-host " + host + " is every address of this machine: give the one the"
                    + " other machines reach it at");
        }
        if (assigned(address)) {
            return host;
        }
        throw new UsageException(address.isLoopbackAddress()
                ? "--local-host " + host + " is no interface's address, which JADE binds to: give 127.0.0.1, or the"
                        + " address the other machines reach this one at"
                : "--local-host " + host + " is not an address of this machine: give the one the other machines reach it at");
    }

    /**
     * Refuses to join the main container at {@code mainHost} from loopback when it is on another
     * machine: it could not reach this container there, and JADE would say only that the join failed.
     */
    static void reachableFrom(String mainHost, String localHost) throws UsageException {
        if (localHost != null) {
            return;
        }
        InetAddress main = resolved("--main-host", mainHost);
        if (!ofThisMachine(main)) {
            throw new UsageException("the main container at " + mainHost + " is on another machine, which cannot reach"
                    + " this JVM's container on loopback: give --local-host ADDRESS, this machine's address on their network");
        }
    }

    private static InetAddress resolved(String option, String host) throws UsageException {
        try {
            return InetAddress.getByName(host);
        } catch (UnknownHostException unknown) {
            throw new UsageException(option + " " + host + ": no such host");
        }
    }

    /** Whether {@code address} is on this machine: loopback, or one of its interfaces'. */
    private static boolean ofThisMachine(InetAddress address) {
        return address.isLoopbackAddress() || assigned(address);
    }

    /**
     * Whether an interface of this machine has {@code address}: what JADE binds to. Not every loopback
     * address is (127.0.0.2 reaches this machine, but JADE takes it for another).
     */
    private static boolean assigned(InetAddress address) {
        try {
            return NetworkInterface.getByInetAddress(address) != null;
        } catch (SocketException cannotTell) {
            return false;
        }
    }
}
