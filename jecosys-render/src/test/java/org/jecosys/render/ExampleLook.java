package org.jecosys.render;

import java.awt.image.BufferedImage;
import java.io.BufferedInputStream;
import java.io.DataInputStream;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import org.jecosys.math.Progress;
import org.jecosys.math.ViewCamera;
import org.jecosys.render.GlContext.DebugOutput;
import org.jecosys.render.gl.GlFramebuffer;
import org.jecosys.render.gl.Pixels;
import org.jecosys.scene.Scene;
import org.jecosys.scene.SceneDef;
import org.jecosys.scene.SceneFiles;
import org.jecosys.scene.Scenes;
import org.jecosys.sim.Simulation;
import org.lwjgl.system.MemoryUtil;

/**
 * Issue 38's measures of an engine example's picture of the meadow's start view, for the examples'
 * tests (their test modes write the pictures and the block series; see the examples' TestCapture):
 * how much of the lower half keeps the game's own ground colour, and the sheen, the median over
 * 16 x 16 blocks in the ground part of the picture of the temporal standard deviation of the block's
 * mean luminance (as {@link WindSheenTest} measures it for the library's renderer), and the same
 * sheen in the library's viewer's picture at the same camera and size ({@link #viewer}).
 */
public final class ExampleLook {
    /** The side of the sheen's blocks, pixels (the examples' TestCapture.BLOCK). */
    public static final int BLOCK = 16;
    /** The examples' test mode steps the plants by this frame time, seconds. */
    public static final float FRAME_SECONDS = 1 / 30f;

    private ExampleLook() {
    }

    /**
     * The share of the lower half of a picture that shows the game's own ground: pixels that keep
     * the colour they had before the plants were drawn (the game's ground as lit, read back in the
     * same frame), within {@link ImageMetrics#sameColour} (3 levels, or 6% of the channel: what the
     * library's cover skin test counts as the game's brown), not counting sky (the colour of the
     * picture's top middle pixel before the plants).
     *
     * @param shot   the frame
     * @param ground the same frame before the plants were drawn
     * @return the share, in [0, 1]
     */
    public static double groundShare(BufferedImage shot, BufferedImage ground) {
        int w = shot.getWidth();
        int h = shot.getHeight();
        if (ground.getWidth() != w || ground.getHeight() != h) {
            throw new IllegalArgumentException("pictures of different sizes");
        }
        int sky = ground.getRGB(w / 2, 0) & 0xFFFFFF;
        int n = 0;
        for (int y = h - h / 2; y < h; y++) {
            for (int x = 0; x < w; x++) {
                int g = ground.getRGB(x, y) & 0xFFFFFF;
                if (!ImageMetrics.sameColour(g, sky) && ImageMetrics.sameColour(shot.getRGB(x, y) & 0xFFFFFF, g)) {
                    n++;
                }
            }
        }
        return n / (double) (w * (h / 2));
    }

    /**
     * The highest row of ground in the middle column of a picture drawn without plants (GL rows,
     * from the bottom): the highest one whose colour is not the sky's (the top middle pixel's).
     *
     * @param ground the game's frame before the plants
     * @return the row, or -1 when the column is all sky
     */
    public static int groundTop(BufferedImage ground) {
        int h = ground.getHeight();
        int x = ground.getWidth() / 2;
        int sky = ground.getRGB(x, 0) & 0xFFFFFF;
        for (int y = 0; y < h; y++) {
            if (!ImageMetrics.sameColour(ground.getRGB(x, y) & 0xFFFFFF, sky)) {
                return h - 1 - y;
            }
        }
        return -1;
    }

    /**
     * Per frame, the mean luminance of each whole block of a picture, blocks from the bottom left
     * corner, row by row upwards (GL order).
     *
     * @param width  picture width, pixels
     * @param height picture height, pixels
     * @param block  the blocks' side, pixels
     * @param means  [frame][block row * blocks across + block column], 0-255
     */
    public record BlockSeries(int width, int height, int block, float[][] means) {
        /** {@return the blocks across} */
        public int across() {
            return width / block;
        }

        /** {@return the block rows} */
        public int rows() {
            return height / block;
        }

        /**
         * Reads what an example's {@code --sheen FILE} wrote: four ints (width, height, block, frames),
         * then the frames' block means as floats, big-endian.
         *
         * @param file the file
         * @return the series
         * @throws IOException when it cannot be read or is cut short
         */
        public static BlockSeries read(Path file) throws IOException {
            try (DataInputStream in = new DataInputStream(new BufferedInputStream(Files.newInputStream(file)))) {
                int w = in.readInt();
                int h = in.readInt();
                int b = in.readInt();
                int frames = in.readInt();
                float[][] m = new float[frames][(w / b) * (h / b)];
                for (float[] f : m) {
                    for (int i = 0; i < f.length; i++) {
                        f[i] = in.readFloat();
                    }
                }
                return new BlockSeries(w, h, b, m);
            }
        }

