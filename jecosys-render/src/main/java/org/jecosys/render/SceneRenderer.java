package org.jecosys.render;

import org.jecosys.render.gl.Closing;
import static org.lwjgl.opengl.GL11C.GL_DEPTH_TEST;
import static org.lwjgl.opengl.GL11C.glDisable;
import static org.lwjgl.opengl.GL11C.glViewport;

import org.jecosys.field.FieldDebugView;
import org.jecosys.math.Require;
import org.jecosys.math.Camera;
import org.jecosys.sim.Frame;
import org.jecosys.sim.World;
import org.jecosys.render.gl.GlFramebuffer;
import org.jecosys.render.gl.GlStateGuard;
import org.jecosys.render.ground.SkyRenderer;
import org.jecosys.render.ground.SunShadow;
import org.jecosys.render.ground.ShadowParams;
import org.jecosys.render.ground.SunShadowMap;
import org.jecosys.render.ground.CoverBlades;
import org.jecosys.render.ground.TerrainRenderer;
import org.jecosys.render.overlay.FieldOverlay;
import org.jecosys.render.plant.PlantRenderer;
import org.jecosys.render.ResolvePath;

/**
 * Renders a whole frame of a {@link World}: sky (gradient and sun), plants, lit terrain and the
 * optional force-field overlays, into the currently bound framebuffer and viewport (a window's, a
 * game's own or a {@link GlFramebuffer}), and puts back every GL state it changed (see
 * {@link #render(Frame, Camera)}). With sun shadows on the {@link ShadowPath#MAP} path it first draws
 * the plants resolved for the view into the sun's shadow map (SunShadowMap), which the plants, the
 * ground cover and the terrain then read. Owns the sky, terrain, ground-cover (blades and skin),
 * plant, shadow-map and overlay renderers (the ground and sky passes are drawn by {@code GroundPass}, the
 * shadow map by {@code SunShadowPass}; the pass timing is kept by {@code PassTiming}). Render thread only;
 * {@link #render} allocates nothing in the steady state (changing the tint or LOD band re-uploads or
 * rebuilds once).
 *
 * <p>A new context: each {@link #render} first asks {@link GlContext#follow()} whether the host
 * replaced its context (jMonkeyEngine's {@code app.restart()}); if so it forgets the old objects
 * without a GL call and makes them again in the new context (once; allocates), then draws as before.
 */
public final class SceneRenderer implements AutoCloseable {
    private final GlContext gl;
    private final RenderSettings settings;
    private final World world;
    private TerrainRenderer terrain;
    private CoverBlades cover;
    /** The ground and sky passes, with the cover's skin over a host's own ground. */
    private final GroundPass ground;
    private PlantRenderer plants;
    private SkyRenderer sky;
    private FieldOverlay overlay;
    private FieldDebugView field;
    private GlStateGuard state;
    /** The path {@link ShadowPath#AUTO} takes on this context. */
    private ShadowPath autoShadows;
    /** The sun's shadow map, made at the first frame that draws one. */
    private final SunShadowPass shadowMap;
    /** The shadow map's per-frame values as the shaders read them, shared with the plants, terrain and cover. */
    private final ShadowParams shadow = new ShadowParams();
    /**
     * How far from the eye plants cast into the map: the nearest distance at which a species with a
     * line level draws lines (lines do not cast), metres; infinite when none has one.
     */
    private final double castReach;
    private boolean closed;
    /** The resolve path asked for when made (null: the best), for a rebuild in a new context. */
    private final ResolvePath path;
    /** The context generation ({@link GlContext#generation()}) the GL objects were made in. */
    private int generation;
    /**
     * Benchmark breakdown and tests only (package-private): skip the terrain or the plants (plants
     * skipped still cast into the shadow map: the ground as it is under them).
     */
    boolean drawTerrain = true;
    boolean drawPlants = true;
    /** The GPU timer queries of {@link #setPassTiming}, while on. */
    private final PassTiming timing;

    /**
     * Uploads everything static of the world, and puts back every GL state that uploading changes
     * (as {@link #render(Frame, Camera)} does), also when it fails. Render thread; allocates.
     *
     * @param gl       the render context, current on this thread
     * @param world    the terrain and plants to draw
     * @param settings read every frame; the caller may change it between frames
     */
    public SceneRenderer(GlContext gl, World world, RenderSettings settings) {
        this(gl, world, settings, null);
    }

