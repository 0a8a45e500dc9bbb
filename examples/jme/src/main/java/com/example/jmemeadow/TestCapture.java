package com.example.jmemeadow;

import static org.lwjgl.opengl.GL11C.GL_NO_ERROR;
import static org.lwjgl.opengl.GL11C.GL_RENDERER;
import static org.lwjgl.opengl.GL11C.GL_VERSION;
import static org.lwjgl.opengl.GL11C.glGetError;
import static org.lwjgl.opengl.GL11C.glGetString;

import com.jme3.post.SceneProcessor;
import com.jme3.profile.AppProfiler;
import com.jme3.renderer.Camera;
import com.jme3.renderer.RenderManager;
import com.jme3.renderer.ViewPort;
import com.jme3.renderer.queue.RenderQueue;
import com.jme3.texture.FrameBuffer;
import com.jme3.util.BufferUtils;
import java.awt.image.BufferedImage;
import java.io.BufferedOutputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.ByteBuffer;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.jecosys.sim.Frame;
import org.jecosys.sim.World;
import org.jecosys.terrain.Heightfield;
import com.jme3.math.Vector3f;

/**
 * The example's test mode: reports every GL error after each phase of a frame (the app's update, jME's
 * scene, the plants, the GUI), and after the last frame saves the finished frame (GUI included) as a
 * PNG, prints what a test checks in it, one {@code [jme-meadow] ...} line each (where the HUD text is,
 * bare ground, plants, the player, the mean bend near the player and away from it, in how many of
 * the last half of the frames drawing the plants allocated on the render thread, the GL error count)
 * and stops the game. Image coordinates have their origin at the top left. With {@code --restart-at N}
 * it also counts the pixels the plants' pass changes (the frame read before and after it) in frames N
 * and N + 1 (the last before the restart and the first after it) and in the last frame:
 * {@code plant pass pixels in frame F: P}. With {@code --start-view} it prints the camera and the back
 * buffer's samples instead of the probes (there is no player); with {@code --ground-screenshot} it also
 * saves the last frame as it is before the plants are drawn; with {@code --sheen} it writes each frame's
 * block luminance ({@link #blockLuminance}, {@link #writeSheen}). Render thread.
 */
final class TestCapture {
    private static final String TAG = "[jme-meadow] ";
    private final JmeMeadowGame game;
    private final JmeMeadowGame.Options options;
    private final Probe sceneDone = new Probe("jME scene");
    private final Probe plantsDone = new Probe("plants");
    private final Probe guiDone = new Probe("GUI");
    private final long start = System.nanoTime();
    private final com.sun.management.ThreadMXBean threads =
            (com.sun.management.ThreadMXBean) java.lang.management.ManagementFactory.getThreadMXBean();
    private int frame;
    private int errors;
    private boolean first = true;
    private long drawStart;
    private int drawsMeasured;
    private int drawsAllocating;
    private long drawMostBytes;
    /** Read-backs of the frame (RGBA, GL rows bottom up): before the plants' pass and after it. */
    private ByteBuffer before;
    private ByteBuffer after;
    /** Per frame, the mean luminance of each {@link #BLOCK} x {@link #BLOCK} block (--sheen). */
    private float[][] sheen;

    /** The side of the sheen's blocks, pixels. */
    static final int BLOCK = 16;

    TestCapture(JmeMeadowGame game, JmeMeadowGame.Options options) {
        this.game = game;
        this.options = options;
        game.getViewPort().addProcessor(plantsDone);  // after the plants' processor and any other
        game.getGuiViewPort().addProcessor(guiDone);
    }

    /** Start of a frame's update (the app states, the plants' included, have updated). */
    void beforeFrame() {
        if (first) {
            first = false;
            // the plant state put its processor first when it initialized: check just before it
            game.getViewPort().getProcessors().add(0, sceneDone);
            System.out.println(TAG + "GL " + glGetString(GL_VERSION) + " | " + glGetString(GL_RENDERER)
                    + " | renderer " + options.renderer() + " | gamma " + options.gamma() + " | LWJGL "
                    + org.lwjgl.Version.getVersion());
            System.out.println(TAG + "scene " + options.scene() + ": " + game.plants().simulation().plantCount()
                    + " plants, " + game.plants().simulation().componentCount() + " components, "
                    + game.plants().simulation().world().plants().textures().layers() + " textures, "
                    + game.plants().simulation().world().plants().meshComponents() + " glTF meshes");
        }
        check("update");
    }