        /**
         * The sheen below a row: over the blocks wholly in GL rows [y0, y1), the median of the
         * temporal standard deviation ({@link ImageMetrics#sd}, population) of the block's mean
         * luminance over the frames. 1/255 units.
         *
         * @param y0 lowest row, inclusive
         * @param y1 highest row, exclusive
         * @return the median, or NaN without a block
         */
        public double medianSd(int y0, int y1) {
            int bx = across();
            double[] sds = new double[bx * rows()];
            int n = 0;
            double[] series = new double[means.length];
            for (int j = 0; j < rows(); j++) {
                if (j * block < y0 || (j + 1) * block > y1) {
                    continue;
                }
                for (int i = 0; i < bx; i++) {
                    for (int f = 0; f < means.length; f++) {
                        series[f] = means[f][j * bx + i];
                    }
                    sds[n++] = ImageMetrics.sd(series);
                }
            }
            if (n == 0) {
                return Double.NaN;
            }
            double[] v = Arrays.copyOf(sds, n);
            Arrays.sort(v);
            return n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
        }

        /**
         * The sheen of the ground part: {@link #medianSd} over rows [0, top], and in its near, middle and far
         * thirds (as {@link WindSheenTest} splits the ground).
         *
         * @param top the highest ground row (GL rows)
         * @return {whole, near, middle, far}
         */
        public double[] sheen(int top) {
            return new double[] {medianSd(0, top + 1), medianSd(0, top / 3), medianSd(top / 3, 2 * top / 3),
                    medianSd(2 * top / 3, top)};
        }
    }

    /** Block means of an RGBA read-back (GL rows bottom up), as the examples' TestCapture computes them. */
    static void blockLuminance(ByteBuffer rgba, int w, int h, float[] dest) {
        int bx = w / BLOCK;
        int by = h / BLOCK;
        for (int j = 0; j < by; j++) {
            for (int i = 0; i < bx; i++) {
                double sum = 0;
                for (int y = j * BLOCK; y < (j + 1) * BLOCK; y++) {
                    for (int x = i * BLOCK, k = 4 * (y * w + x); x < (i + 1) * BLOCK; x++, k += 4) {
                        sum += 0.2126 * (rgba.get(k) & 255) + 0.7152 * (rgba.get(k + 1) & 255)
                                + 0.0722 * (rgba.get(k + 2) & 255);
                    }
                }
                dest[j * bx + i] = (float) (sum / (BLOCK * BLOCK));
            }
        }
    }

    /**
     * The library viewer's picture of a scene's start view and its sheen.
     *
     * @param series the block series, one entry per frame
     * @param top    the highest ground row in the middle column (GL rows) of its terrain without plants
     *               (value under 0.55, as {@link WindSheenTest} finds it)
     * @param seconds how long rendering and measuring took, wall clock
     */
    public record Viewer(BlockSeries series, int top, double seconds) {
    }

    /**
     * The scene's start view as the library's viewer draws it (SceneRenderer with its own terrain,
     * cover and sky, the scene's samples, the low quality on a software rasteriser as the viewer
     * picks it), with the simulation stepped {@link #FRAME_SECONDS} per frame from its start with the
     * start camera, as the examples' test mode steps theirs; the block luminance of each frame. A
     * headless context of its own on the calling thread; allocates.
     *
     * @param scene  the scene file
     * @param width  picture width
     * @param height picture height
     * @param frames frames
     * @return the series and the ground's top row
     * @throws Exception when the scene cannot be read or built
     */
    public static Viewer viewer(Path scene, int width, int height, int frames) throws Exception {
        long t0 = System.nanoTime();
        Scene s = SceneFiles.read(scene);
        SceneDef def = s.def();
        ByteBuffer px = MemoryUtil.memAlloc(4 * width * height);
        float[][] means = new float[frames][(width / BLOCK) * (height / BLOCK)];
        int top = -1;
        try (Simulation sim = Scenes.simulation(s, 0, Progress.NONE);
             GlContext gl = GlContext.headless(DebugOutput.OFF)) {
            ViewCamera cam = ViewCamera.of(def.camera(),
                    sim.world().terrain().heightfield().height(def.camera().x(), def.camera().z()),
                    width / (double) height);
            SoftwareQuality.apply(gl, sim, null);
            try (GlFramebuffer fb = new GlFramebuffer(gl.tracker(), width, height, def.render().antialiasing());
                 SceneRenderer r = new SceneRenderer(gl, sim.world(), RenderScenes.settings(def))) {
                for (int f = 0; f < frames; f++) {
                    sim.step(FRAME_SECONDS, cam);
                    fb.bind();
                    if (f == 0) {
                        r.drawPlants = false; // the terrain alone: where the ground ends
                        r.render(sim.latestFrame(), cam, width, height);
                        r.drawPlants = true;
                        fb.resolve();
                        Pixels.read(width, height, px);
                        for (int y = 0; y < height; y++) {
                            int c = ImageMetrics.rgb(Pixels.red(px, width, width / 2, y),
                                    Pixels.green(px, width, width / 2, y), Pixels.blue(px, width, width / 2, y));
                            if (ImageMetrics.hsv(c)[2] < 0.55) {
                                top = y;
                            }
                        }
                        fb.bind();
                    }
                    r.render(sim.latestFrame(), cam, width, height);
                    fb.resolve();
                    Pixels.read(width, height, px);
                    blockLuminance(px, width, height, means[f]);
                }
                int error = org.lwjgl.opengl.GL11C.glGetError();
                if (error != 0) {
                    throw new IllegalStateException(String.format("GL error 0x%04X drawing the viewer's picture", error));
                }
            }
        } finally {
            MemoryUtil.memFree((java.nio.Buffer) px);
        }
        return new Viewer(new BlockSeries(width, height, BLOCK, means), top, (System.nanoTime() - t0) / 1e9);
    }

