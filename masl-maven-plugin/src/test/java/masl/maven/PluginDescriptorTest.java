package masl.maven;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.InputStream;
import java.lang.reflect.Field;
import java.lang.reflect.Modifier;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import javax.xml.XMLConstants;
import javax.xml.parsers.DocumentBuilderFactory;
import org.apache.maven.plugin.AbstractMojo;
import org.junit.jupiter.api.Test;
import org.w3c.dom.Document;
import org.w3c.dom.Element;
import org.w3c.dom.Node;

/**
 * The hand-written descriptor, META-INF/maven/plugin.xml, against the Mojo classes Maven configures
 * from it: each parameter is a field of its type, each field a parameter or a component, a default or
 * a user property is given for a parameter that exists, and the coordinates are the build's.
 */
class PluginDescriptorTest {

    private final Element plugin = descriptor().getDocumentElement();

    @Test
    void namesThePluginOfThisBuildWithItsGoalPrefix() {
        assertEquals("org.masl", text(plugin, "groupId"));
        assertEquals("masl-maven-plugin", text(plugin, "artifactId"));
        assertEquals(System.getProperty("masl.version"), text(plugin, "version"));
        assertEquals("masl", text(plugin, "goalPrefix"));
    }

    @Test
    void declaresTheFiveGoalsInTheirPhases() {
        Map<String, String> phases = new TreeMap<>();
        for (Element mojo : children(child(plugin, "mojos"), "mojo")) {
            phases.put(text(mojo, "goal"), text(mojo, "phase") + "/" + text(mojo, "executePhase"));
        }
        assertEquals(Map.of("compile", "generate-sources/null", "testCompile", "generate-test-sources/null", "check", "null/null",
                "run", "null/compile", "container", "null/compile"), phases);
    }

    @Test
    void everyParameterIsAFieldOfItsTypeAndEveryFieldIsConfigured() throws ClassNotFoundException {
        for (Element mojo : children(child(plugin, "mojos"), "mojo")) {
            Class<?> type = Class.forName(text(mojo, "implementation"));
            assertTrue(AbstractMojo.class.isAssignableFrom(type) && !Modifier.isAbstract(type.getModifiers()), type + " is a Mojo");
            Map<String, Field> fields = fields(type);
            Map<String, String> declared = new TreeMap<>();
            for (Element parameter : children(child(mojo, "parameters"), "parameter")) {
                declared.put(text(parameter, "name"), text(parameter, "type"));
            }
            for (Element component : children(child(mojo, "requirements"), "requirement")) {
                declared.put(text(component, "field-name"), text(component, "role"));
            }
            Map<String, String> fieldTypes = new TreeMap<>();
            fields.forEach((name, field) -> fieldTypes.put(name, field.getType().getTypeName()));
            assertEquals(fieldTypes, declared, text(mojo, "goal") + ": fields against parameters and components");
            for (Element value : children(child(mojo, "configuration"), null)) {
                String name = value.getTagName();
                assertTrue(declared.containsKey(name), text(mojo, "goal") + " configures " + name + ", which is no parameter");
                assertEquals(declared.get(name), value.getAttribute("implementation"), text(mojo, "goal") + ": the type of " + name);
            }
        }
    }

    /** The fields Maven sets: those of the class and its superclasses up to AbstractMojo, but constants. */
    private static Map<String, Field> fields(Class<?> type) {
        Map<String, Field> fields = new TreeMap<>();
        for (Class<?> at = type; at != AbstractMojo.class; at = at.getSuperclass()) {
            for (Field field : at.getDeclaredFields()) {
                if (!Modifier.isStatic(field.getModifiers())) {
                    fields.put(field.getName(), field);
                }
            }
        }
        return fields;
    }

    private static Document descriptor() {
        try (InputStream in = PluginDescriptorTest.class.getResourceAsStream("/META-INF/maven/plugin.xml")) {
            DocumentBuilderFactory factory = DocumentBuilderFactory.newInstance();
            factory.setFeature("http://apache.org/xml/features/disallow-doctype-decl", true);
            factory.setAttribute(XMLConstants.ACCESS_EXTERNAL_DTD, "");
            factory.setAttribute(XMLConstants.ACCESS_EXTERNAL_SCHEMA, "");
            return factory.newDocumentBuilder().parse(in);
        } catch (Exception unreadable) {
            throw new AssertionError("META-INF/maven/plugin.xml cannot be read", unreadable);
        }
    }

    private static Element child(Element parent, String name) {
        List<Element> found = children(parent, name);
        return found.isEmpty() ? null : found.get(0);
    }

    /** The child elements named {@code name} (all of them for null); none of an absent parent. */
    private static List<Element> children(Element parent, String name) {
        List<Element> found = new ArrayList<>();
        if (parent == null) {
            return found;
        }
        for (Node node = parent.getFirstChild(); node != null; node = node.getNextSibling()) {
            if (node instanceof Element element && (name == null || element.getTagName().equals(name))) {
                found.add(element);
            }
        }
        return found;
    }

    private static String text(Element parent, String name) {
        Element element = child(parent, name);
        return element == null ? null : element.getTextContent().trim();
    }
}
