package org.jecosys.render;

import org.jecosys.render.GlContext.DebugOutput;
import org.jecosys.render.gl.Closing;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.lwjgl.opengl.GL11C.*;
import static org.lwjgl.opengl.GL13C.GL_ACTIVE_TEXTURE;
import static org.lwjgl.opengl.GL13C.GL_TEXTURE0;
import static org.lwjgl.opengl.GL13C.glActiveTexture;
import static org.lwjgl.opengl.GL14C.GL_BLEND_DST_ALPHA;
import static org.lwjgl.opengl.GL14C.GL_BLEND_DST_RGB;
import static org.lwjgl.opengl.GL14C.GL_BLEND_SRC_ALPHA;
import static org.lwjgl.opengl.GL14C.GL_BLEND_SRC_RGB;
import static org.lwjgl.opengl.GL14C.GL_FUNC_REVERSE_SUBTRACT;
import static org.lwjgl.opengl.GL14C.glBlendEquation;
import static org.lwjgl.opengl.GL14C.glBlendFuncSeparate;
import static org.lwjgl.opengl.GL15C.GL_ARRAY_BUFFER;
import static org.lwjgl.opengl.GL15C.GL_ARRAY_BUFFER_BINDING;
import static org.lwjgl.opengl.GL15C.GL_ELEMENT_ARRAY_BUFFER;
import static org.lwjgl.opengl.GL15C.GL_ELEMENT_ARRAY_BUFFER_BINDING;
import static org.lwjgl.opengl.GL15C.GL_STATIC_DRAW;
import static org.lwjgl.opengl.GL15C.glBindBuffer;
import static org.lwjgl.opengl.GL15C.glBufferData;
import static org.lwjgl.opengl.GL15C.glDeleteBuffers;
import static org.lwjgl.opengl.GL15C.glGenBuffers;
import static org.lwjgl.opengl.GL20C.GL_BLEND_EQUATION_ALPHA;
import static org.lwjgl.opengl.GL20C.GL_BLEND_EQUATION_RGB;
import static org.lwjgl.opengl.GL20C.GL_CURRENT_PROGRAM;
import static org.lwjgl.opengl.GL20C.glUseProgram;
import static org.lwjgl.opengl.GL30C.GL_DRAW_FRAMEBUFFER_BINDING;
import static org.lwjgl.opengl.GL30C.GL_R32F;
import static org.lwjgl.opengl.GL30C.GL_READ_FRAMEBUFFER_BINDING;
import static org.lwjgl.opengl.GL30C.GL_VERTEX_ARRAY_BINDING;
import static org.lwjgl.opengl.GL30C.glBindVertexArray;
import static org.lwjgl.opengl.GL30C.glDeleteVertexArrays;
import static org.lwjgl.opengl.GL30C.glGenVertexArrays;
import static org.lwjgl.opengl.GL31C.GL_TEXTURE_BINDING_BUFFER;
import static org.lwjgl.opengl.GL31C.GL_TEXTURE_BUFFER;
import static org.lwjgl.opengl.GL31C.glTexBuffer;
import static org.lwjgl.opengl.GL32C.GL_PROGRAM_POINT_SIZE;
import static org.lwjgl.opengl.GL13C.GL_SAMPLE_ALPHA_TO_COVERAGE;
import static org.lwjgl.opengl.GL13C.GL_MULTISAMPLE;
import static org.lwjgl.opengl.GL33C.GL_SAMPLER_BINDING;

import java.nio.ByteBuffer;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.atomic.AtomicReference;
import org.jecosys.math.MatrixCamera;
import org.jecosys.math.Rgb;
import org.jecosys.math.ViewCamera;
import org.jecosys.sim.World;
import org.joml.Matrix4f;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestInstance;
import org.lwjgl.system.MemoryStack;
import org.lwjgl.system.MemoryUtil;
import org.jecosys.render.gl.GlFramebuffer;
import org.jecosys.render.gl.GlProgram;
import org.jecosys.render.gl.GlTracker;
import org.jecosys.render.gl.Pixels;
import org.jecosys.render.plant.PlantRenderer;
import org.junit.jupiter.api.Tag;

