package org.jecosys.bench;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * One report table: an id (e.g. "table2"), a title, column headers, rows of cells, and notes. It
 * renders as Markdown and as a JSON-ready map. Built by one thread.
 */
public final class Table {
    private final String id;
    private final String title;
    private final List<String> headers;
    private final List<List<Object>> rows = new ArrayList<>();
    private final List<String> notes = new ArrayList<>();

    public Table(String id, String title, List<String> headers) {
        this.id = id;
        this.title = title;
        this.headers = List.copyOf(headers);
    }

    /** Adds a row; its size must match the headers. */
    public Table row(Object... cells) {
        if (cells.length != headers.size()) {
            throw new IllegalArgumentException("table " + id + " has " + headers.size() + " columns, row has "
                    + cells.length);
        }
        rows.add(java.util.Arrays.asList(cells));
        return this;
    }

    /** Adds a note printed under the table. */
    public Table note(String text) {
        notes.add(text);
        return this;
    }

    public String id() {
        return id;
    }

    public String title() {
        return title;
    }

    public List<String> headers() {
        return headers;
    }

    public List<List<Object>> rows() {
        return rows;
    }

    public List<String> notes() {
        return notes;
    }

    /** The table as Markdown. */
    public String toMarkdown() {
        StringBuilder sb = new StringBuilder("### ").append(title).append("\n\n|");
        for (String h : headers) {
            sb.append(' ').append(h).append(" |");
        }
        sb.append("\n|");
        for (int i = 0; i < headers.size(); i++) {
            sb.append(i == 0 ? "---|" : "---:|");
        }
        sb.append('\n');
        for (List<Object> r : rows) {
            sb.append('|');
            for (Object c : r) {
                sb.append(' ').append(cell(c)).append(" |");
            }
            sb.append('\n');
        }
        for (String n : notes) {
            sb.append('\n').append(n).append('\n');
        }
        return sb.append('\n').toString();
    }

    /** The table as a JSON-ready map: title, headers, rows of objects keyed by header, notes. */
    public Map<String, Object> toMap() {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("title", title);
        List<Object> out = new ArrayList<>();
        for (List<Object> r : rows) {
            Map<String, Object> o = new LinkedHashMap<>();
            for (int i = 0; i < headers.size(); i++) {
                o.put(headers.get(i), r.get(i));
            }
            out.add(o);
        }
        m.put("rows", out);
        m.put("notes", notes);
        return m;
    }

    /** A cell as text: numbers with sensible precision. */
    static String cell(Object c) {
        if (c == null) {
            return "-";
        }
        if (c instanceof Double || c instanceof Float) {
            double d = ((Number) c).doubleValue();
            if (!Double.isFinite(d)) {
                return "-";
            }
            double a = Math.abs(d);
            if (a >= 1000 || d == Math.rint(d)) {
                return String.format(java.util.Locale.ROOT, "%,.0f", d);
            }
            return String.format(java.util.Locale.ROOT, a >= 10 ? "%.1f" : a >= 0.1 ? "%.2f" : "%.3g", d);
        }
        if (c instanceof Integer || c instanceof Long) {
            return String.format(java.util.Locale.ROOT, "%,d", ((Number) c).longValue());
        }
        return c.toString();
    }
}