    private void check(String phase) {
        for (int e = glGetError(); e != GL_NO_ERROR; e = glGetError()) {
            errors++;
            System.out.printf("%sGL error 0x%04X after %s in frame %d%n", TAG, e, phase, frame + 1);
        }
    }

    /** Whether the frame being drawn (1-based) is one whose plant pass pixels are counted. */
    private boolean countsPlantPass(int f) {
        int r = options.restartAt();
        return r > 0 && (f == r || f == r + 1 || f == options.frames());
    }

    /** Before the plants' pass: the ground screenshot (last frame) and the frame to compare with. */
    private void beforePlants() {
        int f = frame + 1;
        boolean ground = options.groundShot() != null && f == options.frames();
        if (ground || countsPlantPass(f)) {
            before = read(before);
        }
        if (ground) {
            write(before, options.groundShot());
        }
    }

    /** After the plants' pass, before the GUI: the pixels it changed, the frame's block luminance. */
    private void afterPlants() {
        int f = frame + 1;
        if (!countsPlantPass(f) && options.sheen() == null) {
            return;
        }
        after = read(after);
        if (countsPlantPass(f)) {
            int changed = 0;
            for (int i = 0; i < after.capacity(); i += 4) {
                if (after.get(i) != before.get(i) || after.get(i + 1) != before.get(i + 1)
                        || after.get(i + 2) != before.get(i + 2)) {
                    changed++;
                }
            }
            System.out.printf("%splant pass pixels in frame %d: %d (context generation %d)%n", TAG, f, changed,
                    game.plants().contextGeneration());
        }
        if (options.sheen() != null) {
            Camera cam = game.getCamera();
            if (sheen == null) {
                sheen = new float[options.frames()][(cam.getWidth() / BLOCK) * (cam.getHeight() / BLOCK)];
            }
            blockLuminance(after, cam.getWidth(), cam.getHeight(), sheen[frame]);
        }
    }