/**
 * The renderer inside a host's GL, as a game uses it: a wrapped context ({@link GlContext#current}),
 * a host's state left exactly as it was (a census of every binding and capability the renderer
 * touches, and more), drawing into the bound viewport only, over the host's own background when
 * clearing is off, and a camera given by the host's own matrices.
 */
@Tag("lwjgl-compat")
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
class HostCompositionTest {
    private static final int W = 320;
    private static final int H = 200;
    private static final Rgb SKY = new Rgb(0.62f, 0.76f, 0.92f);

    private GlContext owner;
    private GlContext gl;
    private GlFramebuffer fb;
    private World world;
    private ByteBuffer px;
    private ByteBuffer other;

    @BeforeAll
    void setUp() {
        owner = GlContext.headless(DebugOutput.ON);
        gl = GlContext.current(DebugOutput.OFF);
        fb = new GlFramebuffer(gl.tracker(), W, H);
        world = RenderScenes.build(RenderScenes.load("c1.xml"));
        px = MemoryUtil.memAlloc(4 * W * H);
        other = MemoryUtil.memAlloc(4 * W * H);
    }

    @AfterAll
    void tearDown() {
        MemoryUtil.memFree((java.nio.Buffer) px);
        MemoryUtil.memFree((java.nio.Buffer) other);
        if (fb != null) {
            fb.close();
        }
        if (gl != null) {
            gl.close();
        }
        if (owner != null) {
            owner.debug().check("the host composition test");
            owner.close();
        }
    }

    private ViewCamera camera(int w, int h) {
        ViewCamera c = new ViewCamera();
        c.setPosition(0, 1.6, 9);
        c.setOrientation(0, -0.2);
        c.setLens(Math.toRadians(50), w / (double) h, 0.05, 200);
        return c;
    }

