package masl.runtime;

/** Why a mission failed when the heap was exhausted: its agents' data outgrew the JVM's heap (-Xmx). */
public final class MissionOutOfMemory extends RuntimeException {

    private static final long serialVersionUID = 1L;

    MissionOutOfMemory() {
        super("out of memory", null, false, false);
    }

    /** The heap's limit in MiB, as the JVM was given it ({@code -Xmx}) or chose it. */
    public static long heapLimitMiB() {
        return Runtime.getRuntime().maxMemory() >> 20;
    }
}
