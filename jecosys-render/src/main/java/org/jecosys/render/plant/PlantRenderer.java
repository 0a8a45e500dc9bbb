package org.jecosys.render.plant;

import java.nio.FloatBuffer;
import java.util.List;
import org.jecosys.math.Camera;
import org.jecosys.math.Require;
import org.jecosys.plant.SpeciesModel;
import org.jecosys.render.GlContext;
import org.jecosys.render.Lighting;
import org.jecosys.render.RenderSettings;
import org.jecosys.render.ResolvePath;
import org.jecosys.render.ground.ShadowParams;
import org.jecosys.render.ground.SunShadowMap;
import org.jecosys.sim.Frame;
import org.jecosys.sim.ViewDecision;
import org.jecosys.sim.World;

/**
 * Draws every plant of a {@link World} from a {@link Frame} (paper §4.1-4.2; see also
 * docs/ARCHITECTURE.md, "Rendering").
 * At construction every pose table goes to the GPU once (a buffer texture, 3 RGBA32F texels per
 * skeleton point) with one mesh per species and level (the component colour and the fraction along
 * the component baked into each vertex), and static per-component data (root bases, pose texels,
 * parents). Per frame, {@link #draw} draws what the frame's decision lists ({@link PlantBatches}),
 * uploads only the render states the animation workers wrote for the drawn plants (8 bytes per
 * component) and 8 bytes per drawn plant and level, resolves on the GPU (a compute shader on
 * OpenGL 4.3 hardware, transform feedback on 3.3 and on software rasterisers: {@link ResolvePath})
 * each drawn component's record (3 texels: base, cos/sin of the bend azimuth, pose texel and
 * weight, dither window, and its colour variation: hue turn, brightness, patch dryness, worked out on
 * the CPU only when the look changes; for a line level what its vertices share instead of the
 * variation), then issues per species and
 * level (triangles near, lines far: Table 3) one instanced draw of the plants drawn whole and one
 * of those in a transition band, the only ones whose shaders have the dither test (programs
 * compiled with {@code DITHER}; species with flower parts use the {@code FLOWERS} variants). Triangle
 * levels use {@code plant.vert} (lit ribbons); line levels use {@code plant_line.vert}, which places
 * and lights the same vertices and writes one flat colour per segment, with the share of a pixel the
 * leaf's true width covers as opacity: the line levels are drawn last, blended
 * over the opaque scene ({@link #drawNear}, your terrain, {@link #drawFar}), so far grass has the
 * coverage and colour of the triangle level just nearer instead of one solid pixel per leaf edge.
 * Parts: GL objects and upload layout {@code PlantGpu}; per-component uploads and resolve pass
 * {@code ComponentResolver}; draws {@code PlantPasses}; the passes' shared values {@code PassContext};
 * the camera and target prepared for {@code NearView}; the core's reach {@code CoreReach}.
 *
 * <p>Render thread only; {@link #draw} allocates nothing. Owns its GL objects; {@link #close()} is
 * idempotent, and a constructor that fails part way releases what it had made.
 */
public final class PlantRenderer implements AutoCloseable {
    /** Floats per component record (3 RGBA32F texels), written by the resolve pass. */
    public static final int RECORD_FLOATS = 12;
    /** Largest index a float holds exactly (texels and components passed as floats). */
    public static final int MAX_EXACT = 1 << 24;
    /** Default least width of a thin part, pixels. */
    public static final float DEFAULT_MIN_PIXELS = 1.75f;
    /** Default least size of a flower part, pixels. */
    public static final float DEFAULT_HEAD_PIXELS = 8.0f;
    /**
     * The picture height, pixels, at which flower parts are kept at least {@code headPixels} across
     * ({@link #setThinParts}); in a picture of another height the least size scales with it, so a
     * flower takes the same share of the view at any resolution (half the size in a picture half as high).
     */
    public static final int HEAD_REFERENCE_HEIGHT = 540;
    /** Default turn of flower parts toward the viewer, degrees. */
    public static final float DEFAULT_FLOWER_TILT = 45f;

    private final World world;
    private final PlantBatches batches;
    private final PlantGpu gpu;
    /** The camera and target the near plants are prepared for: their decision and view values. */
    private final NearView near;
    private final PlantPasses passes;
    private final PlantLook look;
    /** The last {@link #prepareNear}'s view, light, haze, pixel size and frame, for the passes after it. */
    private final PassContext context;
    private boolean pending;
    /** For the bench's breakdown only: bit l set = draw level l (lists are still uploaded). */
    private int levelMask = ~0;
    private boolean closed;
    /** How partial coverage goes on the target: blended (core, fringe) or alpha-to-coverage. */
    private final CoverageDraws coverage;