    /**
     * As {@link #SceneRenderer(GlContext, World, RenderSettings)}, with the plants' per-component
     * pass on the path named ({@link ResolvePath}).
     * Render thread; allocates.
     *
     * @param gl       the render context, current on this thread
     * @param world    the terrain and plants to draw
     * @param settings read every frame; the caller may change it between frames
     * @param path     the plants' resolve path; null: the best the context supports
     * @throws IllegalArgumentException when the context cannot run {@code path}
     */
    public SceneRenderer(GlContext gl, World world, RenderSettings settings, ResolvePath path) {
        gl.checkThread();
        this.gl = gl;
        this.settings = settings;
        this.world = world;
        this.path = path;
        castReach = SunShadowMap.castReach(world);
        shadowMap = new SunShadowPass(gl, shadow);
        ground = new GroundPass(gl, shadow);
        timing = new PassTiming(gl);
        build();
    }

    /** Makes every GL object in the current context; puts back the state uploading changes. Allocates. */
    private void build() {
        generation = gl.generation();
        TerrainRenderer t = null;
        CoverBlades c = null;
        PlantRenderer p = null;
        SkyRenderer k = null;
        GlStateGuard g = new GlStateGuard();
        // uploading binds programs, vertex arrays, buffers and textures: the host's are put back after
        // (a host that caches its bindings, such as jMonkeyEngine's one vertex array of a core profile,
        // draws nothing once they change under it)
        g.save();
        try {
            g.setGuestState();
            t = new TerrainRenderer(gl, world, settings.tint());
            c = new CoverBlades(gl, world, t);
            t.setBendMap(c.bendMap(), c.bendMapTransform());
            p = new PlantRenderer(gl, world, path);
            k = new SkyRenderer(gl);
            overlay = new FieldOverlay(gl, world.terrain().heightfield());
        } catch (RuntimeException e) {
            try {
                Closing.closeAll(k, p, c, t);
            } finally {
                g.restore();
                g.close();
            }
            throw e;
        }
        g.restore();
        sky = k;
        terrain = t;
        cover = c;
        plants = p;
        state = g;
        autoShadows = ShadowPath.AUTO.on(org.lwjgl.opengl.GL11C.glGetString(org.lwjgl.opengl.GL11C.GL_RENDERER));
        terrain.useShadowMap(shadow);
        cover.useShadowMap(shadow);
        plants.useShadowMap(shadow);
    }

    /** {@return the world this renderer draws} */
    public World world() {
        return world;
    }

    /** {@return the settings this renderer reads} */
    public RenderSettings settings() {
        return settings;
    }

    /**
     * Sets the force field whose quadtree and wind the overlays show.
     *
     * @param view the field's debug view, read on the render thread between field updates; null for none
     */
    public void setField(FieldDebugView view) {
        this.field = view;
    }

    static {
        org.jecosys.render.internal.SceneParts.grant(new ScenePartsAccess());
    }

    /** The plant renderer (internal: {@code SceneParts}; its batches hold the per-frame counters). */
    PlantRenderer plants() {
        return plants;
    }

    /** The terrain renderer (internal: {@code SceneParts}). */
    TerrainRenderer terrain() {
        return terrain;
    }

    /** The near ground-cover renderer (internal: {@code SceneParts}). */
    CoverBlades cover() {
        return cover;
    }

    /** The overlay renderer (internal: {@code SceneParts}). */
    FieldOverlay overlay() {
        return overlay;
    }

    /** {@return the path the plants' per-component pass takes on this renderer} */
    public ResolvePath resolvePath() {
        return plants.path();
    }

    /** {@return the plant components drawn by the last {@link #render}} */
    public int drawnComponents() {
        return plants.batches().components();
    }

    /** {@return the plant draw calls of the last {@link #render}} */
    public int drawCalls() {
        return plants.drawCalls();
    }

    /** {@return the bytes the last {@link #render} uploaded for the plants: instance records and component render states} */
    public long uploadedBytes() {
        return plants.uploadedBytes();
    }

    /**
     * {@return whether the plants' per-frame uploads go through a persistently mapped ring of three
     * regions with fences (where the GL has buffer storage: 4.4, or 4.3 with {@code ARB_buffer_storage});
     * elsewhere they re-specify streaming buffers} Render thread; no allocation.
     */
    public boolean uploadRing() {
        return plants.uploadRing();
    }

    /**
     * {@return the frames, since this renderer was made, whose upload region the GPU was still reading, so
     * that {@link #render} waited for it: 0 unless the GPU falls more than two frames behind} Render thread;
     * no allocation.
     */
    public long uploadWaits() {
        return plants.uploadWaits();
    }

    /**
     * Times each pass of the following frames on the GPU, or stops: with timer queries read a few frames
     * later and only when ready, so measuring never waits; on a software rasteriser (llvmpipe, whose timer
     * queries do not time passes) by the clock around {@code glFinish} after each pass, a diagnostic that
     * waits. Render thread; turning it on allocates the queries, a timed frame allocates nothing.
     *
     * @param on whether to time the passes
     */
    public void setPassTiming(boolean on) {
        gl.checkThread();
        timing.set(on);
    }

