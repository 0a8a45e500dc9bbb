package org.jecosys.scene;

import com.fasterxml.jackson.dataformat.xml.XmlFactory;
import java.io.StringReader;
import java.util.ArrayDeque;
import java.util.Deque;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.xml.XMLConstants;
import javax.xml.stream.Location;
import javax.xml.stream.XMLInputFactory;
import javax.xml.stream.XMLStreamConstants;
import javax.xml.stream.XMLStreamException;
import javax.xml.stream.XMLStreamReader;

/**
 * Reads scene XML into a located {@link XmlNode} tree through Jackson XML's own input factory
 * (Woodstox with Jackson's hardening: no DTD support, no external entities). We never pass a
 * factory of our own, and on top of that any DOCTYPE is rejected at once, so no entity is ever
 * declared, expanded or fetched (XXE, billion laughs). Text content is not part of the format and
 * is rejected. Any thread; one instance per call.
 *
 * <p>Reading is bounded in elements and in memory at any heap: the parser streams, and the reader
 * stops at the element that crosses {@link #MAX_ELEMENTS}, {@link #MAX_ATTRIBUTES}, or the heap this
 * JVM lets a scene's reading take (the tree and what the checks and binding build from it, estimated
 * per element and attribute as they arrive), with a located problem naming the limit. Nesting depth,
 * attributes per element and attribute length are bounded by the parser's own limits (1,000 levels,
 * 1,000 attributes, 512 KiB), reported with a location too. Finding an attribute's line and column
 * scans its start tag once, so a tag with many attributes costs linear time.
 */
final class XmlReader {
    /**
     * Most elements in one scene file. The schema's own counts allow at most 276,638 (256 flows, each
     * with a path of 1,024 waypoints, beside every other maximum), so no valid scene is refused by
     * this limit; the shipped scenes have 18 to 62.
     */
    static final int MAX_ELEMENTS = 300_000;
    /**
     * Most attributes in one scene file, all elements together. The schema allows at most 627,025
     * (every attribute of every element at the element counts' maxima); the shipped scenes have 68 to about
     * 450 (xsi attributes included).
     */
    static final int MAX_ATTRIBUTES = 700_000;
    /**
     * Heap bytes per element while a scene is read, checked and bound, attributes aside: its located
     * node, its checked values and its share of the Defs. Measured: 136 for an unknown element (node
     * only), 255 for a known one; rounded up.
     */
    static final long BYTES_PER_ELEMENT = 300;
    /**
     * Heap bytes per attribute beyond its value's characters: located name, value, checked value and
     * the entries holding them. Measured: 128 for an unknown attribute, 190 to 290 for known ones
     * (waypoints 286 with their few characters); rounded up.
     */
    static final long BYTES_PER_ATTRIBUTE = 300;
    /** Heap bytes per character of the text and of each attribute value (a UTF-16 string at worst). */
    static final long BYTES_PER_CHAR = 2;

    /** One factory, built and hardened by Jackson; XMLInputFactory is thread-safe once configured. */
    private static final XMLInputFactory FACTORY = new XmlFactory().getXMLInputFactory();
    private static final String XSI = XMLConstants.W3C_XML_SCHEMA_INSTANCE_NS_URI;
    /** The parser's limits: nesting depth (group 1 set) or attributes per element, with the limit (group 2). */
    private static final Pattern LIMIT = Pattern.compile("(?i)(?:(Maximum Element Depth)|Attribute) limit \\((\\d+)\\)");

    private final String file;
    private final String text;
    private final long heap;
    /** Heap bytes the file's bytes and text take while it is read. */
    private final long textBytes;
    /** Heap bytes reading may take beyond the text: a share of the heap, less the program's own. */
    private final long budget;
    private int elements;
    private long attributes;
    /** Estimated heap bytes of what was read so far, text excluded. */
    private long used;

