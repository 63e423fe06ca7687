package masl.runtime.descriptor;

import java.io.FileNotFoundException;
import java.io.IOException;
import java.io.InputStream;
import java.net.URL;
import java.nio.ByteBuffer;
import java.nio.CharBuffer;
import java.nio.charset.CoderResult;
import java.nio.charset.StandardCharsets;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import javax.xml.XMLConstants;
import javax.xml.stream.Location;
import javax.xml.stream.XMLStreamConstants;
import javax.xml.stream.XMLStreamException;
import javax.xml.stream.XMLStreamReader;
import javax.xml.transform.stream.StreamSource;
import javax.xml.validation.Schema;
import javax.xml.validation.SchemaFactory;
import javax.xml.validation.ValidatorHandler;
import masl.runtime.diagnostic.Diagnostic;
import masl.runtime.xml.SecureXml;
import org.xml.sax.ErrorHandler;
import org.xml.sax.Locator;
import org.xml.sax.SAXException;
import org.xml.sax.SAXParseException;
import org.xml.sax.helpers.AttributesImpl;

/**
 * Reads a descriptor into an {@link XmlElement} tree and validates it against {@code agent-type.xsd} in
 * the same pass. Reading uses masl's one XML reader ({@link SecureXml}): no DTD is processed, nothing
 * is fetched and no entity is expanded. The validator is fed the reader's events directly, so its
 * errors carry the reader's positions and it never sees a DTD. Thread-safe.
 */
final class DescriptorReader {

    static final String SCHEMA_RESOURCE = "agent-type.xsd";

    /** The tree (null when the file is not well-formed or unreadable) and the problems found. */
    record Result(XmlElement root, List<Diagnostic> problems) {
    }

    private DescriptorReader() {
    }

    /** Compiled when first needed: a run whose descriptors were validated before never needs it. */
    private static final class Compiled {
        static final Schema SCHEMA = loadSchema();
    }

    static Result read(DescriptorSource source) {
        return read(source, true);
    }

    /**
     * Reads {@code source}; without {@code validate}, the schema is not checked: for a descriptor whose
     * bytes were validated before (see {@link DescriptorLoader#readingValidated}).
     */
    static Result read(DescriptorSource source, boolean validate) {
        List<Diagnostic> problems = new ArrayList<>();
        String file = source.displayName();
        try (InputStream in = source.open()) {
            XMLStreamReader reader = SecureXml.reader(source.uri().toString(), in);
            try {
                return new Result(readValidating(reader, file, problems, validate), problems);
            } finally {
                reader.close();
            }
        } catch (XMLStreamException e) {
            problems.add(notWellFormed(file, e, source));
        } catch (IOException e) {
            String reason = e instanceof FileNotFoundException ? "file not found" : "cannot read the descriptor: " + e;
            problems.add(Diagnostic.error(file, 0, 0, reason));
        } catch (SAXException e) {
            problems.add(Diagnostic.error(file, 0, 0, "schema validation failed: " + e.getMessage()));
        }
        return new Result(null, problems);
    }

    /** The {@code full_class_name} of the root element, or empty when unreadable or absent. */
    static Optional<String> peekFullClassName(DescriptorSource source) {
        try (InputStream in = source.open()) {
            XMLStreamReader reader = SecureXml.reader(source.uri().toString(), in);
            try {
                while (reader.hasNext()) {
                    if (reader.next() == XMLStreamConstants.START_ELEMENT) {
                        return Optional.ofNullable(reader.getAttributeValue(null, "full_class_name"));
                    }
                }
                return Optional.empty();
            } finally {
                reader.close();
            }
        } catch (XMLStreamException | IOException e) {
            // Not a descriptor we can use to find a supertype; reading it for real reports the error.
            return Optional.empty();
        }
    }

