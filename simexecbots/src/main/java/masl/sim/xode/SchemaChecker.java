package masl.sim.xode;

import java.util.Set;

/**
 * Reports elements and attributes that XODE does not define, or that stand where XODE does not
 * allow them. Unknown names are warnings (errors in strict mode) as xode.md §10.14 decides; a
 * known element in the wrong place is an error because the file's author clearly meant something
 * the loader cannot honour. {@code <ext>} subtrees are skipped unread (§8).
 */
final class SchemaChecker {

    /** Attributes some writers add that carry nothing for physics (xode.md §10.14). */
    private static final Set<String> TOLERATED = Set.of("transformstyle");

    private final Problems problems;

    SchemaChecker(Problems problems) {
        this.problems = problems;
    }

    /** @return false when the root is not {@code <xode>}, in which case nothing else is worth reading */
    boolean check(XodeElement root) {
        if (!root.name().equals("xode")) {
            problems.error(root, "the root element must be <xode>, found <" + root.name() + ">");
            return false;
        }
        checkElement(root);
        return true;
    }

    private void checkElement(XodeElement element) {
        for (String attribute : element.attributes().keySet()) {
            if (!XodeSchema.allowsAttribute(element.name(), attribute) && !TOLERATED.contains(attribute)
                    && !(element.name().equals("v") && attribute.equals("e"))) {
                problems.warning(element, "unknown attribute '" + attribute + "' (ignored)");
            }
        }
        for (XodeElement child : element.children()) {
            if (child.name().equals("ext")) {
                continue;
            }
            if (!XodeSchema.isKnown(child.name())) {
                problems.warning(child, "unknown element inside <" + element.name() + "> (ignored)");
            } else if (!XodeSchema.allowsChild(element.name(), child.name())) {
                problems.error(child, "not allowed inside <" + element.name() + ">");
            } else {
                checkElement(child);
            }
        }
    }
}
