package masl.sim.xode;

import java.io.StringReader;
import java.util.ArrayDeque;
import java.util.Deque;
import java.util.List;
import javax.xml.XMLConstants;
import javax.xml.stream.Location;
import javax.xml.stream.XMLInputFactory;
import javax.xml.stream.XMLStreamConstants;
import javax.xml.stream.XMLStreamException;
import javax.xml.stream.XMLStreamReader;

/**
 * Reads XML text into a tree of {@link XodeElement}s with a StAX parser that never fetches a DTD
 * and never expands an external entity: a {@code <!DOCTYPE … SYSTEM "http://…">} line is skipped
 * unread, and a reference to an entity the document declares is an error instead of a file read.
 *
 * <p>The JDK's own StAX implementation is used on purpose (not whatever the class path offers),
 * so security settings and reported columns do not change when another parser is on the path.
 */
public final class SecureXmlReader {

    /**
     * The deepest nesting of elements read: the loader's walks recurse into nested elements (on a
     * deep stack, {@link XodeLoader}), and a scene needs a few levels, not thousands.
     */
    public static final int DEEPEST = 10_000;

    private final String fileName;
    private final String text;
    private final int[] lineStarts;

    /** @param fileName name used in locations; @param text the whole document */
    public SecureXmlReader(String fileName, String text) {
        this.fileName = fileName;
        this.text = text;
        this.lineStarts = lineStarts(text);
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
            reader = secureFactory().createXMLStreamReader(new StringReader(text));
            return readTree(reader);
        } catch (XMLStreamException e) {
            throw malformed(e);
        } finally {
            close(reader);
        }
    }

    private XodeElement readTree(XMLStreamReader reader) throws XMLStreamException, XodeException {
        Deque<XodeElement> open = new ArrayDeque<>();
        XodeElement root = null;
        while (reader.hasNext()) {
            int event = reader.next();
            if (event == XMLStreamConstants.START_ELEMENT) {
                XodeElement element = new XodeElement(qualifiedName(reader), elementStart(reader.getLocation()));
                if (open.size() == DEEPEST) {
                    throw new XodeException(List.of(new XodeProblem(XodeProblem.Severity.ERROR, element.location(),
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
            throw new XodeException(List.of(new XodeProblem(XodeProblem.Severity.ERROR,
                    new SourceLocation(fileName, 1, 1), "", "the file holds no XML element")));
        }
        return root;
    }

    private static String qualifiedName(XMLStreamReader reader) {
        String prefix = reader.getPrefix();
        return prefix == null || prefix.isEmpty() ? reader.getLocalName() : prefix + ":" + reader.getLocalName();
    }

    private static XMLInputFactory secureFactory() {
        XMLInputFactory factory = XMLInputFactory.newDefaultFactory();
        factory.setProperty(XMLInputFactory.SUPPORT_DTD, false);
        factory.setProperty(XMLInputFactory.IS_SUPPORTING_EXTERNAL_ENTITIES, false);
        factory.setProperty(XMLConstants.ACCESS_EXTERNAL_DTD, "");
        factory.setProperty(XMLInputFactory.IS_NAMESPACE_AWARE, true);
        factory.setXMLResolver((publicId, systemId, baseUri, namespace) -> {
            throw new XMLStreamException("external resources are never loaded: " + systemId);
        });
        return factory;
    }

    /**
     * StAX reports a start tag's position after its closing {@code >}; a person wants where the
     * element begins, which is the last {@code <} before that point (attribute values cannot hold
     * a raw {@code <}).
     */
    private SourceLocation elementStart(Location endOfTag) {
        int offset = offsetOf(endOfTag.getLineNumber(), endOfTag.getColumnNumber());
        int start = text.lastIndexOf('<', Math.max(0, offset - 1));
        return start < 0 ? locationOf(endOfTag) : locationAt(start);
    }

    private int offsetOf(int line, int column) {
        if (line < 1 || line > lineStarts.length) {
            return text.length();
        }
        return Math.min(text.length(), lineStarts[line - 1] + Math.max(0, column - 1));
    }

    private SourceLocation locationAt(int offset) {
        int line = 0;
        while (line + 1 < lineStarts.length && lineStarts[line + 1] <= offset) {
            line++;
        }
        return new SourceLocation(fileName, line + 1, offset - lineStarts[line] + 1);
    }

    private SourceLocation locationOf(Location location) {
        return new SourceLocation(fileName, Math.max(1, location.getLineNumber()), Math.max(1, location.getColumnNumber()));
    }

    private XodeException malformed(XMLStreamException e) {
        SourceLocation where = e.getLocation() == null ? new SourceLocation(fileName, 1, 1) : locationOf(e.getLocation());
        return new XodeException(List.of(new XodeProblem(XodeProblem.Severity.ERROR, where, "",
                "malformed XML: " + parserMessage(e))));
    }

    /** The JDK prefixes its message with "ParseError at [row,col]:[…]\nMessage: ", already in the location. */
    private static String parserMessage(XMLStreamException e) {
        String message = String.valueOf(e.getMessage());
        int marker = message.indexOf("Message: ");
        return marker >= 0 ? message.substring(marker + "Message: ".length()).trim() : message.trim();
    }

    private static int[] lineStarts(String text) {
        int count = 1;
        for (int i = 0; i < text.length(); i++) {
            if (text.charAt(i) == '\n') {
                count++;
            }
        }
        int[] starts = new int[count];
        int line = 1;
        for (int i = 0; i < text.length(); i++) {
            if (text.charAt(i) == '\n') {
                starts[line++] = i + 1;
            }
        }
        return starts;
    }

    private static void close(XMLStreamReader reader) {
        if (reader == null) {
            return;
        }
        try {
            reader.close();
        } catch (XMLStreamException ignored) {
            // Closing a reader over an in-memory string cannot lose data; the parse result stands.
        }
    }
}
