package org.jecosys.scene;

import com.fasterxml.jackson.dataformat.xml.XmlFactory;
import java.io.StringReader;
import java.util.ArrayDeque;
import java.util.Deque;
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
 */
final class XmlReader {
    /** One factory, built and hardened by Jackson; XMLInputFactory is thread-safe once configured. */
    private static final XMLInputFactory FACTORY = new XmlFactory().getXMLInputFactory();
    private static final String XSI = XMLConstants.W3C_XML_SCHEMA_INSTANCE_NS_URI;
    /** The parser's limits: nesting depth (group 1 set) or attributes per element, with the limit (group 2). */
    private static final java.util.regex.Pattern LIMIT = java.util.regex.Pattern.compile(
            "(?i)(?:(Maximum Element Depth)|Attribute) limit \\((\\d+)\\)");

    private final String file;
    private final String text;
    private final int[] lineStarts;

    XmlReader(String file, String text) {
        this.file = file;
        this.text = text;
        this.lineStarts = lineStarts(text);
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
                        XmlNode n = startElement(r);
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
            Location loc = e.getLocation();
            if (loc == null || loc.getLineNumber() < 1) {
                // the parser's own limits (nesting depth, attributes per element) carry no location:
                // report where the reader stopped
                loc = r == null ? null : r.getLocation();
            }
            String m = cleanMessage(e);
            java.util.regex.Matcher limit = LIMIT.matcher(m);
            if (limit.find()) {
                int n = Integer.parseInt(limit.group(2));
                if (limit.group(1) != null) {
                    throw problem(loc, "elements are nested more than " + n + " levels deep (the limit)");
                }
                int at = loc == null ? -1 : nthAttributeOffset(loc.getCharacterOffset(), n);
                if (at >= 0) {
                    int line = lineOf(at);
                    throw new SceneLoadException(new SceneProblem(file, line, at - lineStarts[line - 1] + 1,
                            "more than " + n + " attributes on one element (the limit)"));
                }
                throw problem(loc, "more than " + n + " attributes on one element (the limit)");
            }
            throw problem(loc, "malformed XML: " + m);
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

    private XmlNode startElement(XMLStreamReader r) throws SceneLoadException {
        Location loc = r.getLocation();
        String ns = r.getNamespaceURI();
        if (ns != null && !ns.isEmpty()) {
            throw problem(loc, "element <" + qualified(r.getPrefix(), r.getLocalName()) + "> is in namespace '" + ns
                    + "'; scene elements have no namespace");
        }
        XmlNode n = new XmlNode(r.getLocalName(), loc.getLineNumber(), loc.getColumnNumber());
        int offset = loc.getCharacterOffset();
        for (int i = 0; i < r.getAttributeCount(); i++) {
            String ans = r.getAttributeNamespace(i);
            String local = r.getAttributeLocalName(i);
            if (XSI.equals(ans)) {
                continue; // xsi:noNamespaceSchemaLocation and friends, for schema-aware editors
            }
            int at = attributeOffset(offset, qualified(r.getAttributePrefix(i), local));
            int line = at < 0 ? n.line : lineOf(at);
            int col = at < 0 ? n.column : at - lineStarts[line - 1] + 1;
            if (ans != null && !ans.isEmpty()) {
                throw new SceneLoadException(new SceneProblem(file, line, col, "attribute '"
                        + qualified(r.getAttributePrefix(i), local) + "' of <" + n.name
                        + "> is in namespace '" + ans + "'; scene attributes have no namespace"));
            }
            n.attrs.put(local, new XmlNode.Attr(local, r.getAttributeValue(i), line, col));
        }
        return n;
    }

    /**
     * The char offset of the attribute at index {@code n} (0-based) of the start tag beginning at
     * {@code tagStart}, scanning names and quoted values; -1 if the tag has no such attribute.
     */
    private int nthAttributeOffset(int tagStart, int n) {
        if (tagStart < 0 || tagStart >= text.length() || text.charAt(tagStart) != '<') {
            return -1;
        }
        int i = tagStart + 1;
        int len = text.length();
        while (i < len && !isSpace(text.charAt(i)) && text.charAt(i) != '>' && text.charAt(i) != '/') {
            i++;
        }
        for (int k = 0; i < len; k++) {
            while (i < len && isSpace(text.charAt(i))) {
                i++;
            }
            if (i >= len || text.charAt(i) == '>' || text.charAt(i) == '/') {
                return -1;
            }
            if (k == n) {
                return i;
            }
            while (i < len && text.charAt(i) != '"' && text.charAt(i) != '\'' && text.charAt(i) != '>') {
                i++;
            }
            if (i < len && text.charAt(i) != '>') {
                char q = text.charAt(i++);
                while (i < len && text.charAt(i) != q) {
                    i++;
                }
                i++;
            }
        }
        return -1;
    }

    private static String qualified(String prefix, String local) {
        return prefix == null || prefix.isEmpty() ? local : prefix + ":" + local;
    }

    /**
     * The char offset of attribute {@code name} inside the start tag beginning at {@code tagStart}
     * (the '&lt;'), scanning names and quoted values; -1 if not found.
     */
    private int attributeOffset(int tagStart, String name) {
        if (tagStart < 0 || tagStart >= text.length() || text.charAt(tagStart) != '<') {
            return -1;
        }
        int i = tagStart + 1;
        int n = text.length();
        while (i < n && !isSpace(text.charAt(i)) && text.charAt(i) != '>' && text.charAt(i) != '/') {
            i++;
        }
        while (i < n) {
            while (i < n && isSpace(text.charAt(i))) {
                i++;
            }
            if (i >= n || text.charAt(i) == '>' || text.charAt(i) == '/') {
                return -1;
            }
            int nameStart = i;
            while (i < n && !isSpace(text.charAt(i)) && text.charAt(i) != '=') {
                i++;
            }
            boolean match = text.startsWith(name, nameStart) && nameStart + name.length() == i;
            while (i < n && isSpace(text.charAt(i))) {
                i++;
            }
            if (i < n && text.charAt(i) == '=') {
                i++;
            }
            while (i < n && isSpace(text.charAt(i))) {
                i++;
            }
            if (i < n && (text.charAt(i) == '"' || text.charAt(i) == '\'')) {
                char q = text.charAt(i++);
                while (i < n && text.charAt(i) != q) {
                    i++;
                }
                i++;
            }
            if (match) {
                return nameStart;
            }
        }
        return -1;
    }

    private static boolean isSpace(char c) {
        return c == ' ' || c == '\t' || c == '\n' || c == '\r';
    }

    private int lineOf(int offset) {
        int lo = 0;
        int hi = lineStarts.length - 1;
        while (lo < hi) {
            int mid = (lo + hi + 1) >>> 1;
            if (lineStarts[mid] <= offset) {
                lo = mid;
            } else {
                hi = mid - 1;
            }
        }
        return lo + 1;
    }

    private static int[] lineStarts(String s) {
        int count = 1;
        for (int i = 0; i < s.length(); i++) {
            if (s.charAt(i) == '\n') {
                count++;
            }
        }
        int[] starts = new int[count];
        int k = 1;
        for (int i = 0; i < s.length(); i++) {
            if (s.charAt(i) == '\n') {
                starts[k++] = i + 1;
            }
        }
        return starts;
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
