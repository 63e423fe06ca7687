package masl.sim.physics;

import java.util.Set;
import org.ode4j.math.DVector3;
import org.ode4j.ode.DBody;
import org.ode4j.ode.DContactGeomBuffer;
import org.ode4j.ode.DGeom;
import org.ode4j.ode.DRay;
import org.ode4j.ode.DSpace;
import org.ode4j.ode.OdeHelper;

/**
 * Casts one ray through a space tree and finds the nearest solid it meets: what an infra-red
 * proximity sensor measures. Not thread-safe; used under the world's lock.
 */
final class RayCaster {

    private final DContactGeomBuffer hit = new DContactGeomBuffer(1);

    /**
     * The distance from {@code origin} along the unit vector {@code direction} to the first geom
     * within {@code length}, skipping rays and geoms of {@code ignored} bodies (the sensor's own
     * robot); {@link Double#POSITIVE_INFINITY} when there is none.
     */
    double cast(DSpace space, DVector3 origin, DVector3 direction, double length, Set<DBody> ignored) {
        DRay ray = OdeHelper.createRay(null, length);
        try {
            ray.set(origin, direction);
            ray.setClosestHit(true);
            double[] nearest = {Double.POSITIVE_INFINITY};
            DGeom.DNearCallback[] near = new DGeom.DNearCallback[1];
            near[0] = (data, first, second) -> {
                DGeom other = first == ray ? second : first;
                if (other instanceof DSpace) {
                    OdeHelper.spaceCollide2(ray, other, data, near[0]);
                } else if (!(other instanceof DRay) && !ignored.contains(other.getBody())
                        && OdeHelper.collide(ray, other, 1, hit) > 0) {
                    nearest[0] = Math.min(nearest[0], hit.get(0).depth);
                }
            };
            OdeHelper.spaceCollide2(ray, space, null, near[0]);
            return nearest[0];
        } finally {
            ray.destroy();
        }
    }
}