    /** Every piece of GL state a renderer could plausibly touch, read from the driver. */
    static Map<String, String> census() {
        Map<String, String> s = new LinkedHashMap<>();
        int[] ints = {GL_CURRENT_PROGRAM, GL_VERTEX_ARRAY_BINDING, GL_ARRAY_BUFFER_BINDING,
                GL_ELEMENT_ARRAY_BUFFER_BINDING, GL_TEXTURE_BUFFER, GL_ACTIVE_TEXTURE, GL_DEPTH_FUNC,
                GL_DEPTH_WRITEMASK, GL_BLEND_SRC_RGB, GL_BLEND_DST_RGB, GL_BLEND_SRC_ALPHA, GL_BLEND_DST_ALPHA,
                GL_BLEND_EQUATION_RGB, GL_BLEND_EQUATION_ALPHA, GL_CULL_FACE_MODE, GL_FRONT_FACE,
                GL_DRAW_FRAMEBUFFER_BINDING, GL_READ_FRAMEBUFFER_BINDING, GL_PACK_ALIGNMENT, GL_UNPACK_ALIGNMENT};
        String[] names = {"program", "vertex array", "array buffer", "element buffer", "texture buffer",
                "active texture", "depth func", "depth mask", "blend src rgb", "blend dst rgb", "blend src a",
                "blend dst a", "blend eq rgb", "blend eq a", "cull face mode", "front face", "draw fb", "read fb",
                "pack alignment", "unpack alignment"};
        for (int i = 0; i < ints.length; i++) {
            s.put(names[i], Integer.toString(glGetInteger(ints[i])));
        }
        int[] caps = {GL_DEPTH_TEST, GL_CULL_FACE, GL_BLEND, GL_SCISSOR_TEST, GL_STENCIL_TEST,
                GL_POLYGON_OFFSET_FILL, GL_PROGRAM_POINT_SIZE, GL_SAMPLE_ALPHA_TO_COVERAGE, GL_MULTISAMPLE};
        String[] capNames = {"depth test", "cull face", "blend", "scissor test", "stencil test", "polygon offset",
                "program point size", "alpha to coverage", "multisample"};
        for (int i = 0; i < caps.length; i++) {
            s.put(capNames[i], Boolean.toString(glIsEnabled(caps[i])));
        }
        try (MemoryStack stack = MemoryStack.stackPush()) {
            var v = stack.mallocInt(4);
            glGetIntegerv(GL_VIEWPORT, v);
            s.put("viewport", v.get(0) + "," + v.get(1) + "," + v.get(2) + "," + v.get(3));
            glGetIntegerv(GL_SCISSOR_BOX, v);
            s.put("scissor box", v.get(0) + "," + v.get(1) + "," + v.get(2) + "," + v.get(3));
            var f = stack.mallocFloat(4);
            glGetFloatv(GL_COLOR_CLEAR_VALUE, f);
            s.put("clear colour", f.get(0) + "," + f.get(1) + "," + f.get(2) + "," + f.get(3));
            var b = stack.malloc(4);
            glGetBooleanv(GL_COLOR_WRITEMASK, b);
            s.put("colour mask", b.get(0) + "," + b.get(1) + "," + b.get(2) + "," + b.get(3));
            glGetFloatv(GL_LINE_WIDTH, f);
            s.put("line width", Float.toString(f.get(0)));
        }
        int active = glGetInteger(GL_ACTIVE_TEXTURE);
        s.put("transform feedback buffer", Integer.toString(glGetInteger(
                org.lwjgl.opengl.GL30C.GL_TRANSFORM_FEEDBACK_BUFFER_BINDING)));
        s.put("transform feedback buffer 0", Integer.toString(org.lwjgl.opengl.GL30C.glGetIntegeri(
                org.lwjgl.opengl.GL30C.GL_TRANSFORM_FEEDBACK_BUFFER_BINDING, 0)));
        if (org.lwjgl.opengl.GL.getCapabilities().OpenGL43) {
            s.put("shader storage buffer", Integer.toString(glGetInteger(
                    org.lwjgl.opengl.GL43C.GL_SHADER_STORAGE_BUFFER_BINDING)));
            s.put("shader storage buffer 0", Integer.toString(org.lwjgl.opengl.GL30C.glGetIntegeri(
                    org.lwjgl.opengl.GL43C.GL_SHADER_STORAGE_BUFFER_BINDING, 0)));
        }
        s.put("rasterizer discard", Boolean.toString(glIsEnabled(org.lwjgl.opengl.GL30C.GL_RASTERIZER_DISCARD)));
        s.put("alpha to coverage", Boolean.toString(glIsEnabled(org.lwjgl.opengl.GL13C.GL_SAMPLE_ALPHA_TO_COVERAGE)));
        for (int u = 0; u < org.jecosys.render.gl.TextureUnits.COUNT; u++) {
            glActiveTexture(GL_TEXTURE0 + u);
            s.put("unit " + u + " buffer texture", Integer.toString(glGetInteger(GL_TEXTURE_BINDING_BUFFER)));
            s.put("unit " + u + " 2D texture", Integer.toString(glGetInteger(GL_TEXTURE_BINDING_2D)));
            s.put("unit " + u + " sampler", Integer.toString(glGetInteger(GL_SAMPLER_BINDING)));
        }
        glActiveTexture(active);
        return s;
    }

    /** Host objects and unusual, non-default state, as a game might leave them. */
    private final class HostState implements AutoCloseable {
        final GlProgram program = new GlProgram(new GlTracker(), "overlay.vert", "overlay.frag");
        final int vao = glGenVertexArrays();
        final int vbo = glGenBuffers();
        final int ebo = glGenBuffers();
        final int tbo = glGenBuffers();
        final int[] textures = {glGenTextures(), glGenTextures(), glGenTextures(), glGenTextures(), glGenTextures()};
        final int feedback = glGenBuffers();