    /**
     * Uploads pose tables and meshes, and preallocates the per-frame buffers. Render thread;
     * allocates. If it throws, every GL object it had made is deleted again.
     *
     * <p>The per-component pass runs on the {@link ResolvePath} that is faster on this context
     * ({@link ResolvePath#best(org.lwjgl.opengl.GLCapabilities, String)}: compute on OpenGL 4.3
     * hardware, transform feedback on 3.3 and on software rasterisers), or on
     * {@link ResolvePath#TRANSFORM_FEEDBACK} when the world's records would not fit one shader
     * storage buffer of this context.
     *
     * @param gl        the render context, current on this thread
     * @param world     the plants: species models (pose tables, meshes) and positions
     */
    public PlantRenderer(GlContext gl, World world) {
        this(gl, world, (ResolvePath) null);
    }

    /**
     * As {@link #PlantRenderer(GlContext, World)}, with the per-component pass on the path named.
     * Render thread; allocates.
     *
     * @param gl    the render context, current on this thread
     * @param world the plants
     * @param path  the path of the per-component pass; null: the one {@link #PlantRenderer(GlContext,
     *              World)} chooses
     * @throws IllegalArgumentException when the context cannot run {@code path} (compute needs
     *                                  OpenGL 4.3 and a shader storage buffer the size of the records)
     */
    public PlantRenderer(GlContext gl, World world, ResolvePath path) {
        this(gl, world, path, null);
    }

    /**
     * As {@link #PlantRenderer(GlContext, World)}, with its draw and resolve programs taken from
     * {@code programs} (compiled once for this context; the caller closes them after this renderer):
     * what an open world's tile renderers share. Render thread; allocates.
     *
     * @param gl       the render context, current on this thread
     * @param world    the plants
     * @param programs the shared programs
     */
    public PlantRenderer(GlContext gl, World world, PlantPrograms programs) {
        this(gl, world, programs.path(), programs);
    }

    private PlantRenderer(GlContext gl, World world, ResolvePath path, PlantPrograms shared) {
        gl.checkThread();
        this.world = world;
        this.batches = new PlantBatches(world);
        ViewDecision view = new ViewDecision(world);
        List<SpeciesModel> models = world.plants().species();
        gpu = new PlantGpu(gl, world, batches, path, shared);
        boolean[] flowers = PlantMeshes.flowerParts(models);
        NearView n = null;
        try {
            n = new NearView(view, new CoreReach(models, batches));
            // the draw programs' uniforms last: Mesa keeps a transform-feedback program that was left in
            // use here alive past its deletion
            passes = new PlantPasses(gpu.programs, flowers);
            coverage = new CoverageDraws();
        } catch (RuntimeException | Error e) {
            if (n != null) {
                n.close();
            }
            gpu.close();
            throw e;
        }
        near = n;
        context = new PassContext();
        context.viewProj = near.matrix;
        look = new PlantLook(models.size());
        look.setVariations(models);
    }

    /** {@return the path the per-component pass runs on, for the HUD and reports} */
    public ResolvePath path() {
        return gpu.resolver.path();
    }

    /**
     * Sets the strength of the wind's sheen: how much a blade bent by the wind brightens toward its pale,
     * sky-lit side (0 off, 1 the default look). Render thread; no allocation.
     *
     * @param strength in [0, 2]
     */
    public void setSheen(float strength) {
        look.sheen = (float) Require.range("sheen", strength, 0, 2);
    }

    /**
     * Sets the light and haze the next {@link #prepareNear} draws the plants in: the sun's direction
     * and its colour times its intensity, the sky's ambient light, and the haze toward the sky's
     * horizon colour from {@link Lighting#fogStart()} to {@link Lighting#fogEnd()} (values copied).
     * {@code SceneRenderer} sets it from its {@link RenderSettings#lighting()} every frame. Render
     * thread; no allocation.
     *
     * @param light the light, not null
     */
    public void setLighting(Lighting light) {
        Require.nonNull("light", light);
        float k = light.sunIntensity();
        look.setLight(light.sunR() * k, light.sunG() * k, light.sunB() * k, light.ambientR(), light.ambientG(),
                light.ambientB());
        context.setLight(light.sunX(), light.sunY(), light.sunZ());
        context.setFog(light.skyR(), light.skyG(), light.skyB(), light.fogStart(), light.fogEnd());
    }

