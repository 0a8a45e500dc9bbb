package org.jecosys.terrain;

import org.jecosys.math.Require;

/**
 * A resource map over the terrain (paper §4.3: irrigation and nutrients). Values are levels in
 * [0, 1] per cell before plants consume them. Immutable; any thread.
 *
 * @param source     how the map is made
 * @param resolution cells per side, in [2, 1024]
 * @param amount     overall level multiplier, in [0, 1]
 * @param scale      NOISE: feature size, metres, &gt; 0 (ignored otherwise)
 * @param image      IMAGE: path of a greyscale PNG, relative to the scene file; otherwise null
 */
public record ResourceMapDef(Source source, int resolution, double amount, double scale, String image) {
    /** How a map is made. */
    public enum Source {
        /** The same level everywhere. */
        UNIFORM("uniform"),
        /** Seeded value noise. */
        NOISE("noise"),
        /** Water gathering in low ground and valleys, from the heightfield. */
        VALLEYS("valleys"),
        /** Read from a greyscale image. */
        IMAGE("image");

        private final String xmlName;

        Source(String xmlName) {
            this.xmlName = xmlName;
        }

        /** {@return the attribute value used in scene files, e.g. {@code "valleys"}} */
        public String xmlName() {
            return xmlName;
        }
    }

    /**
     * Checks the components.
     *
     * @param source     how the map is made, not null
     * @param resolution cells per side, in [2, {@link #MAX_RESOLUTION}]
     * @param amount     overall level multiplier, in [0, 1]
     * @param scale      NOISE feature size, metres, in [{@link #MIN_SCALE}, {@link #MAX_SCALE}] (even when
     *                   ignored)
     * @param image      IMAGE: the image path; null exactly when the source is not IMAGE
     * @throws IllegalArgumentException when a component is out of range, or {@code image} is given
     *                                  for another source or missing for IMAGE
     */
    public ResourceMapDef {
        Require.nonNull("source", source);
        Require.range("resolution", resolution, 2, MAX_RESOLUTION);
        Require.range("amount", amount, 0, 1);
        Require.range("scale", scale, MIN_SCALE, MAX_SCALE);
        if ((source == Source.IMAGE) != (image != null)) {
            throw new IllegalArgumentException("image must be given exactly when source is image");
        }
    }

    /** Most cells per side (the scene schema's range and the API's). */
    public static final int MAX_RESOLUTION = 1024;
    /** Smallest noise feature size, metres (a smaller one puts the noise beyond double precision). */
    public static final double MIN_SCALE = 1e-3;
    /** Largest noise feature size, metres. */
    public static final double MAX_SCALE = 100_000;

    /** Level 1 everywhere at 64 cells per side. */
    public static final ResourceMapDef UNIFORM_FULL = new ResourceMapDef(Source.UNIFORM, 64, 1, 8, null);
}
