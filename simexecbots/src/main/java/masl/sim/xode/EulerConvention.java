package masl.sim.xode;

/** How {@code <euler x y z>} becomes a rotation matrix (xode.md §10.1). */
public enum EulerConvention {
    /** R = Rx(x)·Ry(y)·Rz(z), as odejava (the reference implementation) does; the default. */
    XYZ,
    /** R = Rx(−x)·Ry(−y)·Rz(−z): what PyODE's xode package hands to ODE, for files written with it. */
    PYODE_COMPATIBLE
}