    /**
     * Sets the colour variation of species {@code s}: per plant (and, a third as much, per
     * component) a hue turn and a brightness factor drawn about-normally with these standard
     * deviations, and straw-coloured tips. A change of the hue or brightness spread makes the next
     * draw work out every component's look again on the render thread (about 35 ns a component:
     * 15 ms for the meadow, 140 ms for 4 million components, measured on llvmpipe's 2-core machine);
     * setting the same values again costs nothing. Render thread; no allocation.
     *
     * @param s        species index in the world, in [0, species count)
     * @param hueDeg   standard deviation of the hue turn, degrees, in [0, 60]
     * @param value    standard deviation of the brightness factor, in [0, 1]
     * @param dryTips  how far the tips turn toward straw, in [0, 1]
     * @throws IllegalArgumentException when an argument is out of range
     */
    public void setVariation(int s, float hueDeg, float value, float dryTips) {
        look.setVariation(s, hueDeg, value, dryTips);
    }

    /**
     * Sets the healthy/dry patches: the ground's patch noise ({@link RenderSettings#patchLevel}), of
     * feature size {@code scale}, turns blades toward straw where it is high, by up to
     * {@code strength}. The seed also picks each plant's colour variation. {@code SceneRenderer} sets
     * it from its {@link RenderSettings} every frame; a change makes the next draw work out every
     * component's look again, as {@link #setVariation} says. Render thread; no allocation.
     *
     * @param scale    patch size, metres, in [0.5, 1000]
     * @param strength how dry the driest patches get, in [0, 1] (0: no patches)
     * @param seed     any integer
     * @throws IllegalArgumentException when an argument is out of range
     */
    public void setPatches(float scale, float strength, int seed) {
        look.setPatches(scale, strength, seed);
    }

    /**
     * Sets how thin parts are kept visible: blades and stems are widened across the view to at
     * least {@code minPixels} (their real share of that width becomes coverage, which
     * multisampling turns into partly covered pixels), flower parts are scaled up to at least
     * {@code headPixels} across in a picture {@link #HEAD_REFERENCE_HEIGHT} pixels high (in proportion
     * in any other: the same share of the view) and turned toward the viewer by {@code flowerTiltDeg}.
     * Render thread; no allocation.
     *
     * @param minPixels     least width of blades and stems, pixels, in [0, 8] (0: off)
     * @param headPixels    least size of flower parts, pixels of a 540-pixel-high picture, in [0, 32] (0: off)
     * @param flowerTiltDeg turn of flower parts toward the viewer, degrees, in [0, 90]
     * @throws IllegalArgumentException when an argument is out of range
     */
    public void setThinParts(float minPixels, float headPixels, float flowerTiltDeg) {
        Require.range("minPixels", minPixels, 0, 8);
        Require.range("headPixels", headPixels, 0, 32);
        Require.range("flowerTilt", flowerTiltDeg, 0, 90);
        look.setThinParts(minPixels, headPixels, (float) Math.toRadians(flowerTiltDeg));
    }

    /**
     * Sets which levels are drawn, for the benchmark's breakdown of the draw time by level (the lists
     * are still built and uploaded). Render thread; no allocation.
     *
     * @param mask bit l set: draw level l; {@code ~0} (the default) draws every level
     */
    public void setLevelMask(int mask) {
        levelMask = mask;
    }

    /** {@return the GL-free lists, LOD choice and counters (read them after {@link #draw})} */
    public PlantBatches batches() {
        return batches;
    }

    /**
     * {@return the number of instanced draw calls issued by the last {@link #draw}} Where thin parts are
     * blended ({@link #blendsNear()}) the near lists are drawn a second time for their fringe
     * ({@link #drawPreparedNear}), not counted here.
     */
    public int drawCalls() {
        return passes.draws();
    }

    /** {@return the instances (plants at a level) drawn by the last {@link #draw}: tests} */
    public long instancesDrawn() {
        return passes.instances();
    }

    /**
     * Culls, chooses levels, uploads the per-instance data of {@code frame} and draws every level:
     * {@link #drawNear} then {@link #drawFar}, lit from {@link #setSunDirection} and hazed as
     * {@link #setHaze} says. Draw your opaque geometry (terrain) before this, since the far level is
     * blended without writing depth. Render thread; no allocation.
     *
     * @param frame          the frame to show (sizes match the world)
     * @param camera         the viewer
     * @param viewportHeight height of the viewport drawn into, pixels, &gt; 0 (see {@link #drawNear})
     * @throws IllegalArgumentException when the frame's size does not match the world or the
     *                                  viewport height is out of range
     */
    public void draw(Frame frame, Camera camera, int viewportHeight) {
        drawNear(frame, camera, viewportHeight);
        drawFar();
    }

