package org.jecosys.render;

import org.jecosys.math.Require;
import org.jecosys.scene.RenderDef;
import org.jecosys.scene.SceneDef;

/**
 * What the renderer shows, changeable between frames (the viewer's panel edits it): the light and
 * haze ({@link #lighting()}: sun, sky, ambient light, fog), contact shadow, sheen, shadows, colour
 * patches, ground cover, terrain tint, the force-field overlays ({@link #overlays()}), and whether the
 * library clears and draws its own sky and terrain. {@link #of(SceneDef)} fills it from a scene's
 * {@code <render>} settings. Colours are display (sRGB) values, as a colour picker gives them; the
 * renderer writes them unconverted. Each value has a getter {@code x()} and a setter
 * {@code setX(...)} that checks its arguments and returns nothing. Render thread only (or whichever
 * thread owns the settings while the renderer does not read them); setters do not allocate.
 *
 * <p>Per-plant colour variation is per species, not here: {@code world.plants().species().get(s).def()
 * .variation()} gives the {@code VariationDef} ({@code hue()}, {@code value()}, {@code dryTips()}) of
 * species {@code s}, and {@code world.plantSpecies(p)} the species of plant {@code p}.
 */
public final class RenderSettings {
    private float contactShadow = 0.5f;
    private float patchScale = 12;
    private float patchStrength = 0.3f;
    private int patchSeed = 1;
    private RenderDef.Tint tint = RenderDef.Tint.NONE;
    private final OverlaySettings overlays = new OverlaySettings();
    private final Lighting lighting = new Lighting();
    private boolean clear;
    private boolean terrain;
    private boolean coverSkin = true;
    private RenderDef.GroundCover groundCover = RenderDef.GroundCover.NONE;
    private float sheen = 1f;
    private float shadows;
    private ShadowPath shadowPath = ShadowPath.AUTO;
    private float shadowReach = (float) org.jecosys.render.ground.SunShadowMap.DEFAULT_REACH;

    /**
     * The defaults of a guest in a game's frame: the plants and their ground cover over what the game drew
     * (no clear, no sky, no terrain), lit like a scene file's defaults: a light blue horizon (the haze
     * colour) and a deeper blue zenith, the sun at azimuth 135 degrees and elevation 50 degrees, warm
     * white at intensity 0.8, a cool ambient of about 0.45, contact shadow 0.5, haze from 20 m to
     * 150 m, 12 m colour patches at strength 0.3 (seed 1), no terrain tint, overlays hidden.
     * {@link #standalone()} adds the library's sky and terrain. Allocates.
     */
    public RenderSettings() {
        // every field has its default; the light's are Lighting's
    }

    /**
     * {@return the light and haze: this object's own, read every frame; change them through it (a game
     * sets its own lights there each frame, without allocating)}
     */
    public Lighting lighting() {
        return lighting;
    }

    /**
     * The defaults of {@link #RenderSettings()} with the library drawing the whole picture: it clears
     * the viewport, draws its sky and the scene's terrain, then the plants (the viewer, headless
     * rendering). Allocates.
     *
     * @return new settings with {@link #clear()} and {@link #terrain()} on
     */
    public static RenderSettings standalone() {
        RenderSettings s = new RenderSettings();
        s.setClear(true);
        s.setTerrain(true);
        return s;
    }

    /**
     * The look a scene file asks for in its {@code <render>} element: sky and haze colours, sun, ambient
     * light, contact shadow, fog, colour patches, ground cover, terrain tint and overlays
     * ({@code RenderDef}, its {@code <light>}, {@code <patches>} and {@code <groundCover>}). Clearing and
     * the terrain stay off, as for any guest; the viewer adds {@code setClear(true)} and
     * {@code setTerrain(true)}. Any thread; allocates.
     *
     * @param scene the scene
     * @return new settings
     */
    public static RenderSettings of(SceneDef scene) {
        return of(Require.nonNull("scene", scene).render());
    }

