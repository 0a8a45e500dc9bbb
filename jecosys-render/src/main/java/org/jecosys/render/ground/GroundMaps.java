package org.jecosys.render.ground;

import org.jecosys.render.Lighting;
import java.nio.ByteBuffer;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Future;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.ThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import org.jecosys.render.RenderSettings;
import org.jecosys.render.gl.GlTexture2D;
import org.jecosys.render.gl.GlTracker;
import org.jecosys.scene.RenderDef;
import org.jecosys.sim.World;
import org.lwjgl.system.MemoryUtil;

/**
 * The terrain's maps of what the plants do to the ground, on the contact-occlusion map's grid and in
 * one RGBA8 texture: red the contact occlusion ({@link ContactOcclusion}, built once), green where
 * the ground cover grows ({@link CoverMap}, rebuilt when its spread changes), blue the share of the
 * sun the plants' shadows take ({@link SunShadow}, rebuilt when the sun moves while shadows are on, 0
 * while they are off, so every reader may weigh it by {@code <light shadows>}).
 * Without plants the texture is a 2 x 2 of zeros. Render thread; the rebuilds allocate, nothing else
 * does. A sun that turns a little (a day passing) has its shadow map rebuilt on a worker thread
 * ({@value #WORKER_NAME}, started at the first such rebuild, ended after a few idle seconds) while the
 * frames go on with the map before; a larger turn, and the first map, are built at once.
 */
final class GroundMaps implements AutoCloseable {
    /** The grid and contact occlusion; null when built without plants. */
    final ContactOcclusion grid;
    private final World world;
    private final GlTexture2D texture;
    private float[] coverLevel;
    private double coverSpread = Double.NaN;
    private float[] shadow;
    /** The sun direction the shadow was built for (NaN: none yet). */
    private float shadowX = Float.NaN;
    private float shadowY = Float.NaN;
    private float shadowZ = Float.NaN;
    /** Shadow maps built so far, at once or started on the worker (tests). */
    private int shadowBuilds;
    /**
     * What the worker made: the shadow map, the texture's texels packed with it (direct memory the
     * collector frees, so that a build dropped half way leaks nothing) and the cover level packed.
     */
    private record Built(float[] shadow, ByteBuffer texels, float[] cover, float sunX, float sunY, float sunZ) {
    }

    /** The shadow map being built on the worker, or null. */
    private Future<Built> building;

    /** The name of the thread that rebuilds shadow maps for small turns of the sun. */
    static final String WORKER_NAME = "jecosys-ground-maps";

    /** One worker for every renderer's small rebuilds; its thread ends after 5 s without work. */
    private static final class Worker {
        static final ExecutorService POOL = new ThreadPoolExecutor(0, 1, 5, TimeUnit.SECONDS,
                new LinkedBlockingQueue<>(), r -> {
                    Thread t = new Thread(r, WORKER_NAME);
                    t.setDaemon(true);
                    return t;
                });
    }

    /**
     * Builds the contact occlusion of a world's plants and uploads it. Render thread; allocates.
     *
     * @param tracker counts the texture
     * @param world   the terrain and plants, or null for a bare terrain
     */
    GroundMaps(GlTracker tracker, World world) {
        this.world = world;
        grid = world == null ? null : ContactOcclusion.of(world);
        int w = grid == null ? 2 : grid.width;
        int h = grid == null ? 2 : grid.height;
        ByteBuffer texels = MemoryUtil.memCalloc(4 * w * h);
        try {
            texture = new GlTexture2D(tracker, w, h, 4, false, grid == null ? texels : grid.bytes(texels, null, null));
        } finally {
            MemoryUtil.memFree((java.nio.Buffer) texels);
        }
    }

    /** {@return the texture: contact occlusion (red), cover (green), sun shadow (blue)} */
    GlTexture2D texture() {
        return texture;
    }

    /**
     * {@return the cover map's mean level, in [0, 1]: what the ground beyond the terrain's square shows
     * (the map's rim, clamped, would smear into streaks toward the horizon); 0 before the map is built}
     * No allocation.
     */
    float meanCoverLevel() {
        if (coverLevel == null || coverLevel.length == 0) {
            return 0f;
        }
        if (coverMeanOf != coverLevel) {
            double sum = 0;
            for (float v : coverLevel) {
                sum += v;
            }
            coverMean = (float) (sum / coverLevel.length);
            coverMeanOf = coverLevel;
        }
        return coverMean;
    }

    private float coverMean;
    /** The map {@link #coverMean} was taken over. */
    private float[] coverMeanOf;

