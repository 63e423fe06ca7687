package masl.runtime.xml;

import com.ctc.wstx.api.WstxInputProperties;
import com.ctc.wstx.stax.WstxInputFactory;
import java.io.InputStream;
import java.io.Reader;
import javax.xml.stream.Location;
import javax.xml.stream.XMLInputFactory;
import javax.xml.stream.XMLStreamException;
import javax.xml.stream.XMLStreamReader;
import org.codehaus.stax2.XMLInputFactory2;

/**
 * The one way masl reads XML: agent type descriptors, XODE scenes and scenario files alike. The
 * reader never fetches and never expands: no DTD is processed (a {@code <!DOCTYPE … SYSTEM "…">}
 * line is skipped unread), an external entity or resource is never loaded, and a reference to an
 * entity the document declares is an error instead of a file read or an expansion.
 *
 * <p>Woodstox's factory is made directly, not looked up: {@code XMLInputFactory.newFactory()}
 * searches the system properties, {@code jaxp.properties} and every jar's
 * {@code META-INF/services} (35–40 ms of a {@code masl run} from the cache), and might find another
 * parser on a build tool's class path, whose security settings and reported positions differ.
 * At a start tag, the reader's location is where the element begins (its {@code <}).
 *
 * <p>Thread-safe: the factory is configured once and only creates readers afterwards.
 */
public final class SecureXml {

    /**
     * The deepest nesting of elements a reader of masl's formats accepts: their walks recurse into
     * nested elements, and a scene or a descriptor needs a few levels, not thousands.
     */
    public static final int DEEPEST = 10_000;

    private static final XMLInputFactory FACTORY = secureFactory();

    private SecureXml() {
    }

    /** A reader of {@code in}; {@code systemId} names the document in the parser's own messages. */
    public static XMLStreamReader reader(String systemId, InputStream in) throws XMLStreamException {
        return FACTORY.createXMLStreamReader(systemId, in);
    }

    /** A reader of the characters of {@code in}. */
    public static XMLStreamReader reader(String systemId, Reader in) throws XMLStreamException {
        return FACTORY.createXMLStreamReader(systemId, in);
    }

    /**
     * The parser's message without the position it appends ({@code "\n at [row,col …]"}): the
     * position has fields of its own, {@link #lineOf} and {@link #columnOf}.
     */
    public static String messageOf(XMLStreamException e) {
        String message = String.valueOf(e.getMessage());
        int positionSuffix = message.indexOf("\n at [");
        return (positionSuffix >= 0 ? message.substring(0, positionSuffix) : message).strip();
    }

    /** The 1-based line of the problem, or 0 when the parser gave none. */
    public static int lineOf(XMLStreamException e) {
        Location location = e.getLocation();
        return location == null ? 0 : Math.max(location.getLineNumber(), 0);
    }

    /** The 1-based column of the problem; at the end of the input the parser may give 0: the line's start. */
    public static int columnOf(XMLStreamException e) {
        Location location = e.getLocation();
        return location == null ? 0 : Math.max(location.getColumnNumber(), 1);
    }

    /** Quietly closes a reader over in-memory or already read input: closing loses no data. */
    public static void close(XMLStreamReader reader) {
        if (reader == null) {
            return;
        }
        try {
            reader.close();
        } catch (XMLStreamException ignored) {
            // The parse result stands; nothing is buffered for writing.
        }
    }

    private static XMLInputFactory secureFactory() {
        XMLInputFactory factory = new WstxInputFactory();
        factory.setProperty(XMLInputFactory.SUPPORT_DTD, false);
        factory.setProperty(XMLInputFactory.IS_SUPPORTING_EXTERNAL_ENTITIES, false);
        factory.setProperty(XMLInputFactory.IS_NAMESPACE_AWARE, true);
        factory.setProperty(XMLInputFactory.IS_COALESCING, true);
        // Woodstox stops at 1,000 levels by default; the formats' own readers report DEEPEST themselves.
        factory.setProperty(WstxInputProperties.P_MAX_ELEMENT_DEPTH, DEEPEST + 1);
        if (factory.isPropertySupported(XMLInputFactory2.P_LAZY_PARSING)) {
            // Errors then surface from next(), where readers catch them, not later from getText().
            factory.setProperty(XMLInputFactory2.P_LAZY_PARSING, false);
        }
        factory.setXMLResolver((publicId, systemId, baseUri, namespace) -> {
            throw new XMLStreamException("external resource " + systemId + " is not loaded");
        });
        return factory;
    }
}
