package org.jecosys.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.jecosys.render.GlContext.DebugOutput;
import java.nio.ByteBuffer;
import java.nio.file.Path;
import java.util.List;
import org.jecosys.field.ForceFieldDef;
import org.jecosys.field.QuadtreeForceField;
import org.jecosys.math.Rgb;
import org.jecosys.math.ViewCamera;
import org.jecosys.plant.Primitive;
import org.jecosys.plant.SpeciesModel;
import org.jecosys.scene.SceneDef;
import org.jecosys.sim.Frame;
import org.jecosys.sim.World;
import org.jecosys.terrain.Heightfield;
import org.jecosys.wind.FlowDef;
import org.jecosys.wind.WindField;
import org.joml.Vector4f;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestInstance;
import org.lwjgl.system.MemoryUtil;
import org.jecosys.render.gl.GlFramebuffer;
import org.jecosys.render.gl.Pixels;
import org.jecosys.render.overlay.FieldOverlay;
import org.jecosys.render.plant.PlantBatches;
import org.junit.jupiter.api.Tag;

/**
 * Headless rendering of scene C1 (paper Table 4) through GLFW's null platform and EGL (Mesa llvmpipe
 * here and on CI), read back with glReadPixels. KHR_debug is on: any GL error fails the test.
 */
@Tag("lwjgl-compat")
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
class RenderC1Test {
    private static final int W = 320;
    private static final int H = 200;
    private static final Rgb SKY = new Rgb(0.62f, 0.76f, 0.92f);

    private SceneDef def;
    private World world;
    private GlContext gl;
    private GlFramebuffer fb;
    private SceneRenderer renderer;
    private ByteBuffer px;
    private ByteBuffer other;

    @BeforeAll
    void setUp() {
        def = RenderScenes.load("c1.xml");
        world = RenderScenes.build(def);
        gl = GlContext.headless(DebugOutput.ON);
        fb = new GlFramebuffer(gl.tracker(), W, H);
        // a flat sky (zenith = horizon, no sun glow), so that every sky pixel has one known colour
        RenderSettings flat = RenderSettings.standalone();
        flat.lighting().setSky(SKY);
        flat.lighting().setSkyZenith(SKY);
        flat.lighting().setSunIntensity(0);
        renderer = new SceneRenderer(gl, world, flat);
        px = MemoryUtil.memAlloc(4 * 1024 * 1024);
        other = MemoryUtil.memAlloc(4 * 1024 * 1024);
    }

    @AfterEach
    void noGlErrors() {
        gl.debug().check("the test");
    }

    @AfterAll
    void tearDown() {
        MemoryUtil.memFree((java.nio.Buffer) px);
        MemoryUtil.memFree((java.nio.Buffer) other);
        if (renderer != null) {
            renderer.close();
            fb.close();
            assertEquals(0, gl.tracker().live(), "every GL object released");
        }
        if (gl != null) {
            gl.close();
        }
    }

    /** The first grass tuft (species 0) and a camera 1.5 m south of it, looking at it. */
    private int grassPlant() {
        for (int p = 0; p < world.plantCount(); p++) {
            if (world.plantSpecies(p) == 0 && Math.abs(world.plantX(p)) < 8 && Math.abs(world.plantZ(p)) < 8) {
                return p;
            }
        }
        throw new IllegalStateException("C1 has no grass tuft near the centre");
    }

    private ViewCamera cameraAt(int plant, double dist) {
        ViewCamera c = new ViewCamera();
        c.setPosition(world.plantX(plant), world.plantY(plant) + 0.9, world.plantZ(plant) + dist);
        c.setOrientation(0, -Math.atan2(0.7, dist));
        c.setLens(Math.toRadians(50), W / (double) H, 0.05, 200);
        return c;
    }

    private void render(Frame frame, ViewCamera camera, ByteBuffer dest) {
        fb.bind();
        renderer.render(frame, camera, fb.width(), fb.height());
        Pixels.read(fb.width(), fb.height(), dest);
    }

    /** Whether a pixel is greener (by more than 3 levels against red) with the plants than without. */
    private static boolean greener(ByteBuffer with, ByteBuffer without, int w, int x, int y) {
        int gw = Pixels.green(with, w, x, y) - Pixels.red(with, w, x, y);
        int go = Pixels.green(without, w, x, y) - Pixels.red(without, w, x, y);
        return gw - go > 3;
    }

    private static boolean sky(ByteBuffer b, int w, int x, int y) {
        return Math.abs(Pixels.red(b, w, x, y) - Math.round(SKY.r() * 255)) <= 1
                && Math.abs(Pixels.green(b, w, x, y) - Math.round(SKY.g() * 255)) <= 1
                && Math.abs(Pixels.blue(b, w, x, y) - Math.round(SKY.b() * 255)) <= 1;
    }

