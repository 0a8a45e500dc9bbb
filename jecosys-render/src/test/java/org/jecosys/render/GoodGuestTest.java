package org.jecosys.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.jecosys.render.GlContext.DebugOutput;
import java.nio.ByteBuffer;
import java.util.Map;
import java.util.function.Consumer;
import org.jecosys.math.Rgb;
import org.jecosys.math.ViewCamera;
import org.jecosys.sim.Frame;
import org.jecosys.sim.World;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestInstance;
import org.lwjgl.opengl.GL11C;
import org.lwjgl.opengl.GL30C;
import org.lwjgl.system.MemoryUtil;
import org.jecosys.render.gl.GlFramebuffer;
import org.jecosys.render.gl.Pixels;
import org.junit.jupiter.api.Tag;

/**
 * The renderer is a good guest in a host's GL (a game, libGDX, jMonkeyEngine): a census of
 * {@link GuestCensus} state (well over 80 entries) is unchanged across construction, {@code render}
 * and {@code close}, both after a host left unusual values everywhere and after defaults; what the
 * plants look like does not depend on what the host left (blend equation, colour mask, polygon offset
 * and mode, depth function, front face, stencil, logic op, sample mask, multisampling off (the picture on a
 * multisampled target is compared too), sampler objects, pixel
 * store); plants write alpha 255; and into an sRGB framebuffer with the host's sRGB writes on, the
 * stored colours are within 3/255 of a linear framebuffer's.
 */
@Tag("lwjgl-compat")
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
class GoodGuestTest {
    private static final int W = 240;
    private static final int H = 160;
    private static final Rgb SKY = new Rgb(0.62f, 0.76f, 0.92f);

    private GlContext owner;
    private GlContext gl;
    private World world;
    private ByteBuffer px;
    private ByteBuffer ref;

    @BeforeAll
    void setUp() {
        owner = GlContext.headless(DebugOutput.ON);
        gl = GlContext.current(DebugOutput.OFF);
        world = RenderScenes.build(RenderScenes.load("c1.xml"));
        px = MemoryUtil.memAlloc(4 * W * H);
        ref = MemoryUtil.memAlloc(4 * W * H);
    }

    @AfterAll
    void tearDown() {
        MemoryUtil.memFree((java.nio.Buffer) px);
        MemoryUtil.memFree((java.nio.Buffer) ref);
        if (gl != null) {
            gl.close();
        }
        if (owner != null) {
            owner.debug().check("the good-guest test");
            owner.close();
        }
    }

    private static ViewCamera camera() {
        ViewCamera c = new ViewCamera();
        c.setPosition(0, 1.6, 9);
        c.setOrientation(0, -0.2);
        c.setLens(Math.toRadians(50), W / (double) H, 0.05, 200);
        return c;
    }

    @Test
    void theCensusIsLargeAndUnchangedAcrossConstructionRenderAndCloseWithUnusualAndDefaultHostState() {
        try (GlFramebuffer fb = new GlFramebuffer(gl.tracker(), W, H)) {
            for (boolean unusual : new boolean[] {true, false}) {
                fb.bind();
                GL11C.glViewport(7, 5, W - 20, H - 12);
                GuestCensus.Hostile host = unusual ? new GuestCensus.Hostile(true) : null;
                try {
                    Map<String, String> before = GuestCensus.take();
                    assertTrue(before.size() >= 80, "entries in the census: " + before.size());
                    // with the sun's shadow map: its own framebuffer is bound and put back within each render
                    RenderSettings settings = RenderSettings.standalone();
                    settings.lighting().setSky(SKY);
                    settings.setShadows(0.6f);
                    settings.setShadowPath(ShadowPath.MAP);
                    SceneRenderer renderer = new SceneRenderer(gl, world, settings);
                    assertEquals(before, GuestCensus.take(), "construction, unusual host state " + unusual);
                    Frame frame = TestFrames.wind(world, 0.4, camera());
                    for (boolean clear : new boolean[] {true, false}) {
                        settings.setClear(clear);
                        settings.setTerrain(clear);
                        renderer.render(frame, camera());
                        assertEquals(before, GuestCensus.take(), "render(frame, camera), clear " + clear + ", unusual "
                                + unusual);
                        renderer.render(frame, camera(), W, H);
                        assertEquals(before, GuestCensus.take(), "render(frame, camera, w, h), clear " + clear);
                    }
                    assertTrue(renderer.triangles() > 0, "something was drawn");
                    renderer.close();
                    assertEquals(before, GuestCensus.take(), "close, unusual host state " + unusual);
                } finally {
                    if (host != null) {
                        host.close();
                    }
                }
            }
        }
    }