    /**
     * A reader of one document.
     *
     * @param file      the name every problem is reported under
     * @param text      the whole document
     * @param fileBytes bytes of the file, held by the caller while it is read
     * @param heap      the Java heap, bytes ({@code Runtime.maxMemory}): bounds what reading may take
     */
    XmlReader(String file, String text, long fileBytes, long heap) {
        this.file = file;
        this.text = text;
        this.heap = heap;
        this.textBytes = fileBytes + BYTES_PER_CHAR * text.length();
        this.budget = (long) (heap * SceneBudget.HEAP_SHARE) - SceneBudget.BASELINE_BYTES - textBytes;
    }

    /** Parses the whole document; the root element is returned. */
    XmlNode read() throws SceneLoadException {
        XMLStreamReader r = null;
        try {
            r = FACTORY.createXMLStreamReader(new StringReader(text));
            Deque<XmlNode> stack = new ArrayDeque<>();
            XmlNode root = null;
            while (r.hasNext()) {
                int ev = r.next();
                switch (ev) {
                    case XMLStreamConstants.DTD -> throw problem(r.getLocation(),
                            "DOCTYPE is not allowed in scene files (no DTDs or entities are read)");
                    case XMLStreamConstants.ENTITY_REFERENCE -> throw problem(r.getLocation(),
                            "entity reference &" + r.getLocalName() + "; is not allowed");
                    case XMLStreamConstants.START_ELEMENT -> {
                        countElement(r);
                        XmlNode n = startElement(r);
                        charge(r, n);
                        if (stack.isEmpty()) {
                            root = n;
                        } else {
                            stack.peek().children.add(n);
                        }
                        stack.push(n);
                    }
                    case XMLStreamConstants.END_ELEMENT -> stack.pop();
                    case XMLStreamConstants.CHARACTERS, XMLStreamConstants.CDATA -> {
                        if (!r.isWhiteSpace() && !r.getText().isBlank()) {
                            String where = stack.isEmpty() ? "outside the root element" : "inside <" + stack.peek().name + ">";
                            throw problem(r.getLocation(), "unexpected text '" + abbreviate(r.getText().strip())
                                    + "' " + where + "; the scene format uses attributes only");
                        }
                    }
                    default -> {
                        // comments, processing instructions, whitespace, document end
                    }
                }
            }
            if (root == null) {
                throw new SceneLoadException(new SceneProblem(file, 1, 1, "no root element; expected <scene version=\"1\">"));
            }
            return root;
        } catch (XMLStreamException e) {
            throw parserProblem(e, r);
        } finally {
            if (r != null) {
                try {
                    r.close();
                } catch (XMLStreamException ignored) {
                    // nothing to release beyond the in-memory reader
                }
            }
        }
    }

    /**
     * Counts the element the reader is at against the limits on elements and attributes before
     * anything of it is kept, and refuses it, located, when it crosses one: reading stops there.
     */
    private void countElement(XMLStreamReader r) throws SceneLoadException {
        elements++;
        attributes += r.getAttributeCount();
        if (elements > MAX_ELEMENTS) {
            throw problem(r.getLocation(), tag(r) + "more than " + SceneBudget.count(MAX_ELEMENTS)
                    + " elements in one scene file (the limit; no valid scene has more); reading stopped here");
        }
        if (attributes > MAX_ATTRIBUTES) {
            throw problem(r.getLocation(), tag(r) + "more than " + SceneBudget.count(MAX_ATTRIBUTES)
                    + " attributes in one scene file, all elements together (the limit; no valid scene has more); "
                    + "reading stopped here");
        }
    }