    /**
     * Plants in a level-switch or thinning band are drawn whole at one level, not dithered over two,
     * when the bound target has fewer samples per pixel than this (default 2: on a back buffer without
     * multisampling, where the dither would show as a checker; {@link PlantBatches#setWholePlants}).
     * 0 dithers always. Render thread; no allocation.
     *
     * @param minSamples in [0, 64]
     */
    public void setWholePlantsBelow(int minSamples) {
        near.wholePlantsBelow = Require.range("minSamples", minSamples, 0, 64);
    }

    /**
     * Culls, chooses levels, uploads the per-instance data of {@code frame} and draws the triangle
     * (near) levels, opaque, writing depth. For the camera the frame's decision was made for (the one
     * its step followed) it draws that decision as it is; for any other camera it decides first
     * ({@link ViewDecision}: the frustum and levels of that camera, by projected size), so split
     * screens, minimaps, shadow passes and the first frame after a camera cut are drawn complete.
     * Follow it in the same frame with your opaque geometry and then {@link #drawFar}. Render thread;
     * no allocation.
     *
     * @param frame          the frame to show (sizes match the world)
     * @param camera         the viewer
     * @param viewportHeight height of the viewport drawn into, pixels, &gt; 0: far away a line is
     *                       wider than the leaf it stands for, and the line level is drawn with the
     *                       share of a pixel the leaf covers as its opacity
     */
    public void drawNear(Frame frame, Camera camera, int viewportHeight) {
        prepareNear(frame, camera, viewportHeight);
        drawPreparedNear();
    }

    /**
     * The first half of {@link #drawNear}: culls, chooses levels, uploads and resolves what the frame
     * draws for this camera and sets the draw programs' uniforms, drawing nothing yet, so the resolved
     * plants can first be drawn into the sun's shadow map ({@link #drawCasters}). Follow it in the same
     * frame with {@link #drawPreparedNear}. Arguments as {@link #drawNear}. Render thread; no allocation.
     */
    public void prepareNear(Frame frame, Camera camera, int viewportHeight) {
        if (frame.componentCount() != world.componentCount()) {
            throw new IllegalArgumentException("frame has " + frame.componentCount() + " components, the world "
                    + world.componentCount());
        }
        Require.range("viewportHeight", viewportHeight, 1, 1 << 16);
        int targetSamples = near.target(batches);
        near.coreless(coverage.twoPassesOnSamples(targetSamples > 1), camera, viewportHeight, look.minPixels, frame, batches);
        near.decide(frame, camera, batches);
        passes.resetCounts();
        pending = batches.instances() > 0;
        context.frame = frame;
        if (!pending) {
            return;
        }
        gpu.resolver.upload(frame);
        near.setCamera(camera, viewportHeight, context);
        gpu.resolver.frame(look, context);
        gpu.resolver.resolve(look);
        context.multisampled = targetSamples > 1;
        passes.frame(look, context);
    }

    /**
     * Draws the triangle levels of the last {@link #prepareNear} into the bound shadow map's framebuffer,
     * seen from the sun (depth only; the caster programs are compiled at the first call). Nothing if
     * nothing is in view. The caller binds the map, clears it and puts its own framebuffer back.
     * Render thread; allocates only at the first call.
     *
     * @param shadow the map, fitted to this frame's view and sun
     */
    public void drawCasters(SunShadowMap shadow) {
        if (!pending) {
            return;
        }
        if (!passes.hasCasters()) {
            gpu.compileCasters(passes);
            passes.frame(look, context); // this frame's values onto the new programs
        }
        passes.casterFrame(look, shadow.placement(), context);
        gpu.bindForDraws();
        passes.drawCasters(batches, gpu.vaos, gpu.indexCount, look, levelMask);
    }

    /**
     * Reads the sun's shadow map from this holder at every {@link #drawPreparedNear} from now on
     * ({@code sun_shadow.glsl}; the map bound to {@code TextureUnits.SUN_SHADOW} by the caller, who
     * fills the holder each frame). Until then no map is read. Render thread; no allocation.
     *
     * @param params the frame's shadow map, kept (not copied)
     * @throws IllegalArgumentException when params is null
     */
    public void useShadowMap(ShadowParams params) {
        look.shadow = Require.nonNull("params", params);
    }

    /**
     * {@return whether {@link #drawPreparedNear} blends the near plants' thin parts by the share of a
     * pixel they cover on the target the last {@link #prepareNear} found (always, unless
     * {@link #setBlendOnSamples} is off and the target is multisampled): draw the ground before them then,
     * so their thin parts blend over it} Render thread; no allocation.
     */
    public boolean blendsNear() {
        return coverage.blends(context);
    }

