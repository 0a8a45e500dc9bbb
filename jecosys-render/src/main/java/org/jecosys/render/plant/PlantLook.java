package org.jecosys.render.plant;

import java.util.List;
import org.jecosys.math.Require;
import org.jecosys.plant.SpeciesModel;
import org.jecosys.plant.VariationDef;
import org.jecosys.render.RenderSettings;
import org.jecosys.render.ground.ShadowParams;

/**
 * The look of the plants, set through {@link PlantRenderer}: the light on them (sun and ambient), how
 * thin parts and flowers are kept visible, and the colour variation: per species the spread of a
 * plant's hue turn and brightness and how far its tips turn to straw, and for the whole scene the
 * healthy/dry patches (the ground's noise, {@link RenderSettings#patchLevel}) and the seed of it all.
 * {@code ComponentLooks} turns it into each component's hue turn, brightness factor and patch dryness
 * when it changes ({@link #version}). Render thread; setters do not allocate.
 */
public final class PlantLook {
    /** Default patch size, metres. */
    public static final float DEFAULT_PATCH_SCALE = 20f;

    private final float[] variation;
    public float minPixels = PlantRenderer.DEFAULT_MIN_PIXELS;
    public float headPixels = PlantRenderer.DEFAULT_HEAD_PIXELS;
    public float flowerTilt = (float) Math.toRadians(PlantRenderer.DEFAULT_FLOWER_TILT);
    public float sunR = 0.80f;
    public float sunG = 0.78f;
    public float sunB = 0.72f;
    public float ambR = 0.42f;
    public float ambG = 0.46f;
    public float ambB = 0.52f;
    /** Strength of the wind's sheen on bent blades (plant_light.glsl windSheen), 0: off. */
    public float sheen = 1f;
    /**
     * The sun's shadow map the triangle levels read ({@code sun_shadow.glsl}): the scene renderer's,
     * filled each frame ({@link PlantRenderer#useShadowMap}); none drawn until then.
     */
    ShadowParams shadow = new ShadowParams();
    private float patchScale = DEFAULT_PATCH_SCALE;
    private float patchStrength;
    private int seed;
    /** Counts the changes of what the component looks are baked from: variation, patches, seed. */
    private int version;

    /** No variation and no patches for {@code species} species. Allocates. */
    public PlantLook(int species) {
        variation = new float[3 * species];
    }

    /**
     * Sets each species' colour variation from its def, species s from {@code models.get(s)}: the hue and
     * dry tips as they are, the brightness spread at most 1 ({@link #setVariation}). Build time.
     */
    void setVariations(List<SpeciesModel> models) {
        for (int s = 0; s < models.size(); s++) {
            VariationDef v = models.get(s).def().variation();
            setVariation(s, (float) v.hue(), (float) Math.min(1, v.value()), (float) v.dryTips());
        }
    }

    public void setVariation(int s, float hueDeg, float value, float dryTips) {
        Require.range("species", s, 0, variation.length / 3 - 1);
        Require.range("hue", hueDeg, 0, 60);
        Require.range("value", value, 0, 1);
        Require.range("dryTips", dryTips, 0, 1);
        float hue = (float) Math.toRadians(hueDeg);
        if (hue != variation[3 * s] || value != variation[3 * s + 1]) {
            version++;
        }
        variation[3 * s] = hue;
        variation[3 * s + 1] = value;
        variation[3 * s + 2] = dryTips;
    }

    /** Sets the sun (colour times intensity) and the sky's ambient light; checked by the caller. */
    public void setLight(float sr, float sg, float sb, float ar, float ag, float ab) {
        sunR = sr;
        sunG = sg;
        sunB = sb;
        ambR = ar;
        ambG = ag;
        ambB = ab;
    }

    /** Sets the thin-part and flower settings (tilt in radians); checked by the caller. */
    public void setThinParts(float minPixels, float headPixels, float flowerTilt) {
        this.minPixels = minPixels;
        this.headPixels = headPixels;
        this.flowerTilt = flowerTilt;
    }

    public void setPatches(float scale, float strength, int seed) {
        Require.range("patchScale", scale, 0.5, 1000);
        Require.range("patchStrength", strength, 0, 1);
        if (scale != patchScale || strength != patchStrength || seed != this.seed) {
            version++;
        }
        this.patchScale = scale;
        this.patchStrength = strength;
        this.seed = seed;
    }

    /**
     * {@return a number that changes whenever the hue or brightness spread of a species, the patches
     * or the seed change: what each component's baked look ({@code ComponentLooks}) is made from}
     */
    public int version() {
        return version;
    }

    /** {@return the hue turn's standard deviation of species s, radians} */
    public float hue(int s) {
        return variation[3 * s];
    }

    /** {@return the brightness factor's standard deviation of species s} */
    public float value(int s) {
        return variation[3 * s + 1];
    }

    /** {@return how far the tips of species s turn to straw, 0..1} */
    public float dryTips(int s) {
        return variation[3 * s + 2];
    }

    /** {@return the patch size, metres} */
    public float patchScale() {
        return patchScale;
    }

    /** {@return how dry the driest patches get, 0..1} */
    public float patchStrength() {
        return patchStrength;
    }

    /** {@return the colour seed} */
    public int seed() {
        return seed;
    }
}
