package masl.sim.xode;

import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import masl.sim.xode.SceneSpec.BodySpec;
import masl.sim.xode.SceneSpec.JointSpec;

/**
 * Checks joint links once the whole document is read, so a link may name a body defined later
 * (xode.md §10.8): every link names a body of the document, and each joint ends up connecting two
 * different things, not nothing and not one body to itself.
 */
final class LinkChecker {

    private final Problems problems;
    private final NameRegistry names;

    LinkChecker(Problems problems, NameRegistry names) {
        this.problems = problems;
        this.names = names;
    }

    /** @return the prefixed names that joints link to */
    Set<String> check(List<BodySpec> bodies, List<JointSpec> joints) {
        Map<String, BodySpec> bodiesByName = new LinkedHashMap<>();
        for (BodySpec body : bodies) {
            if (body.name() != null) {
                bodiesByName.putIfAbsent(body.name(), body);
            }
        }
        Set<String> targets = new HashSet<>();
        for (JointSpec joint : joints) {
            boolean known = knownLink(joint, "link1", joint.link1Name(), bodiesByName, targets);
            known &= knownLink(joint, "link2", joint.link2Name(), bodiesByName, targets);
            if (known) {
                checkEnds(joint, bodiesByName);
            }
        }
        return targets;
    }

    private boolean knownLink(JointSpec joint, String link, String target, Map<String, BodySpec> bodiesByName, Set<String> targets) {
        if (target == null) {
            return true;
        }
        targets.add(target);
        if (bodiesByName.containsKey(target)) {
            return true;
        }
        problems.error(joint.element().child(link).orElse(joint.element()), "no body named '" + names.unprefixed(target) + "' in this document");
        return false;
    }

    private void checkEnds(JointSpec joint, Map<String, BodySpec> bodiesByName) {
        BodySpec first = joint.link1Name() == null ? null : bodiesByName.get(joint.link1Name());
        BodySpec second = joint.link2Name() == null ? null : bodiesByName.get(joint.link2Name());
        BodySpec[] ends = JointEnds.resolve(first, joint.link1Name() != null, second, joint.link2Name() != null, joint.enclosing());
        if (ends[0] == null && ends[1] == null) {
            problems.error(joint.element(), "the joint links nothing: give <link1>/<link2> or put it inside a body");
        } else if (ends[0] == ends[1]) {
            problems.error(joint.element(), "both ends of the joint are the same body");
        }
    }
}