    /**
     * Adds what the element just read will take, kept, checked and bound, to the estimate, and
     * refuses it, located, when the estimate passes what this heap allows: reading stops there.
     */
    private void charge(XMLStreamReader r, XmlNode n) throws SceneLoadException {
        long valueChars = 0;
        for (XmlNode.Attr a : n.attrs.values()) {
            valueChars += a.value().length();
        }
        used += BYTES_PER_ELEMENT + r.getAttributeCount() * BYTES_PER_ATTRIBUTE + valueChars * BYTES_PER_CHAR;
        if (used <= budget) {
            return;
        }
        long allowed = Math.max(0, (long) (heap * SceneBudget.HEAP_SHARE) - SceneBudget.BASELINE_BYTES);
        throw problem(r.getLocation(), tag(r) + "reading stopped at element " + SceneBudget.count(elements)
                + " (with " + SceneBudget.count(attributes) + (attributes == 1 ? " attribute" : " attributes")
                + " so far): the file's text (" + SceneBudget.bytes(textBytes) + ") and its elements so far ("
                + SceneBudget.bytes(used) + ") need more memory to read and check than the " + SceneBudget.bytes(allowed)
                + " a scene may use here (" + Math.round(SceneBudget.HEAP_SHARE * 100) + "% of the Java heap of "
                + SceneBudget.bytes(heap) + ", Runtime.maxMemory, less " + SceneBudget.bytes(SceneBudget.BASELINE_BYTES)
                + " for the program; set with -Xmx); whatever the heap, a scene file holds at most "
                + SceneBudget.count(MAX_ELEMENTS) + " elements");
    }

    private static String tag(XMLStreamReader r) {
        return "<" + qualified(r.getPrefix(), r.getLocalName()) + ">: ";
    }

    private XmlNode startElement(XMLStreamReader r) throws SceneLoadException {
        Location loc = r.getLocation();
        String ns = r.getNamespaceURI();
        if (ns != null && !ns.isEmpty()) {
            throw problem(loc, "element <" + qualified(r.getPrefix(), r.getLocalName()) + "> is in namespace '" + ns
                    + "'; scene elements have no namespace");
        }
        XmlNode n = new XmlNode(r.getLocalName(), loc.getLineNumber(), loc.getColumnNumber());
        TagScan tag = new TagScan(loc);
        for (int i = 0; i < r.getAttributeCount(); i++) {
            String ans = r.getAttributeNamespace(i);
            String local = r.getAttributeLocalName(i);
            if (XSI.equals(ans)) {
                continue; // xsi:noNamespaceSchemaLocation and friends, for schema-aware editors
            }
            String name = qualified(r.getAttributePrefix(i), local);
            boolean found = tag.find(name);
            if (!found) {
                tag = new TagScan(loc); // not after the previous one: look from the tag's start
                found = tag.find(name);
            }
            int line = found ? tag.line : n.line;
            int col = found ? tag.column : n.column;
            if (ans != null && !ans.isEmpty()) {
                throw new SceneLoadException(new SceneProblem(file, line, col, "attribute '" + name + "' of <" + n.name
                        + "> is in namespace '" + ans + "'; scene attributes have no namespace"));
            }
            n.attrs.put(local, new XmlNode.Attr(local, r.getAttributeValue(i), line, col));
        }
        return n;
    }

    /** The parser's own failure as a located problem: its limits named, malformed XML quoted. */
    private SceneLoadException parserProblem(XMLStreamException e, XMLStreamReader r) {
        Location loc = e.getLocation();
        if (loc == null || loc.getLineNumber() < 1) {
            // the parser's own limits (nesting depth, attributes per element) carry no location:
            // report where the reader stopped
            loc = r == null ? null : r.getLocation();
        }
        String m = cleanMessage(e);
        Matcher limit = LIMIT.matcher(m);
        if (!limit.find()) {
            return problem(loc, "malformed XML: " + m);
        }
        int n = Integer.parseInt(limit.group(2));
        if (limit.group(1) != null) {
            return problem(loc, "elements are nested more than " + n + " levels deep (the limit)");
        }
        String message = "more than " + n + " attributes on one element (the limit)";
        if (loc != null) {
            TagScan tag = new TagScan(loc);
            for (int k = 0; k <= n && tag.next(); k++) {
                if (k == n) {
                    return new SceneLoadException(new SceneProblem(file, tag.line, tag.column, message));
                }
            }
        }
        return problem(loc, message);
    }

