package org.jecosys.render;

import org.jecosys.render.gl.Closing;
import static org.lwjgl.opengl.GL11C.GL_COLOR_BUFFER_BIT;
import static org.lwjgl.opengl.GL11C.GL_CULL_FACE;
import static org.lwjgl.opengl.GL11C.GL_DEPTH_BUFFER_BIT;
import static org.lwjgl.opengl.GL11C.GL_DEPTH_TEST;
import static org.lwjgl.opengl.GL11C.GL_LEQUAL;
import static org.lwjgl.opengl.GL11C.glClear;
import static org.lwjgl.opengl.GL11C.glClearColor;
import static org.lwjgl.opengl.GL11C.glDepthFunc;
import static org.lwjgl.opengl.GL11C.glDisable;
import static org.lwjgl.opengl.GL11C.glEnable;
import static org.lwjgl.opengl.GL11C.glViewport;
import static org.lwjgl.opengl.GL11C.GL_BLEND;
import static org.lwjgl.opengl.GL11C.GL_SCISSOR_TEST;
import static org.lwjgl.opengl.GL11C.glDepthMask;
import static org.lwjgl.opengl.GL11C.glScissor;

import org.jecosys.field.FieldDebugView;
import org.jecosys.math.Require;
import org.jecosys.math.Rgb;
import org.jecosys.math.Camera;
import org.jecosys.sim.Frame;
import org.jecosys.sim.World;
import org.jecosys.render.gl.GlFramebuffer;
import org.jecosys.render.gl.GlStateGuard;
import org.jecosys.render.ground.SkyRenderer;
import org.jecosys.render.ground.CoverBlades;
import org.jecosys.render.ground.TerrainRenderer;
import org.jecosys.render.overlay.FieldOverlay;
import org.jecosys.render.plant.PlantRenderer;
import org.jecosys.render.plant.ResolvePath;

/**
 * Renders a whole frame of a {@link World}: sky (gradient and sun), plants, lit terrain and the
 * optional force-field overlays, into the currently bound framebuffer and viewport (a window's, a
 * game's own or a {@link GlFramebuffer}), and puts back every GL state it changed (see
 * {@link #render(Frame, Camera)}). Owns the sky, terrain, plant and overlay renderers. Render thread only; {@link #render} allocates nothing in the
 * steady state (changing the tint or LOD band re-uploads or rebuilds once).
 */
