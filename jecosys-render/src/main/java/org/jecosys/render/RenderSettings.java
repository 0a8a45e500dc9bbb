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
    private TerrainTint tint = TerrainTint.NONE;
    private boolean showField;
    private boolean showWind;
    private float fogStart = 25;
    private float fogEnd = 160;
    private boolean clear = true;
    private boolean terrain = true;

    /**
     * The defaults: a light blue sky, a 1 m LOD transition band, no terrain tint, overlays hidden,
     * fog from 25 m to 160 m, clearing and terrain on. Allocates.
     */
    public RenderSettings() {
    }

    /** {@return the sky (clear and fog) colour} */
    public Rgb sky() {
        return sky;
    }

    /**
     * Sets the sky colour.
     *
     * @param sky the clear and fog colour, not null
     * @return this settings object
     */
    public RenderSettings sky(Rgb sky) {
        this.sky = Require.nonNull("sky", sky);
        return this;
    }


    /** {@return the terrain tint} */
    public TerrainTint tint() {
        return tint;
    }

    /**
     * Sets the terrain tint.
     *
     * @param tint which resource map tints the terrain, not null
     * @return this settings object
     */
    public RenderSettings tint(TerrainTint tint) {
        this.tint = Require.nonNull("tint", tint);
        return this;
    }

    /** {@return whether the force-field quadtree overlay (paper Figure 2) is drawn} */
    public boolean showField() {
        return showField;
    }

    /**
     * Shows or hides the quadtree overlay.
     *
     * @param show true to draw it
     * @return this settings object
     */
    public RenderSettings showField(boolean show) {
        this.showField = show;
        return this;
    }

    /** {@return whether wind vectors per effective node (paper Figure 3) are drawn} */
    public boolean showWind() {
        return showWind;
    }

    /**
     * Shows or hides the wind vectors.
     *
     * @param show true to draw them
     * @return this settings object
     */
    public RenderSettings showWind(boolean show) {
        this.showWind = show;
        return this;
    }

    /** {@return the distance where fog begins, metres} */
    public float fogStart() {
        return fogStart;
    }

    /** {@return the distance of full fog, metres} */
    public float fogEnd() {
        return fogEnd;
    }

    /**
     * Sets the fog range.
     *
     * @param start distance where fog begins, metres, &gt;= 0
     * @param end   distance of full fog, metres, &gt; start
     * @return this settings object
     * @throws IllegalArgumentException when the range is empty or starts below 0
     */
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