    @Test
    void plantsAppearWherePlantsStandAndTerrainOrSkyElsewhere() throws Exception {
        int plant = grassPlant();
        ViewCamera cam = cameraAt(plant, 1.5);
        render(TestFrames.rest(world, cam), cam, px);
        Pixels.writePng(Path.of("target/render-test/c1-close.png"), px, W, H);
        // where the tuft stands: project its base and a point 0.2 m up
        Vector4f p = new Vector4f(world.plantX(plant), world.plantY(plant) + 0.15f, world.plantZ(plant), 1f);
        cam.viewProjection(new org.joml.Matrix4f()).transform(p);
        int sx = (int) ((p.x / p.w * 0.5 + 0.5) * W);
        int sy = (int) ((p.y / p.w * 0.5 + 0.5) * H);
        // the same view without the plants: the tuft's blades (thinner than a pixel here, blended by their
        // coverage on this target without samples) change the ground around its base
        renderer.drawPlants = false;
        render(TestFrames.rest(world, cam), cam, other);
        renderer.drawPlants = true;
        int near = 0;
        for (int y = Math.max(0, sy - 25); y < Math.min(H, sy + 25); y++) {
            for (int x = Math.max(0, sx - 25); x < Math.min(W, sx + 25); x++) {
                near += greener(px, other, W, x, y) ? 1 : 0;
            }
        }
        assertTrue(near > 60, "pixels the tuft at (" + sx + ", " + sy + ") turns greener: " + near);
        // elsewhere: every pixel is sky, terrain or another plant; the top row is sky, the bottom row terrain
        int skyTop = 0;
        int terrainBottom = 0;
        for (int x = 0; x < W; x++) {
            skyTop += sky(px, W, x, H - 1) ? 1 : 0;
            terrainBottom += !sky(px, W, x, 0) && Pixels.red(px, W, x, 0) > 10 ? 1 : 0;
        }
        assertEquals(W, skyTop, "top row is sky");
        assertTrue(terrainBottom > W * 0.9, "bottom row is terrain: " + terrainBottom);
        // not blank: many distinct colours
        assertTrue(distinctColours(px, W, H) > 50, "image not blank");
    }

    private static int distinctColours(ByteBuffer b, int w, int h) {
        java.util.BitSet seen = new java.util.BitSet(1 << 24);
        for (int i = 0; i < w * h; i++) {
            seen.set(b.getInt(4 * i) & 0xFFFFFF);
        }
        return seen.cardinality();
    }

    @Test
    void lookingAtTheSkyShowsOnlySky() {
        ViewCamera cam = cameraAt(grassPlant(), 1.5);
        cam.setOrientation(0, Math.toRadians(80));
        render(TestFrames.rest(world, cam), cam, px);
        for (int y = 0; y < H; y += 7) {
            for (int x = 0; x < W; x += 7) {
                assertTrue(sky(px, W, x, y), "sky at " + x + "," + y);
            }
        }
    }

    @Test
    void twoFramesInWindDiffer() {
        ViewCamera cam = cameraAt(grassPlant(), 1.5);
        render(TestFrames.wind(world, 0.3, cam), cam, px);
        render(TestFrames.wind(world, 1.4, cam), cam, other);
        assertTrue(differing(px, other, W * H) > 200, "wind frames differ: " + differing(px, other, W * H));
    }

    @Test
    void twoFramesInStaticModeAreIdentical() {
        ViewCamera cam = cameraAt(grassPlant(), 1.5);
        render(TestFrames.rest(world, cam), cam, px);
        render(TestFrames.rest(world, cam), cam, other);
        assertEquals(0, differing(px, other, W * H));
    }

    private static int differing(ByteBuffer a, ByteBuffer b, int pixels) {
        int n = 0;
        for (int i = 0; i < pixels; i++) {
            n += a.getInt(4 * i) != b.getInt(4 * i) ? 1 : 0;
        }
        return n;
    }

