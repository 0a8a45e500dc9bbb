package org.jecosys.scene;

import org.jecosys.math.Require;
import org.jecosys.math.Rgb;

/**
 * Presentation settings of a scene. The application passes them to the renderer. Immutable; any thread.
 *
 * @param width         default window or image width, pixels, in [16, 8192]
 * @param height        default window or image height, pixels, in [16, 8192]
 * @param sky           background colour
 * @param lodTransition width of the band over which two levels of detail are dithered, metres, in [0, 10]
 * @param terrainTint   which resource map tints the terrain
 * @param showField     whether the force-field quadtree overlay starts visible (paper Figure 2)
 * @param showWind      whether the wind-vector overlay starts visible (paper Figure 3)
 */
public record RenderDef(int width, int height, Rgb sky, double lodTransition, Tint terrainTint, boolean showField,
                        boolean showWind) {
    /** Which map tints the terrain. */
    public enum Tint {
        /** Plain terrain colour. */
        NONE("none"),
        /** Blue where water is high. */
        WATER("water"),
        /** Brown-green by nutrient level. */
        NUTRIENTS("nutrients");

        private final String xmlName;

        Tint(String xmlName) {
            this.xmlName = xmlName;
        }

        /** {@return the attribute value used in scene files, e.g. {@code "water"}} */
        public String xmlName() {
            return xmlName;
        }
    }

    /**
     * Checks the components.
     *
     * @param width         default width, pixels, in [16, 8192]
     * @param height        default height, pixels, in [16, 8192]
     * @param sky           background colour, not null
     * @param lodTransition dithering band width, metres, in [0, 10]
     * @param terrainTint   terrain tint, not null
     * @param showField     whether the quadtree overlay starts visible
     * @param showWind      whether the wind-vector overlay starts visible
     * @throws IllegalArgumentException when a component is null or out of range
     */
    public RenderDef {
        Require.range("width", width, 16, 8192);
        Require.range("height", height, 16, 8192);
        Require.nonNull("sky", sky);
        Require.range("lodTransition", lodTransition, 0, 10);
        Require.nonNull("terrainTint", terrainTint);
    }

    /** {@return 1280x720, light blue sky, a 1 m transition band, no tint, overlays hidden} */
    public static RenderDef defaults() {
        return new RenderDef(1280, 720, new Rgb(0.62f, 0.76f, 0.92f), 1, Tint.NONE, false, false);
    }
}