    /** {@return the passes' GPU times so far ({@link #setPassTiming}), or null while timing is off} Render thread. */
    public PassTimes passTimes() {
        return timing.times();
    }

    /** {@return the near ground-cover blades drawn by the last {@link #render}} */
    public int coverBlades() {
        return cover.blades();
    }

    /**
     * Draws one frame into the bound framebuffer, over a {@code width x height} viewport at its
     * origin: {@code glViewport(0, 0, width, height)} then {@link #render(Frame, Camera)}. The
     * viewport is put back on return like every other state. Render thread; no allocation in the
     * steady state.
     *
     * @param frame  the animation frame to show
     * @param camera the viewer (its aspect should be width / height)
     * @param width  viewport width, pixels, &gt; 0
     * @param height viewport height, pixels, &gt; 0
     * @throws IllegalArgumentException when the camera's eye or view-projection matrix is not finite
     */
    public void render(Frame frame, Camera camera, int width, int height) {
        gl.checkThread();
        Require.range("width", width, 1, 1 << 16);
        Require.range("height", height, 1, 1 << 16);
        Require.nonNull("frame", frame);
        Require.nonNull("camera", camera);
        Camera.requireFinite("camera", camera, cameraCheck);
        if (gl.follow() != generation) {
            rebuild();
        }
        state.save();
        try {
            glViewport(0, 0, width, height);
            draw(frame, camera, 0, 0, width, height);
        } finally {
            state.restore();
        }
    }

    /**
     * Draws one frame into whatever framebuffer and viewport are bound, so a game can draw its sky and
     * ground first, render into part of its window, and draw its HUD after. With
     * {@link RenderSettings#clear()} on, the viewport's rectangle is first cleared to the horizon colour
     * and depth 1 (a scissored clear) and the sky (gradient and sun) is drawn where no geometry is;
     * off, the plants are depth-tested against what is already in the depth buffer and no sky is drawn.
     * {@link RenderSettings#terrain()} says whether the library's own terrain is drawn; without it the
     * ground cover's skin is laid over the host's ground where the scene has cover
     * ({@link RenderSettings#coverSkin()}).
     *
     * <p>State contract (a good guest): every GL state this method changes is put back before it
     * returns, and every state the drawing depends on is set first, whatever the host left (blend
     * equation, colour mask, polygon offset and mode, depth function, front face, stencil, sampler
     * objects; see {@link GlStateGuard}). Plants write opaque alpha. The colours written are display
     * (sRGB) values, also into an sRGB framebuffer (its conversion is switched off while the library
     * draws), so a host with gamma correction shows the same picture as one without. The framebuffer
     * binding is the host's throughout, except while the sun's shadow map is drawn into its own
     * ({@link ShadowPath#MAP}), after which the host's draw and read framebuffers are bound again; the
     * host's scissor box clips the picture, not the map. The constructor and {@link #close()} keep the
     * same contract. Render thread; no allocation in the steady state (the shadow map and its programs
     * are made at the first frame that draws it).
     *
     * @param frame  the animation frame to show
     * @param camera the viewer (its projection's aspect should match the viewport's)
     * @throws IllegalArgumentException when the camera's eye or view-projection matrix is not finite
     */
    public void render(Frame frame, Camera camera) {
        gl.checkThread();
        Require.nonNull("frame", frame);
        Require.nonNull("camera", camera);
        Camera.requireFinite("camera", camera, cameraCheck);
        if (gl.follow() != generation) {
            rebuild();
        }
        state.save();
        try {
            draw(frame, camera, state.viewportX(), state.viewportY(), state.viewportWidth(),
                    state.viewportHeight());
        } finally {
            state.restore();
        }
    }

    /** The view-projection of the camera being checked ({@link Camera#requireFinite}). */
    private final org.joml.Matrix4f cameraCheck = new org.joml.Matrix4f();

    private void draw(Frame frame, Camera camera, int vx, int vy, int width, int height) {
        if (width <= 0 || height <= 0) {
            return;
        }
        if (!timing.on()) {
            drawPasses(frame, camera, vx, vy, width, height);
            return;
        }
        timing.begin();
        try {
            drawPasses(frame, camera, vx, vy, width, height);
        } finally {
            timing.end();
        }
    }