    @Test
    void whatTheHostLeftChangesNothingInThePictureAndPlantsAreOpaque() {
        try (GlFramebuffer fb = new GlFramebuffer(gl.tracker(), W, H)) {
            Frame frame = TestFrames.wind(world, 0.4, camera());
            // reference: a host at the GL defaults
            render(fb, frame, false, ref);
            // the host leaves everything that would spoil the drawing, from before construction on
            render(fb, frame, true, px);
            assertEquals(0, differingPixels(ref, px), "pixels that differ with the host's unusual state");
            // opaque plants over an opaque background: every pixel alpha 255, plants included
            int plantPixels = 0;
            for (int i = 0; i < W * H; i++) {
                assertEquals(255, px.get(4 * i + 3) & 0xff, "alpha at pixel " + i);
                plantPixels += isPlant(px, i) ? 1 : 0;
            }
            assertTrue(plantPixels > 500, "plant pixels: " + plantPixels);
        }
        // multisampled (the core by alpha-to-coverage, the fringe on pixel centres): the stored alpha is 1
        // as well, and a host that left multisampling off (among the rest) changes nothing there either
        try (GlFramebuffer ms = new GlFramebuffer(gl.tracker(), W, H, 4)) {
            // near enough that the blades have a core on the samples
            ViewCamera near = camera();
            near.setPosition(0, 0.7, 3);
            Frame frame = TestFrames.wind(world, 0.4, near);
            render(ms, frame, near, false, ref);
            render(ms, frame, near, true, px);
            assertEquals(0, differingPixels(ref, px), "multisampled pixels that differ with the host's unusual state");
            for (int i = 0; i < W * H; i++) {
                assertEquals(255, px.get(4 * i + 3) & 0xff, "multisampled alpha at pixel " + i);
            }
        }
    }

    /** Clears to an opaque magenta, then draws plants only (the host's ground is its clear). */
    private void render(GlFramebuffer fb, Frame frame, boolean unusual, ByteBuffer out) {
        render(fb, frame, camera(), unusual, out);
    }

    private void render(GlFramebuffer fb, Frame frame, ViewCamera camera, boolean unusual, ByteBuffer out) {
        fb.bind();
        GL11C.glViewport(0, 0, W, H);
        GL11C.glClearColor(1f, 0f, 1f, 1f);
        GL11C.glClearDepth(1.0);
        GL11C.glClear(GL11C.GL_COLOR_BUFFER_BIT | GL11C.GL_DEPTH_BUFFER_BIT | GL11C.GL_STENCIL_BUFFER_BIT);
        GuestCensus.Hostile host = unusual ? new GuestCensus.Hostile(true) : null;
        try (SceneRenderer r = new SceneRenderer(gl, world, guest())) {
            r.render(frame, camera);
        } finally {
            if (host != null) {
                host.close();
            }
        }
        fb.resolve();
        Pixels.read(W, H, out);
    }

    private static boolean isPlant(ByteBuffer p, int i) {
        return !((p.get(4 * i) & 0xff) == 255 && (p.get(4 * i + 1) & 0xff) == 0 && (p.get(4 * i + 2) & 0xff) == 255);
    }

    private static int differingPixels(ByteBuffer a, ByteBuffer b) {
        int n = 0;
        for (int i = 0; i < W * H; i++) {
            n += a.getInt(4 * i) != b.getInt(4 * i) ? 1 : 0;
        }
        return n;
    }

