package masl.runtime.descriptor;

import java.util.Map;

/**
 * A permeability state of one agent type (MASL §11) with the rights it gives to each of the type's
 * members, inheritance applied (see {@link AgentType#states()} and the README, "Descriptors").
 * Rights are 3 octal digits like {@code chmod}: u (the agent itself), g (an agent in exactly the same
 * innermost block), o (any other); r=4 read attribute, w=2 write attribute, x=1 invoke primitive.
 * Immutable.
 */
public final class PermeabilityState {

    /** Permission bits within one requester's digit. */
    public static final int READ = 4;
    public static final int WRITE = 2;
    public static final int INVOKE = 1;

    /** Rights given to every member by a state that lists no {@code <Member>}. */
    static final int ALL_RIGHTS = 0777;

    /** Who asks, i.e. which octal digit of the rights applies. */
    public enum Requester {
        SELF(6), GROUP(3), OTHER(0);

        private final int shift;

        Requester(int shift) {
            this.shift = shift;
        }
    }

    private final String name;
    private final int umask;
    private final Map<String, Integer> granted;
    private final int grantedToUnlisted;
    private final int line;

    /**
     * @param granted           rights before the umask for each member id of the type
     * @param grantedToUnlisted rights a subtype's new member gets unless the subtype lists it: 0777 when
     *                          this state or one it redeclares lists no member, else 0
     */
    PermeabilityState(String name, int umask, Map<String, Integer> granted, int grantedToUnlisted, int line) {
        this.name = name;
        this.umask = umask;
        this.granted = Map.copyOf(granted);
        this.grantedToUnlisted = grantedToUnlisted;
        this.line = line;
    }

    public String name() {
        return name;
    }

    /** The umask (parsed from octal) of the most derived declaration of this state. */
    public int umask() {
        return umask;
    }

    /**
     * Effective rights of a member in this state: {@code rights & ~umask}, 0 for an id that names no
     * member of the type. Example: {@code 0644} lets the agent read and write, others only read.
     */
    public int rights(String memberId) {
        return granted.getOrDefault(memberId, 0) & ~umask;
    }

    /** Whether {@code requester} has {@code permission} ({@link #READ}, {@link #WRITE}, {@link #INVOKE}) on the member. */
    public boolean allows(String memberId, Requester requester, int permission) {
        return ((rights(memberId) >> requester.shift) & permission) == permission;
    }

    /** 1-based line of the most derived {@code <Permeability>} declaring this state. */
    public int line() {
        return line;
    }

    /** Rights before the umask; 0 for unknown ids. */
    int granted(String memberId) {
        return granted.getOrDefault(memberId, 0);
    }

    int grantedToUnlisted() {
        return grantedToUnlisted;
    }

    @Override
    public String toString() {
        return name + " (umask " + String.format("%03o", umask) + ")";
    }
}
