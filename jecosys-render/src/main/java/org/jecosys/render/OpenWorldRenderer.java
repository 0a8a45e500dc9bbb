package org.jecosys.render;

import static org.lwjgl.opengl.GL11C.glDepthMask;
import static org.lwjgl.opengl.GL11C.glViewport;

import java.util.Arrays;
import org.jecosys.math.Camera;
import org.jecosys.math.Require;
import org.jecosys.render.gl.Closing;
import org.jecosys.render.gl.GlStateGuard;
import org.jecosys.render.ground.OpenGround;
import org.jecosys.render.ground.SkyRenderer;
import org.jecosys.render.plant.PlantPrograms;
import org.jecosys.render.plant.PlantRenderer;
import org.jecosys.sim.OpenWorld;
import org.jecosys.sim.WorldTile;

/**
 * Draws the plants of an {@link OpenWorld}'s live tiles (issue 39, a first renderer of the open world):
 * one plant renderer per tile, all sharing the draw and resolve programs compiled once
 * ({@link PlantPrograms}), each drawing its tile's latest frame with the camera. A tile that became
 * live gets its renderer at a later frame, at most {@link #NEW_TILES_PER_FRAME} per frame (its
 * per-component data uploaded then), so a frame never uploads more than a few tiles; a tile let go
 * has its renderer closed at the next frame. With {@link RenderSettings#clear()} on the sky is drawn
 * first; with {@link RenderSettings#terrain()} on each tile's ground is drawn too (its heightfield, lit
 * in the ground cover's colour: {@code OpenGround}), else the ground is the host's (a game's terrain).
 * Components draw the world's images ({@code <component texture>}: the programs and the image array are
 * shared by every tile). Ground cover blades, contact darkening and sun shadows are not drawn yet.
 *
 * <p>Threads: the open world's stepping thread is the render thread (a game loop that steps, then
 * draws, on one thread with the context current); {@link #render} reads the live tiles the last step
 * left. State contract as {@code SceneRenderer}'s: every GL state changed is put back
 * ({@code GlStateGuard}). Allocation: a tile's renderer is made (allocating) when the tile arrives;
 * a frame without arriving or leaving tiles allocates nothing.
 */
public final class OpenWorldRenderer implements AutoCloseable {
    /** Most tile renderers made in one frame. */
    public static final int NEW_TILES_PER_FRAME = 2;

    private final GlContext gl;
    private final OpenWorld world;
    private final RenderSettings settings;
    private final PlantPrograms programs;
    private final OpenGround ground;
    private final SkyRenderer sky;
    private final GlStateGuard state;
    /** Per drawn tile, its ground mesh (made with its renderer). */
    private OpenGround.Mesh[] meshes = new OpenGround.Mesh[64];
    /** The tiles drawn, and their renderers (parallel; a tile's slot is null until its renderer is made). */
    private WorldTile[] tiles = new WorldTile[64];
    private PlantRenderer[] renderers = new PlantRenderer[64];
    private int count;
    private int made;
    private int drawn;
    private boolean closed;

    /**
     * Compiles the shared programs. Render thread (the open world's stepping thread), context current;
     * allocates; the GL state is put back.
     *
     * @param gl       the render context
     * @param world    the open world to draw
     * @param settings the light, haze and look (read each frame); clear and terrain as for a guest
     */
    public OpenWorldRenderer(GlContext gl, OpenWorld world, RenderSettings settings) {
        gl.checkThread();
        this.gl = gl;
        this.world = Require.nonNull("world", world);
        this.settings = Require.nonNull("settings", settings);
        GlStateGuard g = new GlStateGuard();
        g.save();
        PlantPrograms p = null;
        OpenGround o = null;
        try {
            g.setGuestState();
            p = PlantPrograms.compile(gl, null, world.plants().textures());
            o = new OpenGround(gl);
            sky = new SkyRenderer(gl);
        } catch (RuntimeException e) {
            Closing.closeAll(o, p);
            g.restore();
            g.close();
            throw e;
        }
        programs = p;
        ground = o;
        g.restore();
        state = g;
    }