    @Test
    void intoAnSrgbFramebufferWithSrgbWritesOnThePlantsStoreTheColoursOfALinearOne() {
        Frame frame = TestFrames.wind(world, 0.4, camera());
        drawInto(GL11C.GL_RGBA8, false, frame, ref);
        drawInto(GL30C.GL_SRGB8_ALPHA8, true, frame, px);
        long diff = 0;
        int plant = 0;
        for (int i = 0; i < W * H; i++) {
            if (!isPlant(ref, i)) {
                continue;
            }
            plant++;
            for (int c = 0; c < 3; c++) {
                diff += Math.abs((ref.get(4 * i + c) & 0xff) - (px.get(4 * i + c) & 0xff));
            }
        }
        assertTrue(plant > 500, "plant pixels: " + plant);
        double mean = diff / (3.0 * plant);
        System.out.printf("[guest] sRGB framebuffer against linear: mean %.3f/255 over %d plant pixels%n", mean, plant);
        assertTrue(mean <= 3, "mean difference per channel over plant pixels: " + mean + "/255");
    }

    /** Draws plants over magenta into a framebuffer of {@code format}; reads its stored bytes. */
    private void drawInto(int format, boolean srgbWrites, Frame frame, ByteBuffer out) {
        int fbo = GL30C.glGenFramebuffers();
        int colour = GL11C.glGenTextures();
        int depth = GL30C.glGenRenderbuffers();
        try {
            GL11C.glBindTexture(GL11C.GL_TEXTURE_2D, colour);
            GL11C.glTexImage2D(GL11C.GL_TEXTURE_2D, 0, format, W, H, 0, GL11C.GL_RGBA, GL11C.GL_UNSIGNED_BYTE,
                    (ByteBuffer) null);
            GL30C.glBindRenderbuffer(GL30C.GL_RENDERBUFFER, depth);
            GL30C.glRenderbufferStorage(GL30C.GL_RENDERBUFFER, GL30C.GL_DEPTH24_STENCIL8, W, H);
            GL30C.glBindFramebuffer(GL30C.GL_FRAMEBUFFER, fbo);
            GL30C.glFramebufferTexture2D(GL30C.GL_FRAMEBUFFER, GL30C.GL_COLOR_ATTACHMENT0, GL11C.GL_TEXTURE_2D, colour, 0);
            GL30C.glFramebufferRenderbuffer(GL30C.GL_FRAMEBUFFER, GL30C.GL_DEPTH_STENCIL_ATTACHMENT,
                    GL30C.GL_RENDERBUFFER, depth);
            assertEquals(GL30C.GL_FRAMEBUFFER_COMPLETE, GL30C.glCheckFramebufferStatus(GL30C.GL_FRAMEBUFFER));
            GL11C.glViewport(0, 0, W, H);
            GL11C.glClearColor(1f, 0f, 1f, 1f);
            GL11C.glClear(GL11C.GL_COLOR_BUFFER_BIT | GL11C.GL_DEPTH_BUFFER_BIT);
            Consumer<Boolean> srgb = on -> {
                if (on) {
                    GL11C.glEnable(GL30C.GL_FRAMEBUFFER_SRGB);
                } else {
                    GL11C.glDisable(GL30C.GL_FRAMEBUFFER_SRGB);
                }
            };
            srgb.accept(srgbWrites); // the host's gamma correction (jMonkeyEngine's default)
            try (SceneRenderer r = new SceneRenderer(gl, world, guest())) {
                r.render(frame, camera());
            }
            assertEquals(srgbWrites, GL11C.glIsEnabled(GL30C.GL_FRAMEBUFFER_SRGB), "the host's switch is kept");
            srgb.accept(false); // read the stored bytes as they are
            Pixels.read(W, H, out);
        } finally {
            GL30C.glBindFramebuffer(GL30C.GL_FRAMEBUFFER, 0);
            GL30C.glDeleteFramebuffers(fbo);
            GL11C.glDeleteTextures(colour);
            GL30C.glDeleteRenderbuffers(depth);
        }
    }

    /** A guest's settings (no clear, no terrain) with the test's sky. */
    private static RenderSettings guest() {
        RenderSettings s = new RenderSettings();
        s.lighting().setSky(SKY);
        return s;
    }
}