    /** How an example's test runs the example in a child JVM on a virtual display (its own {@code run}). */
    @FunctionalInterface
    public interface ExampleRun {
        /**
         * Runs the example.
         *
         * @param display the virtual display
         * @param name    the run's name (its screenshot and log)
         * @param width   window width, pixels
         * @param height  window height, pixels
         * @param frames  frames of the test mode
         * @param extra   more arguments
         * @return the run's screenshot and what it printed
         * @throws Exception when the run fails
         */
        ExampleShot run(VirtualDisplay display, String name, int width, int height, int frames, String... extra)
                throws Exception;
    }

    /**
     * Issue 38's sheen check for an engine example: runs the example's start view of {@code scene} for
     * {@code frames} frames with {@code --sheen} (in a child JVM) while this JVM draws the library's viewer
     * picture at the same camera and size ({@link #viewer}); asserts no GL error in the example and that the
     * median temporal s.d. of 16 x 16 block luminance over the ground (below the lower of the two pictures'
     * ground tops) is within 30% of the viewer's, and prints both with a {@code [look]} line.
     *
     * @param engine  the engine's name in the printed line
     * @param out     the example's test output folder
     * @param scene   the scene file
     * @param width   picture width, pixels
     * @param height  picture height, pixels
     * @param frames  frames at 1/30 s
     * @param example the example's run
     * @throws Exception when a run fails
     */
    public static void assertSheenLikeTheViewer(String engine, Path out, String scene, int width, int height,
                                                int frames, ExampleRun example) throws Exception {
        Path sheen = out.resolve("sheen.bin");
        Path ground = out.resolve("sheen-ground.png");
        Files.createDirectories(out);
        Files.deleteIfExists(sheen);
        long t0 = System.nanoTime();
        Viewer viewer;
        ExampleShot shot;
        try (VirtualDisplay display = VirtualDisplay.start(1024, 768)) {
            java.util.concurrent.CompletableFuture<ExampleShot> run = java.util.concurrent.CompletableFuture.supplyAsync(
                    () -> {
                        try {
                            return example.run(display, "sheen", width, height, frames, "--scene", scene,
                                    "--start-view", "--ground-screenshot", ground.toString(), "--sheen",
                                    sheen.toString());
                        } catch (Exception e) {
                            throw new IllegalStateException(e);
                        }
                    });
            viewer = viewer(Path.of(scene), width, height, frames);
            shot = run.join();
        }
        org.junit.jupiter.api.Assertions.assertTrue(shot.noGlErrors(), "GL errors in the example's run");
        BufferedImage groundOnly = javax.imageio.ImageIO.read(ground.toFile());
        BlockSeries series = BlockSeries.read(sheen);
        int top = Math.min(groundTop(groundOnly), viewer.top());
        double[] e = series.sheen(top);
        double[] v = viewer.series().sheen(top);
        double ratio = e[0] / v[0];
        System.out.printf("[look] %s example vs the library's viewer, meadow start view %dx%d, %d frames: median"
                + " temporal s.d. of 16x16 block luminance over the ground (rows 0-%d) %.2f vs %.2f: ratio %.2f"
                + " (0.7-1.3); near/middle/far %.2f/%.2f/%.2f vs %.2f/%.2f/%.2f; ground top %d (example) %d"
                + " (viewer); %.0f s%n", engine, width, height, frames, top, e[0], v[0], ratio, e[1], e[2], e[3],
                v[1], v[2], v[3], groundTop(groundOnly), viewer.top(), (System.nanoTime() - t0) / 1e9);
        org.junit.jupiter.api.Assertions.assertTrue(v[0] > 0, "the viewer's picture moves in the wind: " + v[0]);
        org.junit.jupiter.api.Assertions.assertTrue(ratio >= 0.7 && ratio <= 1.3, String.format(
                "the example's sheen %.2f is %.2f times the viewer's %.2f, want 0.7-1.3", e[0], ratio, v[0]));
    }
}
