package org.jecosys.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.jecosys.render.GlContext.DebugOutput;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.InputStream;
import java.nio.ByteBuffer;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.jecosys.math.ViewCamera;
import org.jecosys.sim.Frame;
import org.jecosys.sim.World;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestInstance;
import org.lwjgl.system.MemoryUtil;
import org.jecosys.render.gl.GlFramebuffer;
import org.jecosys.render.gl.Pixels;
import org.junit.jupiter.api.Tag;

/**
 * The plant renderer's output on C1 against reference images of the same frames and views (test
 * resources {@code reference/c1-*.png}): the mean colour difference stays within 2/255, over the
 * whole image and over the pixels that show plants, so a change to the rendering path that is meant
 * to leave the picture alone is caught. The references were first made by the renderer that resolved
 * every component on the render thread (the GPU resolve matched them to 0.000/255); they were
 * regenerated when the look changed on purpose: the sun-lit terrain with contact darkening, then the
 * plants' light, colour variation and thin-part widening, the ground reaching the horizon, then the
 * blades' shading (by height in the tuft, across the midrib) and contact darkening sized to each plant's
 * footprint, then the wind's sheen on bent blades, then its stronger response to the bend and at
 * grazing views, then the near plants blended by their coverage on a target without samples, then the
 * wind's sheen made stronger (1.3 times on the plants, 1.4 on the ground cover) when blending thin parts
 * on the samples had hidden part of it. Every {@link ResolvePath} the context supports is checked against the same
 * references. Run with the environment variable {@code JECOSYS_WRITE_RENDER_REFERENCE=DIR} to write
 * this renderer's images into DIR instead.
 */
@Tag("lwjgl-compat")
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
class RenderPathEquivalenceTest {
    private static final int W = 320;
    private static final int H = 200;

    private GlContext gl;
    private GlFramebuffer fb;
    private World world;
    private SceneRenderer renderer;
    private SceneRenderer feedback;
    private SceneRenderer compute;
    private ByteBuffer px;
    private ByteBuffer bare;

    @BeforeAll
    void setUp() {
        gl = GlContext.headless(DebugOutput.ON);
        fb = new GlFramebuffer(gl.tracker(), W, H);
        world = RenderScenes.build(RenderScenes.load("c1.xml"));
        renderer = new SceneRenderer(gl, world, RenderSettings.standalone());
        feedback = new SceneRenderer(gl, world, RenderSettings.standalone(), ResolvePath.TRANSFORM_FEEDBACK);
        if (ResolvePath.COMPUTE.supported(gl.capabilities())) {
            compute = new SceneRenderer(gl, world, RenderSettings.standalone(), ResolvePath.COMPUTE);
        }
        px = MemoryUtil.memAlloc(4 * W * H);
        bare = MemoryUtil.memAlloc(4 * W * H);
    }

    @AfterAll
    void tearDown() {
        MemoryUtil.memFree((java.nio.Buffer) px);
        MemoryUtil.memFree((java.nio.Buffer) bare);
        if (renderer != null) {
            renderer.close();
            feedback.close();
            if (compute != null) {
                compute.close();
            }
            fb.close();
            gl.debug().check("the render path test");
            gl.close();
        }
    }

    /** The first plant of a species, by index. */
    static int first(World world, int species) {
        for (int p = 0; p < world.plantCount(); p++) {
            if (world.plantSpecies(p) == species) {
                return p;
            }
        }
        throw new IllegalStateException("no plant of species " + species);
    }

    /**
     * Views of C1, each filled with plants: 0.9 m from a yellow flower (attached heads and petals),
     * 1.3 m from a purple flower, and looking down on a grass tuft from 16 m (the far levels, with
     * the transition band).
     */
    static ViewCamera view(World world, int i) {
        int p = first(world, i == 2 ? 0 : i + 1);
        double d = i == 0 ? 0.35 : i == 1 ? 0.45 : 15;
        double up = i == 2 ? 6 : 0.75;
        double target = i == 2 ? 0 : 0.4;
        ViewCamera c = new ViewCamera();
        c.setPosition(world.plantX(p), world.plantY(p) + up, world.plantZ(p) + d);
        c.setOrientation(0, -Math.atan2(up - target, d));
        c.setLens(Math.toRadians(i == 2 ? 12 : 50), W / (double) H, 0.05, 200);
        return c;
    }

    static Frame frame(World world, int i) {
        return i == 0 ? TestFrames.rest(world) : TestFrames.wind(world, 0.35 * i);
    }

    /**
     * Mean colour difference to the reference, /255 per channel: {@code [0]} over the whole image,
     * {@code [1]} over the pixels where plants are in either image (those that differ from the same
     * view drawn without plants).
     */
    private double[] meanDifference(SceneRenderer renderer, int i) throws IOException {
        fb.bind();
        renderer.drawPlants = false;
        renderer.render(TestFrames.decide(world, frame(world, i), view(world, i)), view(world, i), W, H);
        renderer.drawPlants = true;
        Pixels.read(W, H, bare);
        renderer.render(TestFrames.decide(world, frame(world, i), view(world, i)), view(world, i), W, H);
        Pixels.read(W, H, px);
        String out = System.getenv("JECOSYS_WRITE_RENDER_REFERENCE");
        if (out != null) {
            Pixels.writePng(Path.of(out, "c1-" + i + ".png"), px, W, H);
            return new double[2];
        }
        BufferedImage ref;
        try (InputStream in = RenderPathEquivalenceTest.class.getResourceAsStream("reference/c1-" + i + ".png")) {
            assertTrue(in != null, "reference image c1-" + i + ".png");
            ref = ImageIO.read(in);
        }
        assertEquals(W, ref.getWidth());
        assertEquals(H, ref.getHeight());
        long sum = 0;
        long plantSum = 0;
        int plantPixels = 0;
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                int rgb = ref.getRGB(x, H - 1 - y);
                int r = (rgb >> 16) & 255;
                int g = (rgb >> 8) & 255;
                int b = rgb & 255;
                int d = Math.abs(r - Pixels.red(px, W, x, y)) + Math.abs(g - Pixels.green(px, W, x, y))
                        + Math.abs(b - Pixels.blue(px, W, x, y));
                sum += d;
                boolean plantHere = r != Pixels.red(bare, W, x, y) || g != Pixels.green(bare, W, x, y)
                        || b != Pixels.blue(bare, W, x, y)
                        || px.getInt(4 * (y * W + x)) != bare.getInt(4 * (y * W + x));
                if (plantHere) {
                    plantSum += d;
                    plantPixels++;
                }
            }
        }
        assertTrue(plantPixels > 150, "view " + i + " shows plants: " + plantPixels + " pixels");
        return new double[] {sum / (3.0 * W * H), plantSum / (3.0 * plantPixels)};
    }

    @Test
    void theRendererDrawsWhatThePreviousRendererDrewOnC1() throws IOException {
        assertEquals(ResolvePath.best(gl), renderer.plants().path(), "the best path by default");
        for (SceneRenderer r : new SceneRenderer[] {renderer, feedback, compute}) {
            if (r == null) {
                continue;
            }
            for (int i = 0; i < 3; i++) {
                double[] d = meanDifference(r, i);
                String at = r.plants().path() + " view " + i;
                System.out.printf("render path %s: mean difference %.3f / 255, over plant pixels %.3f / 255%n", at,
                        d[0], d[1]);
                assertTrue(d[0] <= 2.0, at + ": mean colour difference " + d[0] + " / 255");
                assertTrue(d[1] <= 2.0, at + ": mean colour difference over plant pixels " + d[1] + " / 255");
            }
        }
    }
}