        HostState() {
            glBindVertexArray(vao);
            glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo);
            glBufferData(GL_ELEMENT_ARRAY_BUFFER, 64, GL_STATIC_DRAW);
            glBindBuffer(GL_TEXTURE_BUFFER, tbo);
            glBufferData(GL_TEXTURE_BUFFER, 64, GL_STATIC_DRAW);
            glBindBuffer(org.lwjgl.opengl.GL30C.GL_TRANSFORM_FEEDBACK_BUFFER, feedback);
            glBufferData(org.lwjgl.opengl.GL30C.GL_TRANSFORM_FEEDBACK_BUFFER, 256, GL_STATIC_DRAW);
            org.lwjgl.opengl.GL30C.glBindBufferRange(org.lwjgl.opengl.GL30C.GL_TRANSFORM_FEEDBACK_BUFFER, 0,
                    feedback, 64, 128);
            glBindBuffer(org.lwjgl.opengl.GL30C.GL_TRANSFORM_FEEDBACK_BUFFER, ebo);
            if (org.lwjgl.opengl.GL.getCapabilities().OpenGL43) {
                // a game's own storage buffers, which the compute resolve pass must leave as found
                org.lwjgl.opengl.GL30C.glBindBufferRange(org.lwjgl.opengl.GL43C.GL_SHADER_STORAGE_BUFFER, 0,
                        feedback, 0, 64);
                glBindBuffer(org.lwjgl.opengl.GL43C.GL_SHADER_STORAGE_BUFFER, vbo);
            }
            for (int u = 0; u < textures.length; u++) {
                glActiveTexture(GL_TEXTURE0 + u);
                glBindTexture(GL_TEXTURE_BUFFER, textures[u]);
                glTexBuffer(GL_TEXTURE_BUFFER, GL_R32F, tbo);
            }
            glActiveTexture(GL_TEXTURE0 + 3);
            glBindBuffer(GL_ARRAY_BUFFER, vbo);
            glBufferData(GL_ARRAY_BUFFER, 64, GL_STATIC_DRAW);
            program.use();
            glEnable(GL_BLEND);
            glBlendFuncSeparate(GL_ONE, GL_ONE, GL_ZERO, GL_DST_ALPHA);
            glBlendEquation(GL_FUNC_REVERSE_SUBTRACT);
            glEnable(GL_CULL_FACE);
            glCullFace(GL_FRONT);
            glFrontFace(GL_CW);
            glDisable(GL_DEPTH_TEST);
            glDepthFunc(GL_GREATER);
            glDepthMask(false);
            glEnable(GL_SCISSOR_TEST);
            glScissor(3, 4, 50, 60);
            glClearColor(0.9f, 0.1f, 0.2f, 0.5f);
            glViewport(40, 30, 200, 120);
        }