    private void drawPasses(Frame frame, Camera camera, int vx, int vy, int width, int height) {
        state.setGuestState();
        if (settings.clear()) {
            // the library owns the whole picture: the detail mask of its own framebuffer (draw buffer 1,
            // GlFramebuffer) is written too, for the resolve's filter
            org.lwjgl.opengl.GL30C.glColorMaski(1, true, true, true, true);
        }
        terrain.setTint(settings.tint());
        Lighting light = settings.lighting();
        FrameStart.begin(settings, vx, vy, width, height);
        // near plants first: the terrain drawn after them fails the early depth test behind them (less
        // shading on a software rasteriser); the far (line) level last, blended over both
        float lx = light.sunX();
        float ly = light.sunY();
        float lz = light.sunZ();
        // the ground maps first, so the cover blades and the terrain of this frame read the same shadows
        timing.mark(PassTimes.Pass.GROUND_MAPS);
        terrain.prepareShadows(settings);
        shadow.clear();
        boolean map = shadowPath() == ShadowPath.MAP && settings.shadows() > 0
                && ly >= Math.sin(SunShadow.MIN_ELEVATION);
        if (drawPlants || map) {
            // (without the plants on screen their shadows are still drawn: the ground as it is under them)
            plants.setLighting(light);
            plants.setPatches(settings.patchScale(), settings.patchStrength(), settings.patchSeed());
            plants.setSheen(settings.sheen());
            timing.mark(PassTimes.Pass.RESOLVE);
            plants.prepareNear(frame, camera, height);
            if (map) {
                timing.mark(PassTimes.Pass.SHADOW_MAP);
                shadowMap.draw(plants, settings, Math.min(settings.shadowReach(), castReach), camera, lx, ly, lz,
                        vx, vy, width, height);
            }
        }
        // without samples the near plants are blended by the share of a pixel they cover, writing depth:
        // the ground and the cover go first, so the plants' thin edges blend over them
        boolean blendedNear = drawPlants && plants.blendsNear();
        boolean withCover = drawPlants && terrain.prepareCover(settings);
        if (withCover) {
            cover.prepare(frame);
        }
        if (drawPlants && !blendedNear) {
            timing.mark(PassTimes.Pass.NEAR_PLANTS);
            plants.drawPreparedNear();
            if (withCover) {
                timing.mark(PassTimes.Pass.COVER);
                cover.draw(frame, camera, settings, terrain.maps());
            }
        }
        timing.mark(PassTimes.Pass.GROUND);
        ground.drawGround(camera, settings, terrain, cover, drawTerrain, drawPlants);
        if (blendedNear) {
            if (withCover) {
                timing.mark(PassTimes.Pass.COVER);
                cover.draw(frame, camera, settings, terrain.maps());
            }
            timing.mark(PassTimes.Pass.SKY);
            GroundPass.drawSky(sky, camera, settings); // under the plants' fringe, which writes no depth
            timing.mark(PassTimes.Pass.NEAR_PLANTS);
            plants.drawPreparedNear();
        } else {
            timing.mark(PassTimes.Pass.SKY);
            GroundPass.drawSky(sky, camera, settings);
        }
        if (drawPlants) {
            timing.mark(PassTimes.Pass.FAR_PLANTS);
            plants.drawFar();
        }
        glDisable(GL_DEPTH_TEST);
        OverlaySettings shown = settings.overlays();
        if (field != null && (shown.showField() || shown.showWind())) {
            timing.mark(PassTimes.Pass.OVERLAY);
            overlay.draw(field, camera, shown, vx, vy, width, height);
        }
    }

    /**
     * {@return the shadow path this renderer takes with its settings: {@link RenderSettings#shadowPath()},
     * or for {@link ShadowPath#AUTO} the map on a GPU and the ground splat on a software rasteriser}
     */
    public ShadowPath shadowPath() {
        return settings.shadowPath() == ShadowPath.AUTO ? autoShadows : settings.shadowPath();
    }

    /** {@return the number of triangles submitted by the last {@link #render}: plants plus terrain} */
    public long triangles() {
        return plants.batches().triangles() + terrain.triangles();
    }

    /** {@return the number of lines submitted by the last {@link #render} (plants)} */
    public long lines() {
        return plants.batches().lineCount();
    }

    /** A new context: forgets the old objects (no GL call, {@code GlTracker}) and makes them again. Allocates. */
    private void rebuild() {
        Closing.closeAll(ground, shadowMap, overlay, sky, plants, cover, terrain, state);
        boolean timed = timing.forget(); // its queries died with the old context: forgotten, not deleted
        build();
        timing.set(timed);
    }

    /**
     * Deletes every GL object of the renderers, leaving the host's state as it found it (a binding of
     * a deleted object would fall back to 0); after the context is gone ({@link GlContext#generation()}
     * changed) only forgets them, without a GL call. Render thread; idempotent.
     */
    @Override
    public void close() {
        if (!closed) {
            closed = true;
            boolean current = gl.generation() == generation; // else the context is gone: no GL call
            if (current) {
                state.save();
            }
            try {
                Closing.closeAll(current ? timing : null, ground, shadowMap, overlay, sky, plants, cover, terrain);
                timing.forget();
            } finally {
                if (current) {
                    state.restore();
                }
                state.close();
            }
        }
    }
}
