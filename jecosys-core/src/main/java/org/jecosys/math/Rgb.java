package org.jecosys.math;

/**
 * A linear RGB colour, each channel in [0, 1]. Immutable; any thread.
 *
 * @param r red in [0, 1]
 * @param g green in [0, 1]
 * @param b blue in [0, 1]
 */
public record Rgb(float r, float g, float b) {
    /**
     * Checks the channels.
     *
     * @param r red in [0, 1]
     * @param g green in [0, 1]
     * @param b blue in [0, 1]
     * @throws IllegalArgumentException when a channel is not finite or outside [0, 1]
     */
    public Rgb {
        Require.range("r", r, 0, 1);
        Require.range("g", g, 0, 1);
        Require.range("b", b, 0, 1);
    }

    /**
     * Parses {@code #rrggbb} (case-insensitive).
     *
     * @param s a hex colour such as {@code #6b8e23}
     * @return the colour, channels {@code value / 255}
     * @throws IllegalArgumentException when {@code s} is null or not {@code #} and six hex digits
     */
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

    /**
     * This colour as {@code #rrggbb}, channels rounded to 8 bits.
     *
     * @return lower-case hex, e.g. {@code #6b8e23}; {@link #parseHex} reads it back
     */
    public String toHex() {
        return String.format("#%02x%02x%02x", Math.round(r * 255), Math.round(g * 255), Math.round(b * 255));
    }
}