    /**
     * Walks the attribute names of the start tag at a location, in document order, scanning names
     * and quoted values once and counting lines on the way, so that each attribute is found where
     * its name starts. Attributes come from the parser in document order, so finding them one after
     * another costs one pass over the tag. Positions fall back to the element's when the location
     * is not a start tag.
     */
    private final class TagScan {
        /** Next character to scan; past the end when the location is not a start tag. */
        private int i;
        /** Offset of the first character of the current line (may be before the text for column 1). */
        private int lineStart;
        private int currentLine;
        /** The last attribute name found: its line and 1-based column, start and end offsets. */
        int line;
        int column;
        private int nameStart;
        private int nameEnd;

        TagScan(Location loc) {
            int start = loc.getCharacterOffset();
            if (start < 0 || start >= text.length() || text.charAt(start) != '<' || loc.getLineNumber() < 1) {
                i = text.length();
                return;
            }
            currentLine = loc.getLineNumber();
            lineStart = start - (Math.max(loc.getColumnNumber(), 1) - 1);
            i = start + 1;
            while (i < text.length() && !isSpace(text.charAt(i)) && text.charAt(i) != '>' && text.charAt(i) != '/') {
                i++;
            }
        }

        /** Moves to the next attribute name of the tag; false at the tag's end. */
        boolean next() {
            int n = text.length();
            skipSpace();
            if (i >= n || text.charAt(i) == '>' || text.charAt(i) == '/') {
                i = n;
                return false;
            }
            nameStart = i;
            line = currentLine;
            column = i - lineStart + 1;
            while (i < n && !isSpace(text.charAt(i)) && text.charAt(i) != '=' && text.charAt(i) != '>') {
                i++;
            }
            nameEnd = i;
            skipSpace();
            if (i < n && text.charAt(i) == '=') {
                i++;
            }
            skipSpace();
            if (i < n && (text.charAt(i) == '"' || text.charAt(i) == '\'')) {
                char q = text.charAt(i++);
                while (i < n && text.charAt(i) != q) {
                    newline();
                    i++;
                }
                i++;
            }
            return true;
        }

        /** Moves to the next attribute called {@code name}; false (and the tag scanned) if none follows. */
        boolean find(String name) {
            while (next()) {
                if (nameEnd - nameStart == name.length() && text.startsWith(name, nameStart)) {
                    return true;
                }
            }
            return false;
        }

        private void skipSpace() {
            while (i < text.length() && isSpace(text.charAt(i))) {
                newline();
                i++;
            }
        }

        private void newline() {
            if (text.charAt(i) == '\n') {
                currentLine++;
                lineStart = i + 1;
            }
        }
    }

    private static String qualified(String prefix, String local) {
        return prefix == null || prefix.isEmpty() ? local : prefix + ":" + local;
    }

    private static boolean isSpace(char c) {
        return c == ' ' || c == '\t' || c == '\n' || c == '\r';
    }

    private SceneLoadException problem(Location loc, String message) {
        int line = loc == null ? 0 : Math.max(loc.getLineNumber(), 1);
        int col = loc == null ? 0 : Math.max(loc.getColumnNumber(), 1);
        return new SceneLoadException(new SceneProblem(file, line, col, message));
    }

    /** Woodstox messages carry their own location suffix; keep only the sentence. */
    private static String cleanMessage(XMLStreamException e) {
        String m = e.getMessage() == null ? e.getClass().getSimpleName() : e.getMessage();
        int cut = m.indexOf("\n at [");
        if (cut >= 0) {
            m = m.substring(0, cut);
        }
        m = m.replace('\n', ' ').strip();
        if (m.startsWith("ParseError at [")) {
            int msgAt = m.indexOf("Message: ");
            if (msgAt >= 0) {
                m = m.substring(msgAt + 9);
            }
        }
        return m;
    }

    private static String abbreviate(String s) {
        return s.length() <= 40 ? s : s.substring(0, 37) + "...";
    }
}
