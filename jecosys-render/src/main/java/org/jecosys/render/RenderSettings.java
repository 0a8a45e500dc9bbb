package org.jecosys.render;

import org.jecosys.math.Require;
import org.jecosys.math.Rgb;

/**
 * What the renderer shows, changeable between frames (the viewer's panel edits it): sky colour, LOD
 * transition band, terrain tint, overlays, fog. The app fills it from a scene's render settings.
 * Render thread only; setters do not allocate.
 */
public final class RenderSettings {
    private Rgb sky = new Rgb(0.62f, 0.76f, 0.92f);
    private double lodTransition = 1;
    private TerrainTint tint = TerrainTint.NONE;
    private boolean showField;
    private boolean showWind;
    private float fogStart = 25;
    private float fogEnd = 160;
    private boolean clear = true;
    private boolean terrain = true;

    /** Sky (clear and fog) colour. */
    public Rgb sky() {
        return sky;
    }

    /** Sets the sky colour. */
    public RenderSettings sky(Rgb sky) {
        this.sky = Require.nonNull("sky", sky);
        return this;
    }

    /** LOD transition band width, metres. */
    public double lodTransition() {
        return lodTransition;
    }

    /** Sets the LOD transition band width, metres, in [0, 10]. */
    public RenderSettings lodTransition(double metres) {
        this.lodTransition = Require.range("lodTransition", metres, 0, 10);
        return this;
    }

    /** Terrain tint. */
    public TerrainTint tint() {
        return tint;
    }

    /** Sets the terrain tint. */
    public RenderSettings tint(TerrainTint tint) {
        this.tint = Require.nonNull("tint", tint);
        return this;
    }

    /** Whether the force-field quadtree overlay (paper Figure 2) is drawn. */
    public boolean showField() {
        return showField;
    }

    /** Shows or hides the quadtree overlay. */
    public RenderSettings showField(boolean show) {
        this.showField = show;
        return this;
    }

    /** Whether wind vectors per effective node (paper Figure 3) are drawn. */
    public boolean showWind() {
        return showWind;
    }

    /** Shows or hides the wind vectors. */
    public RenderSettings showWind(boolean show) {
        this.showWind = show;
        return this;
    }

    /** Distance where fog begins, metres. */
    public float fogStart() {
        return fogStart;
    }

    /** Distance of full fog, metres. */
    public float fogEnd() {
        return fogEnd;
    }

    /** Sets the fog range, metres, 0 &lt;= start &lt; end. */
    public RenderSettings fog(float start, float end) {
        Require.nonNegative("fogStart", start);
        if (!(end > start)) {
            throw new IllegalArgumentException("fog end must be > start, got " + start + ".." + end);
        }
        fogStart = start;
        fogEnd = end;
        return this;
    }

    /**
     * Whether {@link SceneRenderer#render(org.jecosys.sim.Frame, org.jecosys.math.Camera)} first clears
     * its viewport to the sky colour and depth 1. On by default (the viewer, headless rendering); a
     * game that draws its own sky and ground first turns it off.
     *
     * @return whether the viewport is cleared before drawing
     */
    public boolean clear() {
        return clear;
    }

    /**
     * Sets whether the renderer clears its viewport before drawing (see {@link #clear()}).
     *
     * @param clear true to clear colour and depth of the viewport first
     * @return this settings object
     */
    public RenderSettings clear(boolean clear) {
        this.clear = clear;
        return this;
    }

    /**
     * Whether the library draws the scene's terrain mesh. On by default; a game that draws its own
     * ground turns it off, and the plants are depth-tested against the game's depth buffer.
     *
     * @return whether the terrain is drawn
     */
    public boolean terrain() {
        return terrain;
    }

    /**
     * Sets whether the library draws the scene's terrain (see {@link #terrain()}).
     *
     * @param terrain true to draw the terrain mesh
     * @return this settings object
     */
    public RenderSettings terrain(boolean terrain) {
        this.terrain = terrain;
        return this;
    }
}