        @Override
        public void close() {
            glUseProgram(0);
            glBindVertexArray(0);
            program.close();
            glDeleteVertexArrays(vao);
            glDeleteBuffers(new int[] {vbo, ebo, tbo, feedback});
            glDeleteTextures(textures);
            glDisable(GL_BLEND);
            glDisable(GL_CULL_FACE);
            glDisable(GL_SCISSOR_TEST);
            glDepthMask(true);
            glBlendFuncSeparate(GL_ONE, GL_ZERO, GL_ONE, GL_ZERO);
            glBlendEquation(org.lwjgl.opengl.GL14C.GL_FUNC_ADD);
            glCullFace(GL_BACK);
            glFrontFace(GL_CCW);
            glDepthFunc(GL_LESS);
            glActiveTexture(GL_TEXTURE0);
        }
    }

    @Test
    void everyGlStateTheRendererTouchesIsTheSameAfterRender() {
        RenderSettings settings = standalone();
        settings.overlays().setShowField(true);
        settings.overlays().setShowWind(true);
        try (SceneRenderer renderer = new SceneRenderer(gl, world, settings)) {
            fb.bind();
            try (HostState host = new HostState()) {
                Map<String, String> before = census();
                assertEquals("40,30,200,120", before.get("viewport"), "the host's state is in place");
                for (boolean clear : new boolean[] {true, false}) {
                    settings.setClear(clear);
                    renderer.render(TestFrames.wind(world, 0.4, camera(200, 120)), camera(200, 120));
                    assertEquals(before, census(), "render(frame, camera), clear " + clear);
                    renderer.render(TestFrames.wind(world, 0.4, camera(W, H)), camera(W, H), W, H);
                    assertEquals(before, census(), "render(frame, camera, w, h), clear " + clear);
                }
                assertTrue(renderer.triangles() > 0, "something was drawn");
            }
        }
    }

    @Test
    void drawsOnlyInTheBoundViewportAndOverTheHostsBackgroundWhenNotClearing() {
        RenderSettings settings = standalone();
        settings.setClear(false);
        settings.setTerrain(false);
        try (SceneRenderer renderer = new SceneRenderer(gl, world, settings)) {
            fb.bind();
            // the host's own background: magenta, depth 1
            glClearColor(1f, 0f, 1f, 1f);
            glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
            int vx = 60;
            int vy = 40;
            int vw = 200;
            int vh = 140;
            glViewport(vx, vy, vw, vh);
            renderer.render(TestFrames.rest(world, camera(vw, vh)), camera(vw, vh));
            glViewport(0, 0, W, H);
            Pixels.read(W, H, px);
            int outsideChanged = 0;
            int insidePlant = 0;
            int insideHost = 0;
            for (int y = 0; y < H; y++) {
                for (int x = 0; x < W; x++) {
                    boolean magenta = Pixels.red(px, W, x, y) == 255 && Pixels.green(px, W, x, y) == 0
                            && Pixels.blue(px, W, x, y) == 255;
                    boolean inside = x >= vx && x < vx + vw && y >= vy && y < vy + vh;
                    if (!inside) {
                        outsideChanged += magenta ? 0 : 1;
                    } else if (magenta) {
                        insideHost++;
                    } else {
                        insidePlant++;
                    }
                }
            }
            assertEquals(0, outsideChanged, "nothing drawn outside the bound viewport");
            assertTrue(insidePlant > 300, "plants drawn inside it: " + insidePlant);
            assertTrue(insideHost > vw * vh / 4, "neither sky nor terrain drawn over the host's background: "
                    + insideHost);
        }
    }

    @Test
    void aCameraFromTheHostsMatricesDrawsWhatTheEquivalentViewCameraDraws() {
        RenderSettings settings = standalone();
        try (SceneRenderer renderer = new SceneRenderer(gl, world, settings)) {
            ViewCamera vc = camera(W, H);
            fb.bind();
            renderer.render(TestFrames.wind(world, 0.7, vc), vc, W, H);
            Pixels.read(W, H, other);
            // the same pose built with JOML by a game: lookAt along the camera's forward, perspective
            Matrix4f view = new Matrix4f().setLookAt(0f, 1.6f, 9f, 0f, 1.6f - (float) Math.sin(0.2),
                    9f - (float) Math.cos(0.2), 0f, 1f, 0f);
            Matrix4f proj = new Matrix4f().setPerspective((float) Math.toRadians(50), W / (float) H, 0.05f, 200f);
            MatrixCamera mc = new MatrixCamera(view, proj);
            assertEquals(vc.x(), mc.x(), 1e-5);
            assertEquals(vc.y(), mc.y(), 1e-5);
            assertEquals(vc.z(), mc.z(), 1e-5);
            assertEquals(vc.viewHeightPerMetre(), mc.viewHeightPerMetre(), 1e-5);
            renderer.render(TestFrames.wind(world, 0.7, mc), mc, W, H);
            Pixels.read(W, H, px);
            long diff = 0;
            for (int i = 0; i < W * H * 4; i++) {
                diff += Math.abs((px.get(i) & 0xff) - (other.get(i) & 0xff));
            }
            double mean = diff / (double) (W * H * 3);
            assertTrue(mean < 0.5, "mean difference per channel " + mean);
            // a rolled camera sees another image: the host's matrices are used, not re-derived
            Matrix4f rolled = new Matrix4f().rotateZ(0.5f).mul(view);
            renderer.render(TestFrames.wind(world, 0.7, new MatrixCamera(rolled, proj)), new MatrixCamera(rolled, proj), W, H);
            Pixels.read(W, H, px);
            int changed = 0;
            for (int i = 0; i < W * H; i++) {
                changed += px.getInt(4 * i) != other.getInt(4 * i) ? 1 : 0;
            }
            assertTrue(changed > W * H / 10, "rolled view changes the image: " + changed);
            // an orthographic camera from above draws plants too (no perspective assumed anywhere)
            float px0 = world.plantX(0);
            float py0 = world.plantY(0);
            float pz0 = world.plantZ(0);
            Matrix4f top = new Matrix4f().setLookAt(px0, py0 + 5f, pz0, px0, py0, pz0, 0f, 0f, -1f);
            Matrix4f ortho = new Matrix4f().setOrtho(-1.2f, 1.2f, -0.75f, 0.75f, 0.1f, 20f);
            renderer.render(TestFrames.rest(world, new MatrixCamera(top, ortho)), new MatrixCamera(top, ortho), W, H);
            Pixels.read(W, H, px);
            int green = 0;
            for (int y = 0; y < H; y++) {
                for (int x = 0; x < W; x++) {
                    int r = Pixels.red(px, W, x, y);
                    int g = Pixels.green(px, W, x, y);
                    green += g > r + 10 && g > Pixels.blue(px, W, x, y) ? 1 : 0;
                }
            }
            renderer.drawPlants = false;
            renderer.render(TestFrames.rest(world, new MatrixCamera(top, ortho)), new MatrixCamera(top, ortho), W, H);
            renderer.drawPlants = true;
            Pixels.read(W, H, other);
            int plantPixels = 0;
            for (int i = 0; i < W * H; i++) {
                plantPixels += px.getInt(4 * i) != other.getInt(4 * i) ? 1 : 0;
            }
            assertTrue(green > 100 && plantPixels > 300, "plants seen from above, orthographic: " + green
                    + " green pixels, " + plantPixels + " pixels differ from the bare terrain");
        }
    }

    @Test
    void theWrappedContextLeavesTheHostsContextAliveAndRefusesAThreadWithoutOne() throws Exception {
        GlContext second = GlContext.current(DebugOutput.OFF);
        assertFalse(second.ownsContext());
        assertEquals(0, second.window());
        second.close();
        second.close();
        // the context and its capabilities are still the host's: GL still works on this thread
        fb.bind();
        glClearColor(0f, 1f, 0f, 1f);
        glClear(GL_COLOR_BUFFER_BIT);
        Pixels.read(W, H, px);
        assertEquals(255, Pixels.green(px, W, 5, 5));
        assertTrue(owner.ownsContext());
        AtomicReference<Throwable> thrown = new AtomicReference<>();
        Thread t = new Thread(() -> {
            try {
                GlContext.current(DebugOutput.OFF);
            } catch (Throwable e) {
                thrown.set(e);
            }
        });
        t.start();
        t.join();
        assertTrue(thrown.get() instanceof IllegalStateException, String.valueOf(thrown.get()));
        assertTrue(thrown.get().getMessage().contains("no OpenGL context is current"), thrown.get().getMessage());
    }

    @Test
    void closeAllClosesEveryResourceEvenPastAFailure() {
        List<String> closed = new ArrayList<>();
        AutoCloseable ok1 = () -> closed.add("a");
        AutoCloseable bad1 = () -> {
            closed.add("b");
            throw new IllegalStateException("b failed");
        };
        AutoCloseable bad2 = () -> {
            closed.add("c");
            throw new java.io.IOException("c failed");
        };
        AutoCloseable ok2 = () -> closed.add("d");
        IllegalStateException e = assertThrows(IllegalStateException.class,
                () -> Closing.closeAll(ok1, bad1, null, bad2, ok2));
        assertEquals(List.of("a", "b", "c", "d"), closed);
        assertEquals("b failed", e.getMessage());
        assertEquals(1, e.getSuppressed().length);
        assertNotEquals(null, e.getSuppressed()[0].getCause());
        closed.clear();
        assertThrows(IllegalStateException.class, () -> Closing.closeReverse(List.of(ok1, bad1, ok2)));
        assertEquals(List.of("d", "b", "a"), closed);
    }

    /** The library's whole picture with the test's sky. */
    private static RenderSettings standalone() {
        RenderSettings s = RenderSettings.standalone();
        s.lighting().setSky(SKY);
        return s;
    }
}
