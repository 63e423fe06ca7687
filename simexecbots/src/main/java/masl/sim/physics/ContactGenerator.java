package masl.sim.physics;

import java.util.HashSet;
import java.util.Set;
import org.ode4j.ode.DBody;
import org.ode4j.ode.DContact;
import org.ode4j.ode.DContactBuffer;
import org.ode4j.ode.DContactJoint;
import org.ode4j.ode.DGeom;
import org.ode4j.ode.DJointGroup;
import org.ode4j.ode.DRay;
import org.ode4j.ode.DSpace;
import org.ode4j.ode.DWorld;
import org.ode4j.ode.OdeConstants;
import org.ode4j.ode.OdeHelper;

/**
 * Finds colliding geoms in a space tree and adds a frictional contact joint per contact point.
 * Not thread-safe: used only by the stepping thread under the world's lock.
 *
 * <p>Skipped pairs: two static geoms, two geoms of one body, bodies already connected by a joint
 * (a wheel and its chassis overlap by design), and rays, which are sensors, not solids.
 */
final class ContactGenerator {

    /** Slightly soft contacts keep resting stacks from jittering (ODE manual's advice). */
    private static final double CONTACT_SOFT_CFM = 1e-5;

    private final DWorld world;
    private final DJointGroup contacts;
    private final double friction;
    private final DContactBuffer buffer;
    private final int maxContacts;
    private final DGeom.DNearCallback near = this::near;
    /** Bodies that touched a static geom (the ground, a wall) in the latest {@link #collide}. */
    private final Set<DBody> touchingEnvironment = new HashSet<>();

    ContactGenerator(DWorld world, DJointGroup contacts, double friction, int maxContacts) {
        this.world = world;
        this.contacts = contacts;
        this.friction = friction;
        this.maxContacts = maxContacts;
        this.buffer = new DContactBuffer(maxContacts);
    }

    /**
     * Collides everything in {@code space}: pairs among its direct members (a child space against
     * a geom or another space is expanded), then, recursively, the inside of each child space —
     * which a plain callback would miss for a child space that overlaps nothing.
     */
    void collide(DSpace space) {
        touchingEnvironment.clear();
        collideTree(space);
    }

    private void collideTree(DSpace space) {
        space.collide(null, near);
        for (DGeom member : space.getGeoms()) {
            if (member instanceof DSpace child) {
                collideTree(child);
            }
        }
    }

    /** The bodies that touched a static geom during the latest {@link #collide}. */
    Set<DBody> touchingEnvironment() {
        return touchingEnvironment;
    }

    private void near(Object data, DGeom first, DGeom second) {
        if (first instanceof DSpace || second instanceof DSpace) {
            OdeHelper.spaceCollide2(first, second, data, near);
            return;
        }
        if (first instanceof DRay || second instanceof DRay) {
            return;
        }
        DBody a = first.getBody();
        DBody b = second.getBody();
        if (a == b || (a != null && b != null && OdeHelper.areConnectedExcluding(a, b, DContactJoint.class))) {
            return;
        }
        int count = OdeHelper.collide(first, second, maxContacts, buffer.getGeomBuffer());
        if (count > 0 && (a == null || b == null)) {
            touchingEnvironment.add(a == null ? b : a);
        }
        for (int i = 0; i < count; i++) {
            DContact contact = buffer.get(i);
            contact.surface.mode = OdeConstants.dContactApprox1 | OdeConstants.dContactSoftCFM;
            contact.surface.mu = friction;
            contact.surface.soft_cfm = CONTACT_SOFT_CFM;
            OdeHelper.createContactJoint(world, contacts, contact).attach(a, b);
        }
    }
}
