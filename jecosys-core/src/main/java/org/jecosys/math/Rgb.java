package org.jecosys.math;

/**
 * A linear RGB colour, each channel in [0, 1]. Immutable; any thread.
 *
 * @param r red in [0, 1]
 * @param g green in [0, 1]
 * @param b blue in [0, 1]
 */
public record Rgb(float r, float g, float b) {
    public Rgb {
        Require.range("r", r, 0, 1);
        Require.range("g", g, 0, 1);
        Require.range("b", b, 0, 1);
    }

    /** Parses {@code #rrggbb} (case-insensitive). Throws IllegalArgumentException otherwise. */
    public static Rgb parseHex(String s) {
        if (s == null || s.length() != 7 || s.charAt(0) != '#') {
            throw new IllegalArgumentException("colour must be #rrggbb, got '" + s + "'");
        }
        int v;
        try {
            v = Integer.parseInt(s.substring(1), 16);
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("colour must be #rrggbb, got '" + s + "'");
        }
        return new Rgb(((v >> 16) & 0xff) / 255f, ((v >> 8) & 0xff) / 255f, (v & 0xff) / 255f);
    }

    /** This colour as {@code #rrggbb}, channels rounded to 8 bits. */
    public String toHex() {
        return String.format("#%02x%02x%02x", Math.round(r * 255), Math.round(g * 255), Math.round(b * 255));
    }
}
