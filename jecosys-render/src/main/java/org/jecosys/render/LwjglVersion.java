package org.jecosys.render;

import org.jecosys.math.Require;

/**
 * The LWJGL versions the renderer runs on: 3.3.3 (what libGDX 1.13 and jMonkeyEngine 3.7 bring) and
 * later, 3.4.x included (what the library is built with). Older versions lack functions the renderer
 * calls, and would fail later with a {@code NoSuchMethodError} that names no version; every way to
 * get a {@link GlContext} checks first and refuses them with a message naming both versions.
 * Any thread; no state.
 */
public final class LwjglVersion {
    /** The oldest LWJGL the renderer runs on, as major, minor, revision. */
    private static final int[] MINIMUM = {3, 3, 3};
    /** {@link #MINIMUM} as text. */
    public static final String MINIMUM_TEXT = "3.3.3";

    private LwjglVersion() {
    }

    /**
     * Checks the LWJGL on the class path ({@code org.lwjgl.Version.getVersion()}). Allocates a little.
     *
     * @throws IllegalStateException when it is older than {@link #MINIMUM_TEXT}
     */
    public static void require() {
        require(org.lwjgl.Version.getVersion());
    }

    /**
     * Checks a version string as {@code org.lwjgl.Version.getVersion()} gives it ("3.4.3+4",
     * "3.3.3 SNAPSHOT", "3.2.3 build 13").
     *
     * @param found the version found
     * @throws IllegalStateException when it is older than {@link #MINIMUM_TEXT} or cannot be read
     */
    public static void require(String found) {
        Require.nonNull("found", found);
        int[] v = parse(found);
        if (v == null || compare(v, MINIMUM) < 0) {
            throw new IllegalStateException("JEcoSys needs LWJGL " + MINIMUM_TEXT + " or newer, found LWJGL " + found
                    + " on the class path: align LWJGL to " + MINIMUM_TEXT + " or later (for example import "
                    + "org.jecosys:jecosys-bom, or org.lwjgl:lwjgl-bom, in dependencyManagement)");
        }
    }

    /** Major, minor and revision of a version string, or null when it does not start with them. */
    static int[] parse(String s) {
        int[] v = new int[3];
        int i = 0;
        for (int part = 0; part < 3; part++) {
            int start = i;
            while (i < s.length() && Character.isDigit(s.charAt(i))) {
                i++;
            }
            if (i == start || i - start > 6) {
                return part == 2 ? v : null; // "3.3" reads as 3.3.0
            }
            v[part] = Integer.parseInt(s.substring(start, i));
            if (part < 2) {
                if (i >= s.length() || s.charAt(i) != '.') {
                    return part == 1 ? v : null;
                }
                i++;
            }
        }
        return v;
    }

    static int compare(int[] a, int[] b) {
        for (int i = 0; i < 3; i++) {
            if (a[i] != b[i]) {
                return Integer.compare(a[i], b[i]);
            }
        }
        return 0;
    }
}