    /**
     * Makes sure the cover map matches the settings' ground cover (rebuilds it when its spread changed).
     *
     * @return whether there is cover to draw: it is enabled and there are plants
     */
    boolean prepareCover(RenderSettings settings) {
        RenderDef.GroundCover gc = settings.groundCover();
        if (!gc.enabled() || grid == null) {
            return false;
        }
        if (gc.spread() != coverSpread) {
            coverLevel = CoverMap.of(world, gc.spread(), grid.width, grid.height, grid.minX, grid.minZ, grid.texelX,
                    grid.texelZ).level;
            coverSpread = gc.spread();
            upload();
        }
        return true;
    }

    /**
     * Cosine of the least turn of the sun, 0.25 degrees, that rebuilds the shadow map: a game's sun that
     * moves a little every frame (a day passing) rebuilds it every so many frames, not at each one
     * (the map is made on the CPU). The sun's disc is about half a degree across.
     */
    static final double RESHADE_COS = Math.cos(Math.toRadians(0.25));
    /**
     * Cosine of the largest turn of the sun, 2 degrees, whose shadow map is rebuilt on the worker (the
     * frames meanwhile keep the map before, at most that far off); a larger turn rebuilds at once.
     */
    static final double WORKER_COS = Math.cos(Math.toRadians(2));

    /**
     * Makes sure the shadow map is of the settings' sun when shadows are on: rebuilt when the sun turned
     * by more than a quarter of a degree since it was made, on the worker up to 2 degrees (the map in use
     * is kept until the new one is done, taken in at a later call), at once beyond. Render thread.
     *
     * @return whether shadows are drawn: they are on, there are plants and the sun is high enough
     */
    boolean prepareShadows(RenderSettings settings) {
        if (settings.shadows() <= 0 || grid == null
                || Math.asin(Math.min(1, settings.lighting().sunY())) < SunShadow.MIN_ELEVATION) {
            dropBuild();
            if (shadow != null) { // shadows off: the blue channel goes back to 0 for every reader
                shadow = null;
                shadowX = Float.NaN;
                upload();
            }
            return false;
        }
        Lighting l = settings.lighting();
        if (building != null && building.isDone()) {
            adopt();
        }
        double turned = (double) l.sunX() * shadowX + (double) l.sunY() * shadowY + (double) l.sunZ() * shadowZ;
        if (shadow == null || !(turned >= WORKER_COS)) { // NaN (no map yet) builds at once too
            dropBuild();
            shadow = SunShadow.of(world, grid, l.sunX(), l.sunY(), l.sunZ());
            shadowBuilds++;
            shadowX = l.sunX();
            shadowY = l.sunY();
            shadowZ = l.sunZ();
            upload();
        } else if (!(turned >= RESHADE_COS) && building == null) {
            float x = l.sunX();
            float y = l.sunY();
            float z = l.sunZ();
            World w = world;
            ContactOcclusion g = grid;
            float[] cover = coverLevel; // replaced when rebuilt, never changed in place
            building = Worker.POOL.submit(() -> {
                float[] made = SunShadow.of(w, g, x, y, z);
                ByteBuffer texels = ByteBuffer.allocateDirect(4 * g.width * g.height);
                g.bytes(texels, cover, made);
                return new Built(made, texels, cover, x, y, z);
            });
            shadowBuilds++;
        }
        return true;
    }

    /** Drops the worker's build, if any (its result is let go). */
    private void dropBuild() {
        if (building != null) {
            building.cancel(false);
            building = null;
        }
    }

    /** Takes in the map the worker finished (waits for it when it is not done). */
    private void adopt() {
        Built made;
        try {
            made = building.get();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return;
        } catch (ExecutionException e) {
            building = null;
            throw new IllegalStateException("building the sun shadow map failed: " + e.getCause(), e.getCause());
        }
        building = null;
        shadow = made.shadow();
        shadowX = made.sunX();
        shadowY = made.sunY();
        shadowZ = made.sunZ();
        if (made.cover() == coverLevel) {
            texture.upload(made.texels()); // packed on the worker: only the copy to the GL here
        } else {
            upload(); // the cover changed meanwhile
        }
    }

    /** Waits for the map the worker is building, if any, and takes it in (tests). Render thread. */
    void awaitShadows() {
        if (building != null) {
            adopt();
        }
    }

    /** {@return whether the worker is building a shadow map not taken in yet (tests)} */
    boolean shadowPending() {
        return building != null;
    }

    /** {@return the shadow map in use, or null (tests)} */
    float[] shadow() {
        return shadow;
    }

    /** {@return the sun shadow maps built so far: tests} */
    int shadowBuilds() {
        return shadowBuilds;
    }

    private void upload() {
        ByteBuffer texels = MemoryUtil.memAlloc(4 * grid.width * grid.height);
        try {
            texture.upload(grid.bytes(texels, coverLevel, shadow));
        } finally {
            MemoryUtil.memFree((java.nio.Buffer) texels);
        }
    }

    @Override
    public void close() {
        dropBuild();
        texture.close();
    }
}