    /**
     * Like {@link #of(SceneDef)}, from the {@code <render>} element alone.
     *
     * @param def a scene's render settings
     * @return new settings, clearing and terrain off
     */
    public static RenderSettings of(RenderDef def) {
        Require.nonNull("def", def);
        RenderDef.Light l = def.light();
        RenderSettings s = new RenderSettings();
        s.lighting.setSky(def.sky());
        s.setTint(def.terrainTint());
        s.overlays.setShowField(def.showField());
        s.overlays.setShowWind(def.showWind());
        s.lighting.setSun(l.sunAzimuth(), l.sunElevation());
        s.lighting.setSunColour(l.sunColour());
        s.lighting.setSunIntensity((float) l.sunIntensity());
        s.lighting.setSkyZenith(l.skyZenith());
        s.lighting.setAmbient(l.ambient());
        s.setContactShadow((float) l.contactShadow());
        s.lighting.setFog((float) l.fogStart(), (float) l.fogEnd());
        s.lighting.setClouds((float) l.clouds());
        s.setSheen((float) l.sheen());
        s.setShadows((float) l.shadows());
        s.setPatches((float) def.patches().scale(), (float) def.patches().strength(), def.patches().seed());
        s.setGroundCover(def.groundCover());
        return s;
    }

    /** {@return the strength of the wind's sheen on bent blades and ground cover, 0 for none} */
    public float sheen() {
        return sheen;
    }

    /**
     * Sets the strength of the wind's sheen ({@code <light sheen>}): a blade bent by the wind brightens
     * toward its pale, sky-lit side, the more the further it bends (plants, ground-cover blades and the
     * cover's colour on the ground alike), so a gust reads from afar as a band of light travelling with
     * it. Render thread; no allocation.
     *
     * @param strength in [0, 2]; 0 turns it off, 1 is the default
     */
    public void setSheen(float strength) {
        Require.range("sheen", strength, 0, 2);
        sheen = strength;
    }

    /** {@return the strength of the plants' sun shadows on the ground, 0 for none} */
    public float shadows() {
        return shadows;
    }

    /**
     * Sets the strength of the plants' sun shadows on the ground ({@code <light shadows>}): the share of
     * the sun's direct light a point in a plant's full shadow loses. The shadows are those of the plants
     * at rest from the sun's direction, a world-space map over the terrain rebuilt when the sun moves
     * (the software path; plants do not shade each other). Render thread; no allocation.
     *
     * @param strength in [0, 1]; 0 (the default) turns them off
     */
    public void setShadows(float strength) {
        Require.range("shadows", strength, 0, 1);
        shadows = strength;
    }

    /** {@return how the sun shadows are drawn, {@link ShadowPath#AUTO} by default} */
    public ShadowPath shadowPath() {
        return shadowPath;
    }

    /**
     * Sets how the sun shadows are drawn when {@link #shadows()} is above 0: a shadow map drawn every
     * frame (the plants shade each other and the ground as they sway), the splatted rest-pose shadows on
     * the ground only, or the one that suits the GL ({@link ShadowPath}). Any thread that owns the
     * settings; read by the render thread every frame. No allocation.
     *
     * @param path not null
     */
    public void setShadowPath(ShadowPath path) {
        shadowPath = Require.nonNull("shadowPath", path);
    }

    /** {@return how far from the eye the shadow map reaches, metres} */
    public float shadowReach() {
        return shadowReach;
    }

    /**
     * Sets how far from the eye the shadow map ({@link ShadowPath#MAP}) reaches: it covers the view's frustum
     * out to this distance; farther, the ground keeps the splatted shadows. A longer reach makes the map's
     * texels larger (about {@code 2.4 x reach / 2048} metres with a 60-degree lens). No allocation.
     *
     * @param metres in [2, 200]
     */
    public void setShadowReach(float metres) {
        Require.range("shadowReach", metres, 2, 200);
        shadowReach = metres;
    }

    /** {@return the ground cover: the short layer hiding the soil where plants grow ({@code <groundCover>})} */
    public RenderDef.GroundCover groundCover() {
        return groundCover;
    }

    /**
     * Sets the ground cover ({@link RenderDef.GroundCover#NONE} for bare ground between the plants). The
     * renderer draws it with the plants (near blades) and the terrain (the cover's colour on the ground)
     * or, without it, as a skin over the host's ground on the scene's heights, faded where the cover ends
     * ({@link #coverSkin()}); it works out where cover grows from the plants once per {@code spread}, so a new spread
     * costs one rebuild of that map (allocates), the rest applies at the next frame. Render thread; no
     * allocation.
     *
     * @param cover the cover, not null
     */
    public void setGroundCover(RenderDef.GroundCover cover) {
        groundCover = Require.nonNull("cover", cover);
    }

