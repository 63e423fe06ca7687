package masl.runtime.descriptor;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Pattern;

/**
 * Turns a descriptor's element tree into a {@link Declaration}, checking the rules that need no
 * supertype: member ids and names unique in the file, state names unique, a state's members listed
 * once. Elements the schema already rejected (a required attribute missing, a malformed value) are
 * left out silently, so each fault is reported once.
 */
final class DeclarationReader {

    private static final Pattern OCTAL_RIGHTS = Pattern.compile("[0-7]{3}");

    private final Problems problems;
    private final Map<String, XmlElement> elementsById = new HashMap<>();
    private final Map<String, XmlElement> elementsByName = new HashMap<>();

    private DeclarationReader(Problems problems) {
        this.problems = problems;
    }

    /** The declaration of {@code agent}; null when its identity ({@code full_class_name}) is missing. */
    static Declaration read(XmlElement agent, Problems problems) {
        return new DeclarationReader(problems).declaration(agent);
    }

    private Declaration declaration(XmlElement agent) {
        String fullClassName = agent.attribute("full_class_name");
        if (!agent.name().equals("Agent") || fullClassName == null) {
            return null;
        }
        List<Declaration.UtilityClass> utilityClasses = new ArrayList<>();
        for (XmlElement element : agent.children("Class")) {
            if (element.attribute("name") != null) {
                utilityClasses.add(new Declaration.UtilityClass(element.attribute("name"), element));
            }
        }
        List<Attribute> attributes = new ArrayList<>();
        List<Primitive> primitives = new ArrayList<>();
        for (XmlElement element : agent.children()) {
            if (element.name().equals("Attribute") && isUniqueMember(element, "attribute_name")) {
                attribute(element, attributes);
            } else if (element.name().equals("Primitive") && isUniqueMember(element, "function_name")) {
                primitive(element, primitives);
            }
        }
        List<Declaration.StateDeclaration> states = new ArrayList<>();
        Map<String, XmlElement> statesByName = new HashMap<>();
        for (XmlElement element : agent.children("Permeability")) {
            String name = element.attribute("permeability_name");
            String umask = element.attribute("umask");
            if (name == null || umask == null || !OCTAL_RIGHTS.matcher(umask).matches()) {
                continue;
            }
            XmlElement first = statesByName.putIfAbsent(name, element);
            if (first != null) {
                problems.at(element, "state '" + name + "' is already declared on line " + first.line());
                continue;
            }
            states.add(state(element, name, Integer.parseInt(umask, 8)));
        }
        String shortName = agent.attribute("short_class_name");
        return new Declaration(shortName == null ? simpleName(fullClassName) : shortName, fullClassName,
                agent.attribute("super_full_class_name"), agent, utilityClasses, primitives, attributes, states,
                fipa(agent.children("Fipa")));
    }

    /** The one {@code <Fipa>}, naming its agent one way; null if there is none or it is wrong. */
    private FipaBinding fipa(List<XmlElement> elements) {
        if (elements.isEmpty()) {
            return null;
        }
        for (XmlElement extra : elements.subList(1, elements.size())) {
            problems.at(extra, "a type has one <Fipa> at most: the first is on line " + elements.get(0).line());
        }
        XmlElement element = elements.get(0);
        String serviceType = element.attribute("service_type");
        String agentName = element.attribute("agent_name");
        if ((serviceType == null) == (agentName == null)) {
            problems.at(element, "<Fipa> names its agent by service_type or by agent_name: give one of the two");
            return null;
        }
        String language = element.attribute("language");
        return language == null ? null
                : new FipaBinding(serviceType, agentName, language, element.attribute("ontology"));
    }

    /** Records the member's id and name; false (and a problem) when either is taken already in this file. */
    private boolean isUniqueMember(XmlElement element, String nameAttribute) {
        String id = element.attribute("member_id");
        String name = element.attribute(nameAttribute);
        if (id == null || name == null) {
            return false;
        }
        boolean unique = true;
        XmlElement sameId = elementsById.putIfAbsent(id, element);
        if (sameId != null) {
            problems.at(element, "duplicate member_id '" + id + "': already used by " + sameId.describe()
                    + " on line " + sameId.line());
            unique = false;
        }
        XmlElement sameName = elementsByName.putIfAbsent(name, element);
        if (sameName != null) {
            problems.at(element, "duplicate member name '" + name + "': already declared by " + sameName.describe()
                    + " on line " + sameName.line());
            unique = false;
        }
        return unique;
    }

    private void attribute(XmlElement element, List<Attribute> attributes) {
        String type = element.attribute("attribute_class");
        if (type == null) {
            return;
        }
        List<String> modifiers = modifiers(element);
        attributes.add(new Attribute(element.attribute("attribute_name"), element.attribute("member_id"),
                JavaTypes.normalise(type), element.attribute("value"), modifiers.contains("static"),
                modifiers.contains("final"), element.line(), element.column()));
    }

    private void primitive(XmlElement element, List<Primitive> primitives) {
        String returnType = element.attribute("return_type_name");
        String synchronous = element.attribute("synchronous_call");
        if (returnType == null || synchronous == null) {
            return;
        }
        List<Parameter> parameters = new ArrayList<>();
        for (XmlElement parameter : element.children("Parameter")) {
            String name = parameter.attribute("parameter_name");
            String type = parameter.attribute("parameter_type");
            if (name != null && type != null) {
                if (parameters.stream().anyMatch(previous -> previous.name().equals(name))) {
                    problems.at(parameter, "duplicate parameter name '" + name + "'");
                }
                parameters.add(new Parameter(name, JavaTypes.normalise(type)));
            }
        }
        List<String> exceptions = element.children("Exception").stream()
                .map(exception -> exception.attribute("exception_name")).filter(name -> name != null).toList();
        List<String> modifiers = modifiers(element);
        primitives.add(new Primitive(element.attribute("function_name"), element.attribute("member_id"),
                JavaTypes.normalise(returnType), parameters, isTrue(synchronous), isTrue(element.attribute("accessor")),
                element.attribute("countermeasure"), modifiers.contains("static"), modifiers.contains("final"),
                exceptions, element.line(), element.column()));
    }

    private Declaration.StateDeclaration state(XmlElement element, String name, int umask) {
        Map<String, Integer> members = new LinkedHashMap<>();
        List<XmlElement> memberElements = new ArrayList<>();
        for (XmlElement member : element.children("Member")) {
            String id = member.attribute("member_id");
            String rights = member.attribute("rights");
            if (id == null || rights == null || !OCTAL_RIGHTS.matcher(rights).matches()) {
                continue;
            }
            if (members.putIfAbsent(id, Integer.parseInt(rights, 8)) != null) {
                problems.at(member, "member '" + id + "' is already listed in state '" + name + "'");
            } else {
                memberElements.add(member);
            }
        }
        String unlisted = element.attribute("unlisted_rights");
        Integer unlistedRights = unlisted != null && OCTAL_RIGHTS.matcher(unlisted).matches()
                ? Integer.valueOf(unlisted, 8) : null;
        return new Declaration.StateDeclaration(name, umask, members, memberElements, unlistedRights, element);
    }

    private static List<String> modifiers(XmlElement member) {
        return member.children("Modifier").stream().map(modifier -> modifier.attribute("modifier_name")).toList();
    }

    /** xs:boolean: {@code true} or {@code 1}. */
    private static boolean isTrue(String value) {
        return value != null && (value.strip().equals("true") || value.strip().equals("1"));
    }

    private static String simpleName(String fullClassName) {
        return fullClassName.substring(fullClassName.lastIndexOf('.') + 1);
    }
}
