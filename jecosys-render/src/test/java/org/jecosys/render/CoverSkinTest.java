package org.jecosys.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.lwjgl.opengl.GL11C.GL_COLOR_BUFFER_BIT;
import static org.lwjgl.opengl.GL11C.GL_DEPTH_BUFFER_BIT;
import static org.lwjgl.opengl.GL11C.GL_DEPTH_TEST;
import static org.lwjgl.opengl.GL11C.GL_LESS;
import static org.lwjgl.opengl.GL11C.GL_TRIANGLES;
import static org.lwjgl.opengl.GL11C.GL_UNSIGNED_INT;
import static org.lwjgl.opengl.GL11C.glClear;
import static org.lwjgl.opengl.GL11C.glClearColor;
import static org.lwjgl.opengl.GL11C.glDepthFunc;
import static org.lwjgl.opengl.GL11C.glDisable;
import static org.lwjgl.opengl.GL11C.glDrawElements;
import static org.lwjgl.opengl.GL11C.glEnable;
import static org.lwjgl.opengl.GL11C.glViewport;
import static org.lwjgl.opengl.GL20C.glUniform1f;
import static org.lwjgl.opengl.GL20C.glUniform3f;
import static org.lwjgl.opengl.GL20C.glUniformMatrix4fv;
import static org.lwjgl.opengl.GL20C.glUseProgram;

import com.sun.management.ThreadMXBean;
import java.lang.management.ManagementFactory;
import java.nio.ByteBuffer;
import java.nio.FloatBuffer;
import java.nio.IntBuffer;
import java.util.Map;
import org.jecosys.math.Camera;
import org.jecosys.math.Rgb;
import org.jecosys.math.ViewCamera;
import org.jecosys.render.GlContext.DebugOutput;
import org.jecosys.render.ImageMetrics.Img;
import org.jecosys.render.gl.GlBuffer;
import org.jecosys.render.gl.GlFramebuffer;
import org.jecosys.render.gl.GlProgram;
import org.jecosys.render.gl.GlVertexArray;
import org.jecosys.render.gl.Pixels;
import org.jecosys.scene.RenderDef;
import org.jecosys.scene.SceneDef;
import org.jecosys.sim.Frame;
import org.jecosys.sim.World;
import org.jecosys.terrain.Heightfield;
import org.joml.Matrix4f;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestInstance;
import org.lwjgl.system.MemoryUtil;

/**
 * Issue 38, "Cover on any ground": a game that draws its own ground (the library's terrain off) gets
 * the ground cover over it, not bare game ground beyond the near blades. The meadow's start view
 * (960x540) over a flat brown "game ground" on the meadow's heights, drawn by the test as a game would
 * (depth written), then the renderer as a guest: with the cover's skin at most 5% of the lower half
 * keeps the game's brown, without it much more does; a game's ground a little above the scene's
 * heights hides the skin entirely; every GL state is put back, no GL error is raised (debug output
 * on), and the skin allocates nothing per frame.
 */
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
class CoverSkinTest {
    private static final int W = 960;
    private static final int H = 540;
    /** The game's ground: a flat brown, unlit. */
    private static final Rgb BROWN = new Rgb(0.45f, 0.30f, 0.15f);
    private static final Rgb SKY = new Rgb(0.62f, 0.76f, 0.92f);

    private SceneDef def;
    private World world;
    private GlContext gl;
    private GlFramebuffer fb;
    private HostGround host;
    private ByteBuffer px;

    @BeforeAll
    void setUp() {
        def = RenderScenes.load("meadow.xml");
        world = RenderScenes.build(def);
        gl = GlContext.headless(DebugOutput.ON);
        fb = new GlFramebuffer(gl.tracker(), W, H);
        host = new HostGround(world.terrain().heightfield());
        px = MemoryUtil.memAlloc(4 * W * H);
    }

    @AfterEach
    void noGlErrors() {
        gl.debug().check("the cover skin test");
    }

    @AfterAll
    void tearDown() {
        MemoryUtil.memFree((java.nio.Buffer) px);
        if (host != null) {
            host.close();
        }
        if (fb != null) {
            fb.close();
        }
        if (gl != null) {
            assertEquals(0, gl.tracker().live(), "every GL object released");
            gl.close();
        }
    }

    /** The game's ground as a game would draw it: a heightfield mesh in one colour, depth written. */
    private final class HostGround implements AutoCloseable {
        final GlProgram program = new GlProgram(gl.tracker(), "host_ground.vert", "host_ground.frag");
        final GlVertexArray vao = new GlVertexArray(gl.tracker());
        final GlBuffer vertices;
        final GlBuffer indices;
        final int count;
        final FloatBuffer matrix = MemoryUtil.memAllocFloat(16);

