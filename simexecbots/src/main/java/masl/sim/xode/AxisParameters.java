package masl.sim.xode;

import org.ode4j.ode.DJoint;

/** Maps XODE axis attributes (xode.md §7) to ode4j joint parameters. */
final class AxisParameters {

    private AxisParameters() {
    }

    /**
     * @param xodeName  e.g. {@code LowStop} or {@code FMax}
     * @param axisIndex 0 for the first {@code <axis>}
     * @return e.g. {@code dParamLoStop1}
     */
    static DJoint.PARAM_N odeParameter(String xodeName, int axisIndex) {
        String odeName = xodeName.equals("LowStop") ? "LoStop" : xodeName;
        return DJoint.PARAM_N.valueOf("dParam" + odeName + (axisIndex + 1));
    }
}