    /**
     * Draws the live tiles' plants into the bound framebuffer's {@code width} x {@code height} viewport
     * at the origin. Render thread; no allocation in a frame where no tile arrives or leaves.
     *
     * @param camera the viewer (the step's camera, or another view registered with the open world)
     * @param width  viewport width, pixels, &gt; 0
     * @param height viewport height, pixels, &gt; 0
     */
    public void render(Camera camera, int width, int height) {
        gl.checkThread();
        Require.nonNull("camera", camera);
        Require.range("width", width, 1, 1 << 16);
        Require.range("height", height, 1, 1 << 16);
        if (closed) {
            throw new IllegalStateException("the open-world renderer is closed");
        }
        state.save();
        try {
            glViewport(0, 0, width, height);
            state.setGuestState();
            FrameStart.begin(settings, 0, 0, width, height);
            follow();
            Lighting light = settings.lighting();
            if (settings.clear()) {
                glDepthMask(false);
                sky.draw(camera, settings); // the whole picture first: the ground and plants cover it
                glDepthMask(true);
            }
            if (settings.terrain()) {
                float[] c = groundColour();
                ground.begin(camera, light, c[0], c[1], c[2]);
                for (int k = 0; k < count; k++) {
                    if (meshes[k] != null) {
                        meshes[k].draw();
                    }
                }
            }
            drawn = 0;
            for (int k = 0; k < count; k++) {
                PlantRenderer r = renderers[k];
                if (r == null) {
                    continue;
                }
                r.setLighting(settings.lighting());
                r.setSheen(settings.sheen());
                r.setPatches(settings.patchScale(), settings.patchStrength(), settings.patchSeed());
                r.draw(tiles[k].simulation().latestFrame(), camera, height);
                drawn++;
            }
        } finally {
            state.restore();
        }
    }

    /** The ground's colour: the scene's ground cover where it has one, else a meadow soil green (sRGB). */
    private float[] groundColour() {
        if (settings.groundCover() != null && settings.groundCover().amount() > 0) {
            org.jecosys.math.Rgb c = settings.groundCover().colour();
            groundColour[0] = (float) c.r();
            groundColour[1] = (float) c.g();
            groundColour[2] = (float) c.b();
        }
        return groundColour;
    }

    private final float[] groundColour = {0.29f, 0.40f, 0.20f};

    /** Closes the renderers of tiles let go, lists the new ones and makes a few of their renderers. */
    private void follow() {
        int live = world.liveTiles();
        // keep the drawn tiles that are still live, in the world's order
        int kept = 0;
        for (int k = 0; k < count; k++) {
            if (isLive(tiles[k], live)) {
                tiles[kept] = tiles[k];
                renderers[kept] = renderers[k];
                meshes[kept] = meshes[k];
                kept++;
            } else {
                Closing.closeAll(renderers[k], meshes[k]);
            }
        }
        Arrays.fill(tiles, kept, count, null);
        Arrays.fill(renderers, kept, count, null);
        Arrays.fill(meshes, kept, count, null);
        count = kept;
        for (int l = 0; l < live; l++) {
            WorldTile t = world.tile(l);
            if (indexOf(t) < 0) {
                if (count == tiles.length) {
                    tiles = Arrays.copyOf(tiles, 2 * count);
                    renderers = Arrays.copyOf(renderers, 2 * count);
                    meshes = Arrays.copyOf(meshes, 2 * count);
                }
                tiles[count++] = t;
            }
        }
        int budget = NEW_TILES_PER_FRAME;
        for (int k = 0; k < count && budget > 0; k++) {
            if (renderers[k] == null) {
                renderers[k] = new PlantRenderer(gl, tiles[k].world(), programs);
                meshes[k] = ground.mesh(tiles[k].world().terrain().heightfield());
                made++;
                budget--;
            }
        }
    }

    private boolean isLive(WorldTile t, int live) {
        for (int l = 0; l < live; l++) {
            if (world.tile(l) == t) {
                return true;
            }
        }
        return false;
    }

    private int indexOf(WorldTile t) {
        for (int k = 0; k < count; k++) {
            if (tiles[k] == t) {
                return k;
            }
        }
        return -1;
    }

    /** {@return the tiles with a renderer now} */
    public int tileRenderers() {
        int n = 0;
        for (int k = 0; k < count; k++) {
            n += renderers[k] != null ? 1 : 0;
        }
        return n;
    }

    /** {@return the tiles drawn in the last frame} */
    public int tilesDrawn() {
        return drawn;
    }

    /** {@return the tile renderers made so far} */
    public int renderersMade() {
        return made;
    }

    /** Closes every tile renderer and the shared programs. Render thread; idempotent; GL state put back. */
    @Override
    public void close() {
        if (closed) {
            return;
        }
        closed = true;
        state.save();
        try {
            for (int k = 0; k < count; k++) {
                Closing.closeAll(renderers[k], meshes[k]);
                renderers[k] = null;
                meshes[k] = null;
            }
            Closing.closeAll(sky, ground, programs);
        } finally {
            state.restore();
            state.close();
        }
    }
}
