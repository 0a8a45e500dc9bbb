package org.jecosys.app;

/** A tiny JSON object writer for reports (flat keys and one level of nesting); not for arbitrary data. */
final class JsonWriter {
    private final StringBuilder sb = new StringBuilder();
    private int depth;
    private boolean first = true;

    JsonWriter begin() {
        sb.append('{');
        depth++;
        first = true;
        return this;
    }

    JsonWriter beginObject(String key) {
        key(key);
        sb.append('{');
        depth++;
        first = true;
        return this;
    }

    JsonWriter end() {
        depth--;
        sb.append('\n').append("  ".repeat(depth)).append('}');
        first = false;
        return this;
    }

    JsonWriter put(String key, String value) {
        key(key);
        quote(value);
        return this;
    }

    JsonWriter put(String key, long value) {
        key(key);
        sb.append(value);
        return this;
    }

    JsonWriter put(String key, double value) {
        key(key);
        sb.append(Double.isFinite(value) ? Double.toString(value) : "null");
        return this;
    }

    JsonWriter put(String key, boolean value) {
        key(key);
        sb.append(value);
        return this;
    }

    private void key(String key) {
        if (!first) {
            sb.append(',');
        }
        first = false;
        sb.append('\n').append("  ".repeat(depth));
        quote(key);
        sb.append(": ");
    }

    private void quote(String s) {
        sb.append('"');
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            switch (c) {
                case '"' -> sb.append("\\\"");
                case '\\' -> sb.append("\\\\");
                case '\n' -> sb.append("\\n");
                case '\r' -> sb.append("\\r");
                case '\t' -> sb.append("\\t");
                default -> {
                    if (c < 0x20) {
                        sb.append(String.format("\\u%04x", (int) c));
                    } else {
                        sb.append(c);
                    }
                }
            }
        }
        sb.append('"');
    }

    @Override
    public String toString() {
        return sb.toString() + "\n";
    }
}
