package masl.sim.xode;

import masl.sim.xode.SceneSpec.BodySpec;

/**
 * The two bodies a joint connects (xode.md §7): each missing link falls back to the enclosing
 * body, unless the other end already is that body, and then to the static environment (null).
 */
final class JointEnds {

    private JointEnds() {
    }

    /**
     * @param first      the body {@code <link1>} names (null if absent or unknown)
     * @param firstGiven whether {@code <link1>} is present
     * @param enclosing  the joint's nearest enclosing body, or null
     * @return {body1, body2}, either may be null for the environment
     */
    static BodySpec[] resolve(BodySpec first, boolean firstGiven, BodySpec second, boolean secondGiven, BodySpec enclosing) {
        BodySpec one = first;
        BodySpec two = second;
        if (!firstGiven) {
            one = enclosing != null && two != enclosing ? enclosing : null;
        }
        if (!secondGiven) {
            two = enclosing != null && one != enclosing ? enclosing : null;
        }
        return new BodySpec[] {one, two};
    }
}
