package masl.sim.xode;

import java.io.StringReader;
import java.util.ArrayDeque;
import java.util.Deque;
import java.util.List;
import javax.xml.stream.Location;
import javax.xml.stream.XMLStreamConstants;
import javax.xml.stream.XMLStreamException;
import javax.xml.stream.XMLStreamReader;
import masl.runtime.diagnostic.Severity;
import masl.runtime.xml.SecureXml;

/**
 * Reads XODE and scenario text into a tree of {@link XodeElement}s with masl's one XML reader
 * ({@link SecureXml}, shared with the agent type descriptors): no DTD is processed, nothing is
 * fetched and no entity is expanded; a reference to an entity the document declares is an error.
 */
public final class SecureXmlReader {

    /**
     * The deepest nesting of elements read ({@link SecureXml#DEEPEST}): the loader's walks recurse
     * into nested elements (on a deep stack, {@link XodeLoader}).
     */
    public static final int DEEPEST = SecureXml.DEEPEST;

    private final String fileName;
    private final String text;

    /** @param fileName name used in locations; @param text the whole document */
    public SecureXmlReader(String fileName, String text) {
        this.fileName = fileName;
        this.text = text;
    }

    /**
     * Parses the document.
     *
     * @return the root element
     * @throws XodeException when the text is not well-formed XML, with the parser's position
     */
    public XodeElement read() throws XodeException {
        XMLStreamReader reader = null;
        try {
            reader = SecureXml.reader(fileName, new StringReader(text));
            return readTree(reader);
        } catch (XMLStreamException e) {
            throw malformed(e);
        } finally {
            SecureXml.close(reader);
        }
    }

    private XodeElement readTree(XMLStreamReader reader) throws XMLStreamException, XodeException {
        Deque<XodeElement> open = new ArrayDeque<>();
        XodeElement root = null;
        while (reader.hasNext()) {
            int event = reader.next();
            if (event == XMLStreamConstants.START_ELEMENT) {
                XodeElement element = new XodeElement(qualifiedName(reader), locationOf(reader.getLocation()));
                if (open.size() == DEEPEST) {
                    throw new XodeException(List.of(new XodeProblem(Severity.ERROR, element.location(),
                            element.name(), String.format("elements nested more than %,d deep: masl loads at most %,d"
                                    + " levels", DEEPEST, DEEPEST))));
                }
                for (int i = 0; i < reader.getAttributeCount(); i++) {
                    // xsi:… and other namespaced attributes are schema hints, not XODE data.
                    if (reader.getAttributeNamespace(i) == null || reader.getAttributeNamespace(i).isEmpty()) {
                        element.putAttribute(reader.getAttributeLocalName(i), reader.getAttributeValue(i));
                    }
                }
                if (open.isEmpty()) {
                    root = element;
                } else {
                    open.peek().addChild(element);
                }
                open.push(element);
            } else if (event == XMLStreamConstants.END_ELEMENT) {
                open.pop();
            }
        }
        if (root == null) {
            throw new XodeException(List.of(new XodeProblem(Severity.ERROR,
                    new SourceLocation(fileName, 1, 1), "", "the file holds no XML element")));
        }
        return root;
    }

    private static String qualifiedName(XMLStreamReader reader) {
        String prefix = reader.getPrefix();
        return prefix == null || prefix.isEmpty() ? reader.getLocalName() : prefix + ":" + reader.getLocalName();
    }

    private SourceLocation locationOf(Location location) {
        return new SourceLocation(fileName, Math.max(1, location.getLineNumber()), Math.max(1, location.getColumnNumber()));
    }

    private XodeException malformed(XMLStreamException e) {
        SourceLocation where = new SourceLocation(fileName, Math.max(1, SecureXml.lineOf(e)), Math.max(1, SecureXml.columnOf(e)));
        return new XodeException(List.of(new XodeProblem(Severity.ERROR, where, "",
                "malformed XML: " + SecureXml.messageOf(e))));
    }
}