    private static XmlElement readValidating(XMLStreamReader reader, String file, List<Diagnostic> problems,
            boolean validate) throws XMLStreamException, SAXException {
        Deque<ElementBuilder> open = new ArrayDeque<>();
        ProblemCollector collector = new ProblemCollector(file, problems);
        ValidatorHandler validator = validate ? validator(reader, file, collector) : null;
        XmlElement root = null;
        while (reader.hasNext()) {
            switch (reader.next()) {
                case XMLStreamConstants.START_ELEMENT -> {
                    ElementBuilder element = ElementBuilder.start(reader);
                    collector.validating = element;
                    if (validator != null) {
                        validator.startElement(nonNull(reader.getNamespaceURI()), element.name, qualifiedName(reader),
                                saxAttributes(reader));
                    }
                    open.push(element);
                }
                case XMLStreamConstants.END_ELEMENT -> {
                    if (validator != null) {
                        validator.endElement(nonNull(reader.getNamespaceURI()), reader.getLocalName(),
                                qualifiedName(reader));
                    }
                    XmlElement done = open.pop().build();
                    if (open.isEmpty()) {
                        root = done;
                    } else {
                        open.peek().children.add(done);
                        collector.validating = open.peek();
                    }
                }
                case XMLStreamConstants.CHARACTERS, XMLStreamConstants.CDATA, XMLStreamConstants.SPACE -> {
                    collector.validating = open.peek();
                    if (validator != null) {
                        validator.characters(reader.getTextCharacters(), reader.getTextStart(), reader.getTextLength());
                    }
                }
                default -> {
                    // Comments, processing instructions and the ignored DOCTYPE mean nothing here.
                }
            }
        }
        if (validator != null) {
            validator.endDocument();
        }
        return root;
    }

    private static ValidatorHandler validator(XMLStreamReader reader, String file, ProblemCollector collector)
            throws SAXException {
        ValidatorHandler validator = Compiled.SCHEMA.newValidatorHandler();
        // Schema location hints (xsi:schemaLocation) must not make the validator fetch anything either.
        validator.setFeature(XMLConstants.FEATURE_SECURE_PROCESSING, true);
        validator.setProperty(XMLConstants.ACCESS_EXTERNAL_DTD, "");
        validator.setProperty(XMLConstants.ACCESS_EXTERNAL_SCHEMA, "");
        validator.setErrorHandler(collector);
        validator.setDocumentLocator(new ReaderLocator(reader, file));
        validator.startDocument();
        return validator;
    }

    /**
     * The parser's problem at its position; one it gives without a position (a byte sequence that is
     * not UTF-8, found by the decoder under the parser) is placed at the first such byte.
     */
    private static Diagnostic notWellFormed(String file, XMLStreamException e, DescriptorSource source) {
        int line = SecureXml.lineOf(e);
        int column = SecureXml.columnOf(e);
        if (line == 0) {
            int[] position = firstMalformedUtf8(source);
            line = position[0];
            column = position[1];
        }
        return Diagnostic.error(file, line, column, "not well-formed XML: " + SecureXml.messageOf(e));
    }

    /** Line and column (from 1) of the first byte of {@code source} that is not UTF-8, or of its start if none. */
    private static int[] firstMalformedUtf8(DescriptorSource source) {
        byte[] bytes;
        try (InputStream in = source.open()) {
            bytes = in.readAllBytes();
        } catch (IOException unreadable) {
            return new int[] {1, 1};
        }
        ByteBuffer input = ByteBuffer.wrap(bytes);
        CoderResult result = StandardCharsets.UTF_8.newDecoder()
                .decode(input, CharBuffer.allocate(bytes.length), true);
        if (!result.isError()) {
            return new int[] {1, 1};
        }
        int bad = input.position();
        int line = 1;
        int lineStart = 0;
        for (int i = 0; i < bad; i++) {
            if (bytes[i] == '\n') {
                line++;
                lineStart = i + 1;
            }
        }
        return new int[] {line, new String(bytes, lineStart, bad - lineStart, StandardCharsets.UTF_8).length() + 1};
    }

    private static AttributesImpl saxAttributes(XMLStreamReader reader) {
        AttributesImpl sax = new AttributesImpl();
        for (int i = 0; i < reader.getAttributeCount(); i++) {
            String prefix = nonNull(reader.getAttributePrefix(i));
            String localName = reader.getAttributeLocalName(i);
            sax.addAttribute(nonNull(reader.getAttributeNamespace(i)), localName,
                    prefix.isEmpty() ? localName : prefix + ":" + localName, "CDATA", reader.getAttributeValue(i));
        }
        return sax;
    }