    /**
     * The mean luminance (0.2126 R + 0.7152 G + 0.0722 B, 0-255 as stored) of each whole
     * {@code BLOCK} x {@code BLOCK} block of a read-back, blocks from the bottom-left corner, row by row
     * upwards (GL order); the rows and columns left over at the top and right are not in any block.
     */
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
     * Writes the sheen's series: four ints (width, height, block side, frames), then per frame the
     * block means of {@link #blockLuminance} as floats (big-endian, {@code DataOutputStream}).
     */
    private void writeSheen(int w, int h) {
        Path out = options.sheen().toAbsolutePath();
        try {
            Files.createDirectories(out.getParent());
            try (DataOutputStream d = new DataOutputStream(new BufferedOutputStream(Files.newOutputStream(out)))) {
                d.writeInt(w);
                d.writeInt(h);
                d.writeInt(BLOCK);
                d.writeInt(sheen.length);
                for (float[] f : sheen) {
                    for (float v : f) {
                        d.writeFloat(v);
                    }
                }
            }
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        System.out.println(TAG + "sheen " + out + " " + sheen.length + " frames");
    }

    /** The frame now (the default framebuffer), RGBA, GL rows bottom up, into {@code into} or a new buffer. */
    private ByteBuffer read(ByteBuffer into) {
        Camera cam = game.getCamera();
        ByteBuffer px = into != null ? into : BufferUtils.createByteBuffer(4 * cam.getWidth() * cam.getHeight());
        px.clear();
        game.getRenderManager().getRenderer().readFrameBuffer(null, px);
        check("readFrameBuffer");
        return px;
    }

    /** Writes a read-back as an opaque PNG, rows top down. */
    private void write(ByteBuffer px, Path file) {
        Camera cam = game.getCamera();
        int w = cam.getWidth();
        int h = cam.getHeight();
        BufferedImage img = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                int i = 4 * ((h - 1 - y) * w + x);
                img.setRGB(x, y, (px.get(i) & 255) << 16 | (px.get(i + 1) & 255) << 8 | (px.get(i + 2) & 255));
            }
        }
        try {
            Path out = file.toAbsolutePath();
            Files.createDirectories(out.getParent());
            ImageIO.write(img, "png", out.toFile());
            System.out.println(TAG + "screenshot " + out + " " + w + "x" + h);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    private void frameDone() {
        frame++;
        if (frame == options.restartAt()) {
            // a new GL context from the next frame on: the plants' renderer must notice and remake its objects
            System.out.println(TAG + "restart after frame " + frame + ", generation "
                    + game.plants().contextGeneration());
            game.restart();
        }
        if (frame == options.frames()) {
            capture();
            game.stop();
        }
    }

    private void capture() {
        Camera cam = game.getCamera();
        int w = cam.getWidth();
        int h = cam.getHeight();
        write(read(null), options.screenshot());
        if (sheen != null) {
            writeSheen(w, h);
        }
        if (options.startView()) {
            int samples = org.lwjgl.opengl.GL11C.glGetInteger(org.lwjgl.opengl.GL13C.GL_SAMPLES);
            Vector3f eye = cam.getLocation();
            Vector3f ahead = cam.getDirection();
            System.out.printf("%sstart view: eye %.2f %.2f %.2f, looking %.3f %.3f %.3f, back buffer samples %d%n",
                    TAG, eye.x, eye.y, eye.z, ahead.x, ahead.y, ahead.z, samples);
        } else {
            probes(cam, w, h);
        }
        System.out.printf("%sdraw allocations: %d of %d frames, at most %d bytes%n", TAG, drawsAllocating,
                drawsMeasured, drawMostBytes);
        System.out.printf("%sframes %d in %.1f s%n", TAG, frame, (System.nanoTime() - start) / 1e9);
        if (options.restartAt() > 0) {
            System.out.println(TAG + "context generation " + game.plants().contextGeneration());
        }
        System.out.println(TAG + "gl errors: " + (errors == 0 ? "none" : errors));
    }

    /** Where the test should find the HUD, bare ground and plants, and how bent the plants are. */
    private void probes(Camera cam, int w, int h) {
        float top = 12;
        int hx0 = 12;
        int hy0 = Math.round(top);
        int hx1 = Math.round(12 + game.hud().getLineWidth());
        int hy1 = Math.round(top + game.hud().getLineHeight());
        System.out.printf("%sprobe hud %d %d %d %d%n", TAG, hx0, hy0, hx1, hy1);

        World world = game.plants().simulation().world();
        Heightfield t = world.terrain().heightfield();
        Vector3f s = new Vector3f();
        Vector3f p = new Vector3f();
        Vector3f eye = cam.getLocation();
        float px = game.playerX();
        float pz = game.playerZ();
        screen(cam, p.set(px, (float) t.height(px, pz) + 0.85f, pz), s, h);
        int playerSx = Math.round(s.x);
        int playerSy = Math.round(s.y);
        System.out.printf("%sprobe player %d %d%n", TAG, playerSx, playerSy);

        // bare ground: the visible ground point farthest from any plant (at least 1.3 m)
        double best = 1.3;
        int gx = -1;
        int gy = -1;
        for (double z = t.minZ() + 0.5; z < t.maxZ() - 0.5; z += 0.25) {
            for (double x = t.minX() + 0.5; x < t.maxX() - 0.5; x += 0.25) {
                double d = Math.hypot(x - eye.x, z - eye.z);
                if (d < 3 || d > 12 || Math.hypot(x - px, z - pz) < 1.5) {
                    continue;
                }
                screen(cam, p.set((float) x, (float) t.height(x, z), (float) z), s, h);
                if (!onScreen(s, w, h, hy1) || Math.hypot(s.x - playerSx, s.y - playerSy) < 60) {
                    continue;
                }
                double clear = nearestPlant(world, x, z);
                if (clear > best) {
                    best = clear;
                    gx = Math.round(s.x);
                    gy = Math.round(s.y);
                }
            }
        }
        if (gx >= 0) {
            System.out.printf("%sprobe ground %d %d%n", TAG, gx, gy);
        }
        // plants: grass tufts 2.5 to 7 m from the eye, away from the player, a hand's breadth above their base
        int found = 0;
        for (int q = 0; q < world.plantCount() && found < 12; q += 7) {
            float x = world.plantX(q);
            float z = world.plantZ(q);
            double d = Math.hypot(x - eye.x, z - eye.z);
            if (d < 2.5 || d > 7 || Math.hypot(x - px, z - pz) < 1.5) {
                continue;
            }
            screen(cam, p.set(x, world.plantY(q) + 0.12f, z), s, h);
            if (onScreen(s, w, h, hy1) && Math.hypot(s.x - playerSx, s.y - playerSy) > 60) {
                System.out.printf("%sprobe plant %d %d%n", TAG, Math.round(s.x), Math.round(s.y));
                found++;
            }
        }
        Frame f = game.plants().simulation().latestFrame();
        System.out.printf("%sbend near %.4f far %.4f%n", TAG, meanBend(world, f, px, pz, 0, 1.0),
                meanBend(world, f, px, pz, 3, 6));
    }

    /** Window coordinates of a world point, origin top left; z is the depth in [0, 1]. */
    private static Vector3f screen(Camera cam, Vector3f world, Vector3f dest, int h) {
        cam.getScreenCoordinates(world, dest);
        dest.y = h - 1 - dest.y;
        return dest;
    }

    private static boolean onScreen(Vector3f s, int w, int h, int hudBottom) {
        return s.z > 0 && s.z < 1 && s.x >= 10 && s.x < w - 10 && s.y >= hudBottom + 10 && s.y < h - 10;
    }

    private static double nearestPlant(World world, double x, double z) {
        double best = Double.MAX_VALUE;
        for (int q = 0; q < world.plantCount(); q++) {
            best = Math.min(best, Math.hypot(world.plantX(q) - x, world.plantZ(q) - z));
        }
        return best;
    }

    /** Mean |pose coordinate| of the components of the plants in the ring [r0, r1) around (x, z). */
    private static double meanBend(World world, Frame frame, double x, double z, double r0, double r1) {
        double sum = 0;
        int n = 0;
        for (int q = 0; q < world.plantCount(); q++) {
            double d = Math.hypot(world.plantX(q) - x, world.plantZ(q) - z);
            if (d < r0 || d >= r1) {
                continue;
            }
            for (int c = world.firstComponent(q), e = c + world.componentsOf(q); c < e; c++) {
                sum += Math.abs(frame.poseCoord(c));
                n++;
            }
        }
        return n == 0 ? Double.NaN : sum / n;
    }

    /** Checks the GL errors of the phase that ends where it stands; the GUI's one also counts the frame. */
    private final class Probe implements SceneProcessor {
        private final String phase;
        private boolean initialized;

        Probe(String phase) {
            this.phase = phase;
        }

        @Override
        public void initialize(RenderManager rm, ViewPort vp) {
            initialized = true;
        }

        @Override
        public void reshape(ViewPort vp, int w, int h) {
            // nothing sized
        }

        @Override
        public boolean isInitialized() {
            return initialized;
        }

        @Override
        public void preFrame(float tpf) {
            // nothing before the scene
        }

        @Override
        public void postQueue(RenderQueue rq) {
            // nothing between queueing and drawing
        }

        @Override
        public void postFrame(FrameBuffer out) {
            check(phase);
            if (this == sceneDone) {
                beforePlants(); // before the allocation count starts
            }
            long now = threads.getThreadAllocatedBytes(Thread.currentThread().getId());
            if (this == sceneDone) {
                drawStart = now; // the plant state's processor draws next
            } else if (this == plantsDone && frame >= options.frames() / 2) {
                // what drawing the plants allocated on the render thread, once warm
                long bytes = now - drawStart;
                drawsMeasured++;
                drawsAllocating += bytes > 0 ? 1 : 0;
                drawMostBytes = Math.max(drawMostBytes, bytes);
            }
            if (this == plantsDone) {
                afterPlants(); // after the allocation count
            } else if (this == guiDone) {
                frameDone();
            }
        }

        @Override
        public void cleanup() {
            initialized = false;
        }

        @Override
        public void setProfiler(AppProfiler profiler) {
            // not profiled
        }
    }
}