        HostGround(Heightfield h) {
            int res = h.resolution();
            float[] heights = h.copyHeights(new float[res * res]);
            FloatBuffer v = MemoryUtil.memAllocFloat(3 * res * res);
            IntBuffer idx = MemoryUtil.memAllocInt(6 * (res - 1) * (res - 1));
            try {
                for (int j = 0; j < res; j++) {
                    for (int i = 0; i < res; i++) {
                        v.put((float) (h.minX() + i * h.cellX())).put(heights[j * res + i])
                                .put((float) (h.minZ() + j * h.cellZ()));
                    }
                }
                // the other diagonal than the library's mesh: a game's triangulation need not be ours
                for (int j = 0; j < res - 1; j++) {
                    for (int i = 0; i < res - 1; i++) {
                        int a = j * res + i;
                        idx.put(a).put(a + res).put(a + res + 1).put(a).put(a + res + 1).put(a + 1);
                    }
                }
                vao.bind();
                vertices = GlBuffer.of(gl.tracker(), org.lwjgl.opengl.GL15C.GL_ARRAY_BUFFER, v.flip(),
                        org.lwjgl.opengl.GL15C.GL_STATIC_DRAW);
                indices = GlBuffer.of(gl.tracker(), org.lwjgl.opengl.GL15C.GL_ELEMENT_ARRAY_BUFFER, idx.flip(),
                        org.lwjgl.opengl.GL15C.GL_STATIC_DRAW);
                org.lwjgl.opengl.GL20C.glEnableVertexAttribArray(0);
                org.lwjgl.opengl.GL20C.glVertexAttribPointer(0, 3, org.lwjgl.opengl.GL11C.GL_FLOAT, false, 12, 0L);
                org.lwjgl.opengl.GL30C.glBindVertexArray(0);
            } finally {
                MemoryUtil.memFree((java.nio.Buffer) v);
                MemoryUtil.memFree((java.nio.Buffer) idx);
            }
            count = 6 * (res - 1) * (res - 1);
        }

        /** Clears to the sky and depth 1, draws the ground raised by {@code raise} metres, depth-tested. */
        void draw(Camera camera, float raise) {
            glViewport(0, 0, W, H);
            glClearColor(SKY.r(), SKY.g(), SKY.b(), 1f);
            glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
            glEnable(GL_DEPTH_TEST);
            glDepthFunc(GL_LESS);
            program.use();
            glUniformMatrix4fv(program.uniform("uViewProj"), false, camera.viewProjection(new Matrix4f()).get(matrix));
            glUniform3f(program.uniform("uColour"), BROWN.r(), BROWN.g(), BROWN.b());
            glUniform1f(program.uniform("uRaise"), raise);
            vao.bind();
            glDrawElements(GL_TRIANGLES, count, GL_UNSIGNED_INT, 0L);
            org.lwjgl.opengl.GL30C.glBindVertexArray(0);
            glUseProgram(0);
            glDisable(GL_DEPTH_TEST);
        }

        @Override
        public void close() {
            org.jecosys.render.gl.Closing.closeAll(vao, vertices, indices, program);
            MemoryUtil.memFree((java.nio.Buffer) matrix);
        }
    }

    /** The guest settings a game starts from: the scene's look, no clear, no terrain. */
    private RenderSettings guest(boolean skin) {
        RenderSettings s = RenderSettings.of(def);
        s.lighting().setSky(SKY);
        s.setCoverSkin(skin);
        assertTrue(!s.clear() && !s.terrain(), "a guest's defaults");
        return s;
    }

    /** The game's frame: its ground, then the renderer over it; the GL state is checked unchanged. */
    private Img frame(SceneRenderer r, Frame frame, Camera camera, float raise) {
        fb.bind();
        host.draw(camera, raise);
        Map<String, String> before = GuestCensus.take();
        r.render(frame, camera);
        assertEquals(before, GuestCensus.take(), "every GL state put back");
        Pixels.read(W, H, px);
        gl.debug().check("a guest frame over the game's ground");
        return Img.of(px, W, H);
    }

    /** Share of the lower half of the picture in the game's brown. */
    private static double brownShare(Img img) {
        int brown = ImageMetrics.rgb(Math.round(BROWN.r() * 255), Math.round(BROWN.g() * 255),
                Math.round(BROWN.b() * 255));
        int n = 0;
        for (int y = 0; y < H / 2; y++) {
            for (int x = 0; x < W; x++) {
                n += ImageMetrics.sameColour(img.at(x, y), brown) ? 1 : 0;
            }
        }
        return n / (double) (W * H / 2);
    }

    @Test
    void theCoverHidesTheGamesGroundBeyondItsBlades() throws java.io.IOException {
        ViewCamera cam = RenderScenes.camera(def, world, W, H);
        Frame frame = TestFrames.rest(world, cam);
        double[] share = new double[2];
        for (int k = 0; k < 2; k++) {
            boolean skin = k == 0;
            try (SceneRenderer r = new SceneRenderer(gl, world, guest(skin))) {
                share[k] = brownShare(frame(r, frame, cam, 0f));
                Pixels.writePng(java.nio.file.Path.of("target/render-test/cover-skin-" + (skin ? "on" : "off") + ".png"),
                        px, W, H);
            }
        }
        System.out.printf("[look] meadow start view over a game's brown ground: %.1f%% of the lower half brown with"
                + " the cover skin (<= 5%%), %.1f%% without%n", 100 * share[0], 100 * share[1]);
        assertTrue(share[0] <= 0.05, String.format("%.1f%% of the lower half shows the game's brown ground with the"
                + " cover skin, want <= 5%%", 100 * share[0]));
        assertTrue(share[1] >= 0.15 && share[1] >= 4 * share[0], String.format("without the skin the game's ground"
                + " shows (%.1f%% of the lower half), with it %.1f%%", 100 * share[1], 100 * share[0]));
    }

