package masl.sim.physics;

import java.util.ArrayList;
import java.util.List;
import org.ode4j.math.DMatrix3C;
import org.ode4j.math.DVector3C;
import org.ode4j.ode.DBox;
import org.ode4j.ode.DGeom;
import org.ode4j.ode.DSpace;

/** Top-down outlines of the static boxes of a space tree, for pictures of a run. */
final class StaticOutlines {

    private StaticOutlines() {
    }

    static List<double[][]> of(DSpace space) {
        List<double[][]> outlines = new ArrayList<>();
        collect(space, outlines);
        return outlines;
    }

    private static void collect(DSpace space, List<double[][]> outlines) {
        for (DGeom geom : space.getGeoms()) {
            if (geom instanceof DSpace child) {
                collect(child, outlines);
            } else if (geom instanceof DBox box && box.getBody() == null) {
                outlines.add(outline(box));
            }
        }
    }

    /** Projects the four corners of the box's half-height section on the ground, in order around it. */
    private static double[][] outline(DBox box) {
        DVector3C side = box.getLengths();
        DVector3C centre = box.getPosition();
        DMatrix3C r = box.getRotation();
        // The box axis whose world direction is most vertical is dropped; the other two span the outline.
        int up = 0;
        for (int axis = 1; axis < 3; axis++) {
            if (Math.abs(r.get(2, axis)) > Math.abs(r.get(2, up))) {
                up = axis;
            }
        }
        int a = up == 0 ? 1 : 0;
        int b = up == 2 ? 1 : 2;
        double[][] corners = new double[4][];
        int[][] signs = {{1, 1}, {-1, 1}, {-1, -1}, {1, -1}};
        for (int i = 0; i < 4; i++) {
            double ha = signs[i][0] * side.get(a) / 2;
            double hb = signs[i][1] * side.get(b) / 2;
            corners[i] = new double[] {
                centre.get0() + r.get(0, a) * ha + r.get(0, b) * hb,
                centre.get1() + r.get(1, a) * ha + r.get(1, b) * hb};
        }
        return corners;
    }
}