    /**
     * {@return how much darker fully occluded ground under plants is, in [0, 1] (0 none); ground within
     * about 0.2 m of a plant's base is occluded}
     */
    public float contactShadow() {
        return contactShadow;
    }

    /**
     * Sets the contact-shadow strength.
     *
     * @param strength darkening of fully occluded ground, in [0, 1]
     * @throws IllegalArgumentException when out of range
     */
    public void setContactShadow(float strength) {
        Require.range("contactShadow", strength, 0, 1);
        this.contactShadow = strength;
    }

    /** {@return the feature size of the healthy/dry colour patches, metres} */
    public float patchScale() {
        return patchScale;
    }

    /** {@return how far the driest patches go from healthy to dry, in [0, 1] (0 no patches)} */
    public float patchStrength() {
        return patchStrength;
    }

    /** {@return the seed of the patch noise} */
    public int patchSeed() {
        return patchSeed;
    }

    /**
     * Sets the healthy/dry colour patches. The patch level at ground point (x, z) is
     * {@link #patchLevel(float, float)}; the shaders compute the same function.
     *
     * @param scaleMetres feature size of the noise, metres, in [0.5, 1000]
     * @param strength    how far the driest patches go toward dry, in [0, 1]; 0 turns them off
     * @param seed        seed of the noise, any int
     * @throws IllegalArgumentException when a value is out of range
     */
    public void setPatches(float scaleMetres, float strength, int seed) {
        Require.range("patchScale", scaleMetres, 0.5, 1000);
        Require.range("patchStrength", strength, 0, 1);
        patchScale = scaleMetres;
        patchStrength = strength;
        patchSeed = seed;
    }

    /** {@return the terrain tint} */
    public RenderDef.Tint tint() {
        return tint;
    }

    /**
     * Sets the terrain tint.
     *
     * @param tint which resource map tints the terrain, not null
     */
    public void setTint(RenderDef.Tint tint) {
        this.tint = Require.nonNull("tint", tint);
    }

    /**
     * {@return the force-field overlays (the quadtree and the wind vectors): this object's own, read
     * every frame; change them through it}
     */
    public OverlaySettings overlays() {
        return overlays;
    }

    /**
     * Whether {@link SceneRenderer#render(org.jecosys.sim.Frame, org.jecosys.math.Camera)} first clears
     * its viewport to depth 1 and draws the library's sky (the gradient with the sun) behind
     * everything. Off by default (a guest draws over the game's frame); on in {@link #standalone()}
     * (the viewer, headless rendering).
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
     */
    public void setClear(boolean clear) {
        this.clear = clear;
    }

    /**
     * Whether the library draws the scene's terrain mesh. Off by default: the plants are
     * depth-tested against the game's own ground in its depth buffer; on in {@link #standalone()}.
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
     */
    public void setTerrain(boolean terrain) {
        this.terrain = terrain;
    }

    /** {@return whether the ground cover is laid over a host's ground when {@link #terrain()} is off (on by default)} */
    public boolean coverSkin() {
        return coverSkin;
    }

    /**
     * Sets {@link #coverSkin()}. No allocation.
     *
     * @param coverSkin false for the near blades alone over a host's ground
     */
    public void setCoverSkin(boolean coverSkin) {
        this.coverSkin = coverSkin;
    }

    /**
     * The healthy/dry patch level at a ground point: 0 healthy, 1 driest, before
     * {@link #patchStrength()} scales it. Value noise of two octaves over {@link #patchScale()}, seeded
     * by {@link #patchSeed()}, made into patches with a smooth step; {@code terrain.frag} computes the
     * same function ({@code patchLevel}). Any thread reading settings not being changed; no allocation.
     *
     * @param x world X, metres
     * @param z world Z, metres
     * @return the level, in [0, 1]
     */
    public float patchLevel(float x, float z) {
        return org.jecosys.render.ground.PatchNoise.level(x / patchScale, z / patchScale, patchSeed);
    }
}