    @Test
    void aGamesGroundAboveTheScenesHeightsHidesTheSkin() {
        // the game's ground 10 cm above the scene's heights: things that stand on the ground win over the skin
        ViewCamera cam = RenderScenes.camera(def, world, W, H);
        Frame frame = TestFrames.rest(world, cam);
        RenderSettings settings = guest(true);
        try (SceneRenderer r = new SceneRenderer(gl, world, settings)) {
            int[] with = frame(r, frame, cam, 0.1f).rgb().clone();
            settings.setCoverSkin(false);
            int[] without = frame(r, frame, cam, 0.1f).rgb();
            int differ = 0;
            for (int i = 0; i < with.length; i++) {
                differ += with[i] != without[i] ? 1 : 0;
            }
            System.out.printf("[look] a game's ground 10 cm above the meadow's heights: %d pixels differ with the"
                    + " skin%n", differ);
            assertTrue(differ <= W * H / 1000, differ + " pixels show the skin through a game's ground above it");
        }
    }

    @Test
    @org.junit.jupiter.api.Tag("slow") // 7 s; the skin's hiding the game's ground stays in the default run
    void theSkinShowsTheCoverOfTheLibrarysTerrain() {
        // the same view with the library's own terrain: the skin carries its cover's colour, grain and shading
        ViewCamera cam = RenderScenes.camera(def, world, W, H);
        Frame frame = TestFrames.rest(world, cam);
        RenderSettings own = RenderSettings.of(def);
        own.lighting().setSky(SKY);
        own.setClear(true);
        own.setTerrain(true);
        int[] ours;
        try (SceneRenderer r = new SceneRenderer(gl, world, own)) {
            ours = frame(r, frame, cam, 0f).rgb().clone();
        }
        Img guest;
        try (SceneRenderer r = new SceneRenderer(gl, world, guest(true))) {
            guest = frame(r, frame, cam, 0f);
        }
        double diff = 0;
        for (int y = 0; y < H / 2; y++) {
            for (int x = 0; x < W; x++) {
                int p = guest.at(x, y);
                int q = ours[y * W + x];
                diff += Math.abs(ImageMetrics.r(p) - ImageMetrics.r(q)) + Math.abs(ImageMetrics.g(p) - ImageMetrics.g(q))
                        + Math.abs(ImageMetrics.b(p) - ImageMetrics.b(q));
            }
        }
        diff /= 3.0 * W * H / 2;
        System.out.printf("[look] meadow start view, lower half: the skin over a game's ground differs from the"
                + " library's terrain by %.2f levels a channel on average%n", diff);
        assertTrue(diff < 4, String.format("mean difference %.2f levels a channel from the library's terrain", diff));
    }

    @Test
    void drawingTheSkinAllocatesNothingAfterWarmUp() {
        ThreadMXBean threads = (ThreadMXBean) ManagementFactory.getThreadMXBean();
        SceneDef c1 = RenderScenes.load("c1.xml");
        World small = RenderScenes.build(c1);
        int w = 160;
        int h = 100;
        ViewCamera cam = RenderScenes.camera(c1, small, w, h);
        Frame frame = TestFrames.wind(small, 0.3, cam);
        RenderSettings settings = RenderSettings.of(c1);
        settings.setGroundCover(new RenderDef.GroundCover(1, 0.06, 800, 6, 1.5, new Rgb(0.3f, 0.5f, 0.16f),
                new Rgb(0.6f, 0.55f, 0.3f)));
        long thread = Thread.currentThread().getId();
        try (SceneRenderer r = new SceneRenderer(gl, small, settings)) {
            fb.bind();
            int made = gl.tracker().live();
            for (int i = 0; i < 20; i++) {
                r.render(frame, cam, w, h);
            }
            // the skin's program and vertex array, and the 4 split programs of a target without samples
            assertEquals(made + 2 + org.jecosys.render.plant.PlantPasses.CASTERS, gl.tracker().live(),
                    "the skin's program and vertex array and the plants' split programs made at the first frame");
            threads.getThreadAllocatedBytes(thread); // the counter's own first call allocates
            long[] windows = new long[40];
            int zeroRun = 0;
            int n = 0;
            for (; n < windows.length && zeroRun < 2; n++) {
                long start = threads.getThreadAllocatedBytes(thread);
                for (int i = 0; i < 50; i++) {
                    r.render(frame, cam, w, h);
                }
                windows[n] = threads.getThreadAllocatedBytes(thread) - start;
                zeroRun = windows[n] == 0 ? zeroRun + 1 : 0;
            }
            assertEquals(2, zeroRun, "two windows of 50 guest frames with the cover skin allocating 0 bytes: "
                    + java.util.Arrays.toString(java.util.Arrays.copyOf(windows, n)));
        }
    }
}
