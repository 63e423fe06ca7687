package masl.runtime;

/** The mode of an e-block (MASL §6.2): the rhythm its members run its body in. */
public enum Mode {
    /** One agent per wave of the parent block runs the body; the other eligible agents skip it. */
    SCALAR,
    /** Members run the body in lock-step behind the entry, synchronisation and exit barriers (§6.3). */
    SYNCHRONOUS,
    /** Members run the body independently, with no barrier. */
    ASYNCHRONOUS
}
