package org.jecosys.scene;

import org.jecosys.math.Require;
import org.jecosys.math.Rgb;

/**
 * The checks of the canonical constructors of {@link RenderDef} and of its {@link RenderDef.Light},
 * {@link RenderDef.Patches} and {@link RenderDef.GroundCover}: every component in the range its record
 * documents, in the order each constructor has always checked them (so the value reported is the same).
 * Static methods only; any thread; no allocation but the messages they throw.
 */
final class RenderDefChecks {
    private RenderDefChecks() {
    }

    /**
     * Checks the components of a {@link RenderDef}; arguments as its canonical constructor's (the
     * overlay flags take any value).
     *
     * @throws IllegalArgumentException when a component is null or out of range
     */
    static void render(int width, int height, Rgb sky, double lodTransition, RenderDef.Tint terrainTint,
                       RenderDef.Light light, RenderDef.Patches patches, int antialiasing,
                       RenderDef.GroundCover groundCover) {
        Require.range("width", width, 16, 8192);
        Require.range("height", height, 16, 8192);
        Require.nonNull("sky", sky);
        Require.range("lodTransition", lodTransition, 0, 10);
        Require.nonNull("terrainTint", terrainTint);
        Require.nonNull("light", light);
        Require.nonNull("patches", patches);
        Require.nonNull("groundCover", groundCover);
        if (antialiasing != 1 && antialiasing != 2 && antialiasing != 4 && antialiasing != 8) {
            throw new IllegalArgumentException("antialiasing must be 1, 2, 4 or 8 samples per pixel, got "
                    + antialiasing);
        }
    }

    /**
     * Checks the components of a {@link RenderDef.Light}: clouds, sheen and shadows first, then the rest
     * in record order; arguments as its canonical constructor's.
     *
     * @throws IllegalArgumentException when a component is null or out of range
     */
    static void light(double sunAzimuth, double sunElevation, Rgb sunColour, double sunIntensity, Rgb skyZenith,
                      Rgb ambient, double contactShadow, double fogStart, double fogEnd, double sheen,
                      double shadows, double clouds) {
        Require.range("clouds", clouds, 0, 1);
        Require.range("sheen", sheen, 0, RenderDef.Light.MAX_SHEEN);
        Require.range("shadows", shadows, 0, 1);
        Require.degrees("sunAzimuth", sunAzimuth, -RenderDef.Light.MAX_AZIMUTH_DEGREES,
                RenderDef.Light.MAX_AZIMUTH_DEGREES);
        Require.degrees("sunElevation", sunElevation, 0, RenderDef.Light.MAX_ELEVATION_DEGREES);
        Require.nonNull("sunColour", sunColour);
        Require.range("sunIntensity", sunIntensity, 0, RenderDef.Light.MAX_INTENSITY);
        Require.nonNull("skyZenith", skyZenith);
        Require.nonNull("ambient", ambient);
        Require.range("contactShadow", contactShadow, 0, 1);
        Require.range("fogStart", fogStart, 0, RenderDef.Light.MAX_FOG);
        Require.range("fogEnd", fogEnd, 0, RenderDef.Light.MAX_FOG);
        if (!(fogEnd > fogStart)) {
            throw new IllegalArgumentException("fogEnd must be > fogStart (" + fogStart + "), got " + fogEnd);
        }
    }

    /**
     * Checks the components of a {@link RenderDef.Patches} (the seed takes any value).
     *
     * @throws IllegalArgumentException when a component is out of range
     */
    static void patches(double scale, double strength) {
        Require.range("scale", scale, RenderDef.Patches.MIN_SCALE, RenderDef.Patches.MAX_SCALE);
        Require.range("strength", strength, 0, 1);
    }

    /**
     * Checks the components of a {@link RenderDef.GroundCover}; arguments as its canonical constructor's.
     *
     * @throws IllegalArgumentException when a component is null or out of range
     */
    static void groundCover(double amount, double height, double density, double reach, double spread, Rgb colour,
                            Rgb dryColour) {
        Require.range("amount", amount, 0, 1);
        Require.range("height", height, RenderDef.GroundCover.MIN_HEIGHT, RenderDef.GroundCover.MAX_HEIGHT);
        Require.range("density", density, 0, RenderDef.GroundCover.MAX_DENSITY);
        Require.range("reach", reach, 0, RenderDef.GroundCover.MAX_REACH);
        Require.range("spread", spread, RenderDef.GroundCover.MIN_SPREAD, RenderDef.GroundCover.MAX_SPREAD);
        Require.nonNull("colour", colour);
        Require.nonNull("dryColour", dryColour);
    }
}
