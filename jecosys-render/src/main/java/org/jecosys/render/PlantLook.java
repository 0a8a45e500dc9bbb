package org.jecosys.render;

import org.jecosys.math.Require;

/**
 * The colour variation of the plants, set through {@link PlantRenderer}: per species the spread of a
 * plant's hue turn and brightness and how far its tips turn to straw, and for the whole scene the
 * healthy/dry patches (the ground's noise, {@link RenderSettings#patchLevel}) and the seed of it all. The resolve pass
 * turns it into each drawn component's hue turn, brightness factor and patch dryness. Render thread;
 * setters do not allocate.
 */
final class PlantLook {
    /** Default patch size, metres. */
    static final float DEFAULT_PATCH_SCALE = 20f;

    private final float[] variation;
    private float patchScale = DEFAULT_PATCH_SCALE;
    private float patchStrength;
    private int seed;

    /** No variation and no patches for {@code species} species. Allocates. */
    PlantLook(int species) {
        variation = new float[3 * species];
    }

    void setVariation(int s, float hueDeg, float value, float dryTips) {
        Require.range("species", s, 0, variation.length / 3 - 1);
        Require.range("hue", hueDeg, 0, 60);
        Require.range("value", value, 0, 1);
        Require.range("dryTips", dryTips, 0, 1);
        variation[3 * s] = (float) Math.toRadians(hueDeg);
        variation[3 * s + 1] = value;
        variation[3 * s + 2] = dryTips;
    }

    void setPatches(float scale, float strength, int seed) {
        Require.range("patchScale", scale, 0.5, 1000);
        Require.range("patchStrength", strength, 0, 1);
        this.patchScale = scale;
        this.patchStrength = strength;
        this.seed = seed;
    }

    /** {@return the hue turn's standard deviation of species s, radians} */
    float hue(int s) {
        return variation[3 * s];
    }

    /** {@return the brightness factor's standard deviation of species s} */
    float value(int s) {
        return variation[3 * s + 1];
    }

    /** {@return how far the tips of species s turn to straw, 0..1} */
    float dryTips(int s) {
        return variation[3 * s + 2];
    }

    /** {@return the patch size, metres} */
    float patchScale() {
        return patchScale;
    }

    /** {@return how dry the driest patches get, 0..1} */
    float patchStrength() {
        return patchStrength;
    }

    /** {@return the colour seed} */
    int seed() {
        return seed;
    }
}