    /**
     * How a multisampled target gets the share of a pixel a thin part covers. On (the default) as on a
     * target without samples: an opaque core writes depth, and the thin parts and far lines blend by the
     * share they cover over what is there, each on the samples its geometry covers; the plants then
     * weigh in the picture what they cover, whether the target has samples or not ({@link #blendsNear()}
     * is then true: draw the ground first). Off, the GL's alpha-to-coverage: every part with the same
     * share takes the same samples, so thin parts overlapping in a pixel count once (on llvmpipe a
     * 4-sample meadow then weighs about a quarter less than the truth); the plants go first, before
     * the ground, and hide it from the depth test. Render thread; no allocation.
     *
     * @param on whether to blend thin parts on multisampled targets
     */
    public void setBlendOnSamples(boolean on) {
        coverage.setBlendOnSamples(on);
    }

    /**
     * On a multisampled target that blends thin parts ({@link #setBlendOnSamples}), how the two passes
     * of the near plants keep the core and the fringe apart: on (the default), the ordinary programs,
     * the core's alpha cut to 0 or 1 through alpha-to-coverage, the fringe behind a strict depth test,
     * with no discard (cheaper on a software rasteriser); off, the split programs, as on a target
     * without samples. The picture is the same. Render thread; no allocation.
     *
     * @param on whether to cut the core's alpha rather than use the split programs
     */
    public void setCoreCut(boolean on) {
        coverage.setCoreCut(on);
    }

    /**
     * With the core cut ({@link #setCoreCut}), whether its pass leaves out whole the plants its lists
     * hold as having no core where they stand ({@link PlantBatches#coreless}; on, the default) or draws
     * them and lets the vertex shader leave out each of their vertices. The picture is the same (the
     * fringe's order is that of the lists either way). Render thread; no allocation.
     */
    public void setLeaveOutCoreless(boolean on) {
        passes.setLeaveOutCoreless(on);
    }

    /**
     * The second half of {@link #drawNear}: draws the triangle (near) levels the last
     * {@link #prepareNear} resolved: an opaque core writing depth, then the thin parts blended by the
     * share of a pixel they cover over what is there, on the samples their geometry covers when
     * multisampled ({@link #blendsNear()}: draw the ground first), so a blade narrower than a pixel
     * weighs what it covers rather than a whole pixel. With {@link #setBlendOnSamples} off, a
     * multisampled target gets alpha-to-coverage and opaque plants instead. Render thread; no allocation.
     */
    public void drawPreparedNear() {
        if (!pending) {
            return;
        }
        passes.shadow(look);
        gpu.bindForDraws();
        coverage.near(context, gpu, passes, batches, look, levelMask);
    }

    /**
     * Draws the line (far) levels of the last {@link #drawNear}: blended by the share of a pixel each
     * leaf covers, depth tested but not written, so call it after the opaque geometry. Does nothing
     * if nothing is in view. Render thread; no allocation.
     */
    public void drawFar() {
        if (!pending) {
            return;
        }
        pending = false;
        gpu.bindForDraws();
        coverage.far(context, gpu, passes, batches, look, levelMask);
    }

    /**
     * Reads back the component records of the last {@link #drawNear} (tests). Render thread; waits
     * for the GPU.
     */
    public void readRecords(FloatBuffer dest) {
        gpu.resolver.readRecords(dest);
    }

    /** {@return bytes uploaded by the last {@link #drawNear}: instance records and component render states} */
    public long uploadedBytes() {
        return gpu.resolver.uploadedBytes();
    }

    /** {@return whether the per-frame uploads go through a mapped ring (see {@link ComponentResolver#uploadRing})} */
    public boolean uploadRing() {
        return gpu.resolver.uploadRing();
    }

    /** {@return frames that waited for their upload region (see {@link ComponentResolver#uploadWaits})} */
    public long uploadWaits() {
        return gpu.resolver.uploadWaits();
    }

    /** Deletes every GL object and frees the staging memory. Render thread; idempotent. */
    @Override
    public void close() {
        if (closed) {
            return;
        }
        closed = true;
        gpu.close();
        near.close();
    }

    /** {@return the pose buffer's layout, see {@link PlantMeshes#poseTexelLayout}} (tests and benchmarks) */
    public static long poseTexelLayout(List<SpeciesModel> models, int[][][] first) {
        return PlantMeshes.poseTexelLayout(models, first);
    }
}