    private static String qualifiedName(XMLStreamReader reader) {
        String prefix = nonNull(reader.getPrefix());
        return prefix.isEmpty() ? reader.getLocalName() : prefix + ":" + reader.getLocalName();
    }

    private static String nonNull(String namespace) {
        return namespace == null ? "" : namespace;
    }

    private static Schema loadSchema() {
        URL schema = DescriptorReader.class.getResource(SCHEMA_RESOURCE);
        if (schema == null) {
            throw new IllegalStateException("resource " + SCHEMA_RESOURCE + " is missing from masl-runtime");
        }
        try {
            // The JDK's own factory, not whichever one the class path provides: an old Xerces (Gradle's
            // own jars, in the plug-in's tests and builds) rejects the secure-processing properties.
            SchemaFactory factory = SchemaFactory.newDefaultInstance();
            factory.setFeature(XMLConstants.FEATURE_SECURE_PROCESSING, true);
            factory.setProperty(XMLConstants.ACCESS_EXTERNAL_DTD, "");
            factory.setProperty(XMLConstants.ACCESS_EXTERNAL_SCHEMA, "");
            return factory.newSchema(new StreamSource(schema.toString()));
        } catch (SAXException e) {
            throw new IllegalStateException("the shipped " + SCHEMA_RESOURCE + " is invalid", e);
        }
    }

    /** An element being read: its children arrive before it is complete. */
    private static final class ElementBuilder {
        final String name;
        final Map<String, String> attributes = new LinkedHashMap<>();
        final List<XmlElement> children = new ArrayList<>();
        final int line;
        final int column;

        private ElementBuilder(String name, int line, int column) {
            this.name = name;
            this.line = line;
            this.column = column;
        }

        static ElementBuilder start(XMLStreamReader reader) {
            Location location = reader.getLocation();
            ElementBuilder element = new ElementBuilder(reader.getLocalName(), location.getLineNumber(),
                    location.getColumnNumber());
            // Descriptor attributes have no namespace; others (xsi:…) only concern the validator.
            for (int i = 0; i < reader.getAttributeCount(); i++) {
                if (nonNull(reader.getAttributeNamespace(i)).isEmpty()) {
                    element.attributes.put(reader.getAttributeLocalName(i), reader.getAttributeValue(i));
                }
            }
            return element;
        }

        XmlElement build() {
            return new XmlElement(name, attributes, children, line, column);
        }
    }

    /** Tells the validator where the reader is, so its errors carry the element's position. */
    private record ReaderLocator(XMLStreamReader reader, String file) implements Locator {
        @Override
        public String getPublicId() {
            return null;
        }

        @Override
        public String getSystemId() {
            return file;
        }

        @Override
        public int getLineNumber() {
            return reader.getLocation().getLineNumber();
        }

        @Override
        public int getColumnNumber() {
            return reader.getLocation().getColumnNumber();
        }
    }

    /** Collects every validation error (validation goes on after one) as a rephrased problem. */
    private static final class ProblemCollector implements ErrorHandler {
        private final String file;
        private final List<Diagnostic> problems;
        /** The element the validator is at: being started, holding text, or just completed. */
        ElementBuilder validating;

        ProblemCollector(String file, List<Diagnostic> problems) {
            this.file = file;
            this.problems = problems;
        }

        @Override
        public void warning(SAXParseException exception) {
            // Schema warnings do not make a descriptor invalid.
        }

        @Override
        public void error(SAXParseException exception) {
            String message = String.valueOf(exception.getMessage());
            if (SchemaMessages.isFacetError(message)) {
                return;
            }
            String element = validating == null ? "" : validating.name;
            Map<String, String> attributes = validating == null ? Map.of() : validating.attributes;
            problems.add(Diagnostic.error(file, Math.max(exception.getLineNumber(), 1),
                    Math.max(exception.getColumnNumber(), 1), SchemaMessages.rephrase(message, element, attributes)));
        }

        @Override
        public void fatalError(SAXParseException exception) {
            error(exception);
        }
    }
}