    @Test
    void aPlantBeyond15mIsDrawnWithLinesAndCountersSumInstancesTimesPrimitives() {
        int plant = grassPlant();
        ViewCamera cam = cameraAt(plant, 20);
        cam.setOrientation(0, -Math.atan2(0.9, 20));
        render(TestFrames.rest(world, cam), cam, px);
        PlantBatches b = renderer.plants().batches();
        int far = b.list(0, 2);
        assertTrue(b.lines(far));
        boolean listed = false;
        for (int i = 0; i < b.count(far); i++) {
            listed |= b.plant(far, i) == plant;
        }
        assertTrue(listed, "the tuft 20 m away is in the line list");
        long tri = 0;
        long lines = 0;
        List<SpeciesModel> species = world.plants().species();
        for (int s = 0; s < species.size(); s++) {
            for (int l = 0; l < species.get(s).levels(); l++) {
                long n = (long) b.count(b.list(s, l)) * species.get(s).primitiveCount(l);
                if (species.get(s).mesh(l).primitive() == Primitive.LINES) {
                    lines += n;
                } else {
                    tri += n;
                }
            }
        }
        assertTrue(lines > 0);
        assertEquals(tri, b.triangles());
        assertEquals(lines, b.lineCount());
        assertEquals(tri + renderer.terrain().triangles(), renderer.triangles());
        assertEquals(lines, renderer.lines());
        // the far tuft's lines reach the image: it differs from the same view without plants
        render(new Frame(world.plantCount(), world.bendGeometry()), cam, other);
        assertTrue(differing(px, other, W * H) > 0);
    }

    @Test
    void overlaysRender() throws Exception {
        Heightfield h = world.terrain().heightfield();
        WindField wind = WindField.of(List.of(FlowDef.uniform("w", 5, 0.3)));
        float[] xs = new float[world.plantCount()];
        float[] zs = new float[world.plantCount()];
        for (int p = 0; p < xs.length; p++) {
            xs[p] = world.plantX(p);
            zs[p] = world.plantZ(p);
        }
        QuadtreeForceField field = QuadtreeForceField.build(ForceFieldDef.builder().maxObjectsPerNode(4).maxDepth(6)
                .lodDistances(4.0, 8.0).build(),
                h.minX(), h.minZ(), h.maxX(), h.maxZ(), h.minHeight(), h.maxHeight() + 1, wind, xs, zs);
        ViewCamera cam = cameraAt(grassPlant(), 3);
        field.update(cam);
        renderer.setField(field.debugView());
        renderer.settings().overlays().setShowField(true);
        renderer.settings().overlays().setShowWind(true);
        try {
            render(TestFrames.rest(world, cam), cam, px);
        } finally {
            renderer.settings().overlays().setShowField(false);
            renderer.settings().overlays().setShowWind(false);
            renderer.setField(null);
        }
        Pixels.writePng(Path.of("target/render-test/c1-overlays.png"), px, W, H);
        render(TestFrames.rest(world, cam), cam, other);
        // the map sits in the top-right corner: grey cells (r = g = b), red wind arrows
        int side = (int) (0.38f * Math.min(W, H));
        int grey = 0;
        int red = 0;
        int darkest = 0;
        for (int y = H - side - 10; y < H - 10; y++) {
            for (int x = W - side - 10; x < W - 10; x++) {
                int r = Pixels.red(px, W, x, y);
                int g = Pixels.green(px, W, x, y);
                int bl = Pixels.blue(px, W, x, y);
                grey += r == g && g == bl && r > 20 ? 1 : 0;
                darkest += r == g && g == bl && r < 45 ? 1 : 0;
                red += r > 150 && g < 80 && bl < 80 ? 1 : 0;
            }
        }
        assertTrue(grey > side * side / 4, "grey quadtree cells: " + grey);
        assertTrue(darkest > 0, "invisible cells are darkest: " + darkest);
        assertTrue(red > 5, "wind vectors: " + red);
        assertTrue(differing(px, other, W * H) > side * side / 2);
        assertEquals(0.12f, FieldOverlay.grey(false, -1));
        assertTrue(FieldOverlay.grey(true, 0) > FieldOverlay.grey(true, 1));
    }

    @Test
    void resizingWorks() {
        ViewCamera cam = cameraAt(grassPlant(), 1.5);
        int w2 = 200;
        int h2 = 300;
        try {
            fb.resize(w2, h2);
            cam.setLens(cam.fovY(), w2 / (double) h2, cam.near(), cam.far());
            render(TestFrames.rest(world, cam), cam, px);
            assertTrue(sky(px, w2, w2 / 2, h2 - 1), "sky at the top of the resized image");
            assertFalse(sky(px, w2, w2 / 2, 0), "terrain at the bottom");
            assertTrue(distinctColours(px, w2, h2) > 50);
        } finally {
            fb.resize(W, H);
        }
        assertNotEquals(0, gl.tracker().live());
    }

    @Test
    void closingReleasesEveryGlObject() {
        int before = gl.tracker().live();
        SceneRenderer r = new SceneRenderer(gl, world, RenderSettings.standalone());
        GlFramebuffer f = new GlFramebuffer(gl.tracker(), 64, 64);
        assertTrue(gl.tracker().live() > before + 10);
        f.bind();
        r.render(TestFrames.rest(world, cameraAt(grassPlant(), 2)), cameraAt(grassPlant(), 2), 64, 64);
        r.close();
        f.close();
        r.close();
        f.close();
        assertEquals(before, gl.tracker().live());
    }
}