public final class SceneRenderer implements AutoCloseable {
    private final GlContext gl;
    private final RenderSettings settings;
    private final World world;
    private final TerrainRenderer terrain;
    private final CoverBlades cover;
    private final PlantRenderer plants;
    private final SkyRenderer sky;
    private final FieldOverlay overlay;
    private FieldDebugView field;
    private final GlStateGuard state;
    private boolean closed;
    /** Benchmark breakdown only (package-private): skip the terrain or the plants. */
    boolean drawTerrain = true;
    boolean drawPlants = true;

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
     * pass on the path named (see {@link PlantRenderer#PlantRenderer(GlContext, World, ResolvePath)}).
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

    /** {@return the plant renderer (its batches hold the per-frame counters)} */
    public PlantRenderer plants() {
        return plants;
    }

    /** {@return the terrain renderer} */
    public TerrainRenderer terrain() {
        return terrain;
    }

    /** {@return the near ground-cover renderer (its counters: tiles and blades of the last frame)} */
    public CoverBlades cover() {
        return cover;
    }

    /** {@return the overlay renderer} */
    public FieldOverlay overlay() {
        return overlay;
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
     */
    public void render(Frame frame, Camera camera, int width, int height) {
        gl.checkThread();
        Require.range("width", width, 1, 1 << 16);
        Require.range("height", height, 1, 1 << 16);
        Require.nonNull("frame", frame);
        Require.nonNull("camera", camera);
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
     * {@link RenderSettings#terrain()} says whether the library's own terrain is drawn.
     *
     * <p>State contract (a good guest): every GL state this method changes is put back before it
     * returns, and every state the drawing depends on is set first, whatever the host left (blend
     * equation, colour mask, polygon offset and mode, depth function, front face, stencil, sampler
     * objects; see {@link GlStateGuard}). Plants write opaque alpha. The colours written are display
     * (sRGB) values, also into an sRGB framebuffer (its conversion is switched off while the library
     * draws), so a host with gamma correction shows the same picture as one without. The framebuffer
     * binding is never changed; the constructor and {@link #close()} keep the same contract. Render
     * thread; no allocation in the steady state.
     *
     * @param frame  the animation frame to show
     * @param camera the viewer (its projection's aspect should match the viewport's)
     */
    public void render(Frame frame, Camera camera) {
        gl.checkThread();
        Require.nonNull("frame", frame);
        Require.nonNull("camera", camera);
        state.save();
        try {
            draw(frame, camera, state.viewportX(), state.viewportY(), state.viewportWidth(),
                    state.viewportHeight());
        } finally {
            state.restore();
        }
    }

    private void draw(Frame frame, Camera camera, int vx, int vy, int width, int height) {
        if (width <= 0 || height <= 0) {
            return;
        }
        state.setGuestState();
        if (settings.clear()) {
            // the library owns the whole picture: the detail mask of its own framebuffer (draw buffer 1,
            // GlFramebuffer) is written too, for the resolve's filter
            org.lwjgl.opengl.GL30C.glColorMaski(1, true, true, true, true);
        }
        terrain.setTint(settings.tint());
        Rgb horizon = settings.sky();
        if (settings.clear()) {
            glEnable(GL_SCISSOR_TEST);
            glScissor(vx, vy, width, height);
            glClearColor(horizon.r(), horizon.g(), horizon.b(), 1f);
            glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
            glDisable(GL_SCISSOR_TEST);
        }
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LEQUAL);
        glDepthMask(true);
        glDisable(GL_CULL_FACE);
        glDisable(GL_BLEND);
        // near plants first: the terrain drawn after them fails the early depth test behind them (less
        // shading on a software rasteriser); the far (line) level last, blended over both
        float lx = settings.sunX();
        float ly = settings.sunY();
        float lz = settings.sunZ();
        // the ground maps first, so the cover blades and the terrain of this frame read the same shadows
        terrain.prepareShadows(settings);
        if (drawPlants) {
            plants.setLight(settings.sunColour(), settings.sunIntensity(), settings.ambient());
            plants.setPatches(settings.patchScale(), settings.patchStrength(), settings.patchSeed());
            plants.setSheen(settings.sheen());
            plants.drawNear(frame, camera, lx, ly, lz, horizon, settings.fogStart(), settings.fogEnd(), height);
            if (terrain.prepareCover(settings)) {
                cover.prepare(frame);
                cover.draw(frame, camera, settings, terrain.maps());
            }
        }
        if (drawTerrain && settings.terrain()) {
            terrain.draw(camera, settings, drawPlants);
        }
        if (settings.clear()) {
            // the sky where nothing is (depth still 1), before the blended far level
            glDepthMask(false);
            this.sky.draw(camera, settings);
            glDepthMask(true);
        }
        if (drawPlants) {
            plants.drawFar();
        }
        glDisable(GL_DEPTH_TEST);
        if (field != null && (settings.showField() || settings.showWind())) {
            overlay.draw(field, camera, settings.showField(), settings.showWind(), vx, vy, width, height);
        }
    }

    /** {@return the number of triangles submitted by the last {@link #render}: plants plus terrain} */
    public long triangles() {
        return plants.batches().triangles() + terrain.triangles();
    }

    /** {@return the number of lines submitted by the last {@link #render} (plants)} */
    public long lines() {
        return plants.batches().lineCount();
    }

    /**
     * Deletes every GL object of the renderers, leaving the host's state as it found it (a binding of
     * a deleted object would fall back to 0). Render thread; idempotent.
     */
    @Override
    public void close() {
        if (!closed) {
            closed = true;
            state.save();
            try {
                Closing.closeAll(overlay, sky, plants, cover, terrain);
            } finally {
                state.restore();
                state.close();
            }
        }
    }
}
