package masl.gradle;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.nio.file.Path;
import java.util.Map;
import java.util.TreeMap;
import javax.xml.XMLConstants;
import javax.xml.parsers.DocumentBuilderFactory;
import javax.xml.parsers.ParserConfigurationException;
import org.junit.jupiter.api.Test;
import org.w3c.dom.Element;
import org.w3c.dom.NodeList;
import org.xml.sax.SAXException;

/**
 * The POMs every module is published with, as a Maven build reads them: what each module's API
 * exposes has compile scope, what it only runs with runtime scope, and no build-time tool (the ANTLR
 * tool) or test library leaks into them. Read from the folder the modules were just published into.
 */
class PublishedPomsTest {

    @Test
    void eachModuleDependsOnWhatItsApiExposesAtCompileScopeAndOnTheRestAtRuntime() throws Exception {
        assertEquals(Map.of("org.antlr:antlr4-runtime", "compile"), dependencies("masl-grammar"));
        assertEquals(Map.of("com.fasterxml.woodstox:woodstox-core", "runtime"), dependencies("masl-runtime"));
        assertEquals(Map.of("org.masl:masl-grammar", "compile", "org.masl:masl-runtime", "compile"), dependencies("masl-translator"));
        assertEquals(Map.of("org.masl:masl-runtime", "compile"), dependencies("agents"));
        assertEquals(Map.of("org.masl:masl-runtime", "compile", "net.sf.ingenias:jade", "compile",
                "com.fasterxml.jackson.core:jackson-databind", "compile"), dependencies("masl-jade-bridge"));
        assertEquals(Map.of("org.masl:masl-translator", "compile", "org.junit.jupiter:junit-jupiter-api", "compile",
                "org.masl:agents", "runtime", "org.junit.jupiter:junit-jupiter-engine", "runtime"), dependencies("masl-testing"));
        assertEquals(Map.of("org.masl:masl-testing", "compile", "org.masl:masl-jade-bridge", "compile"),
                dependencies("masl-testing-jade"));
        assertEquals(Map.of("org.masl:masl-translator", "runtime", "org.masl:agents", "runtime"), dependencies("masl-gradle-plugin"));
    }

    /** group:artifact to scope, of the module's published POM. */
    private static Map<String, String> dependencies(String module) throws IOException, SAXException, ParserConfigurationException {
        Path pom = Path.of(System.getProperty("masl.repo"), "org/masl", module, UserBuild.VERSION,
                module + "-" + UserBuild.VERSION + ".pom");
        DocumentBuilderFactory factory = DocumentBuilderFactory.newInstance();
        // A POM has no DOCTYPE: none is read, nothing is fetched.
        factory.setFeature("http://apache.org/xml/features/disallow-doctype-decl", true);
        factory.setFeature(XMLConstants.FEATURE_SECURE_PROCESSING, true);
        NodeList found = factory.newDocumentBuilder().parse(pom.toFile()).getElementsByTagName("dependency");
        Map<String, String> scopes = new TreeMap<>();
        for (int i = 0; i < found.getLength(); i++) {
            Element dependency = (Element) found.item(i);
            scopes.put(text(dependency, "groupId") + ":" + text(dependency, "artifactId"), text(dependency, "scope"));
        }
        return scopes;
    }

    private static String text(Element parent, String tag) {
        return parent.getElementsByTagName(tag).item(0).getTextContent();
    }
}
