package com.example.gdxmeadow;

import com.badlogic.gdx.Gdx;
import com.badlogic.gdx.graphics.GL20;
import com.badlogic.gdx.graphics.PerspectiveCamera;
import com.badlogic.gdx.math.Vector3;
import java.awt.image.BufferedImage;
import java.io.BufferedOutputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.IntBuffer;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.jecosys.sim.Frame;
import org.jecosys.sim.World;
import org.jecosys.terrain.Heightfield;

/**
 * The example's test mode: counts frames once the scene is loaded, reports every GL error after each
 * phase of a frame, and after the last frame saves the back buffer (HUD included) as a PNG and prints
 * what a test checks in it, one {@code [gdx-meadow] ...} line each: where the HUD text is, bare
 * ground, plants, the player, the mean bend near the player and away from it, and the GL error count.
 * Image coordinates have their origin at the top left. With {@code --start-view} it prints the camera
 * and the back buffer's samples instead of the probes (there is no player); with
 * {@code --ground-screenshot} it also saves the last frame as it is before the plants are drawn; with
 * {@code --sheen} it keeps each frame's block luminance ({@link #writeSheen}).
 */
final class TestCapture {
    private static final String TAG = "[gdx-meadow] ";
    private final GdxMeadowLauncher.Options options;
    private int frame;
    private int errors;
    private final long start = System.nanoTime();
    /** Read-backs of the back buffer (RGBA, GL rows bottom up), made at the first that needs one. */
    private ByteBuffer px;
    /** Per frame, the mean luminance of each {@link #BLOCK} x {@link #BLOCK} block (--sheen). */
    private float[][] sheen;

    /** The side of the sheen's blocks, pixels. */
    static final int BLOCK = 16;

    TestCapture(GdxMeadowLauncher.Options options) {
        this.options = options;
    }

    /** After the game's ground and player, before the plants: on the last frame, the ground screenshot. */
    void beforePlants() {
        if (options.groundShot() != null && frame + 1 == options.frames()) {
            int w = Gdx.graphics.getBackBufferWidth();
            int h = Gdx.graphics.getBackBufferHeight();
            write(read(w, h), w, h, options.groundShot());
        }
    }

    /** After the plants, before the HUD: the frame's block luminance (--sheen). */
    void afterPlants() {
        if (options.sheen() == null) {
            return;
        }
        int w = Gdx.graphics.getBackBufferWidth();
        int h = Gdx.graphics.getBackBufferHeight();
        if (sheen == null) {
            sheen = new float[options.frames()][(w / BLOCK) * (h / BLOCK)];
        }
        blockLuminance(read(w, h), w, h, sheen[frame]);
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
    private void writeSheen(int w, int h) throws IOException {
        Path out = options.sheen().toAbsolutePath();
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
        System.out.println(TAG + "sheen " + out + " " + sheen.length + " frames");
    }

    /** The back buffer now, RGBA, GL rows bottom up. */
    private ByteBuffer read(int w, int h) {
        if (px == null) {
            px = ByteBuffer.allocateDirect(4 * w * h).order(ByteOrder.nativeOrder());
        }
        px.clear();
        Gdx.gl.glPixelStorei(GL20.GL_PACK_ALIGNMENT, 4);
        Gdx.gl.glReadPixels(0, 0, w, h, GL20.GL_RGBA, GL20.GL_UNSIGNED_BYTE, px);
        checkGl("glReadPixels");
        return px;
    }

    /** Writes a read-back as an opaque PNG, rows top down. */
    private static void write(ByteBuffer rgba, int w, int h, Path file) {
        BufferedImage img = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB); // the window is opaque
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                int i = 4 * ((h - 1 - y) * w + x);
                img.setRGB(x, y, (rgba.get(i) & 255) << 16 | (rgba.get(i + 1) & 255) << 8 | (rgba.get(i + 2) & 255));
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

    /** Reports the GL errors raised since the last check. */
    void checkGl(String phase) {
        for (int e = Gdx.gl.glGetError(); e != GL20.GL_NO_ERROR; e = Gdx.gl.glGetError()) {
            errors++;
            System.out.printf("%sGL error 0x%04X after %s in frame %d%n", TAG, e, phase, frame + 1);
        }
    }

    /** Counts a finished frame (HUD drawn); after the last, captures it. {@return whether to exit} */
    boolean frameDone(GdxMeadowGame game) {
        if (frame == 0) {
            System.out.println(TAG + "GL " + Gdx.gl.glGetString(GL20.GL_VERSION) + " | "
                    + Gdx.gl.glGetString(GL20.GL_RENDERER) + " | gl30=" + (Gdx.gl30 != null) + " | LWJGL "
                    + org.lwjgl.Version.getVersion());
            System.out.println(TAG + "scene " + options.scene() + ": " + game.plants().simulation().plantCount()
                    + " plants, " + game.plants().simulation().componentCount() + " components, "
                    + game.plants().simulation().world().plants().textures().layers() + " textures, "
                    + game.plants().simulation().world().plants().meshComponents() + " glTF meshes");
        }
        frame++;
        if (frame < options.frames()) {
            return false;
        }
        capture(game);
        return true;
    }

    private void capture(GdxMeadowGame game) {
        int w = Gdx.graphics.getBackBufferWidth();
        int h = Gdx.graphics.getBackBufferHeight();
        write(read(w, h), w, h, options.screenshot());
        if (sheen != null) {
            try {
                writeSheen(w, h);
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
        }
        if (options.startView()) {
            PerspectiveCamera c = game.camera();
            IntBuffer samples = ByteBuffer.allocateDirect(64).order(ByteOrder.nativeOrder()).asIntBuffer();
            Gdx.gl.glGetIntegerv(GL20.GL_SAMPLES, samples);
            System.out.printf("%sstart view: eye %.2f %.2f %.2f, looking %.3f %.3f %.3f, fov %.1f, back buffer"
                    + " samples %d%n", TAG, c.position.x, c.position.y, c.position.z, c.direction.x, c.direction.y,
                    c.direction.z, c.fieldOfView, samples.get(0));
        } else {
            probes(game, w, h);
        }
        System.out.printf("%sframes %d in %.1f s%n", TAG, frame, (System.nanoTime() - start) / 1e9);
        System.out.println(TAG + "gl errors: " + (errors == 0 ? "none" : errors));
    }

    /** Where the test should find the HUD, bare ground and plants, and how bent the plants are. */
    private void probes(GdxMeadowGame game, int w, int h) {
        PerspectiveCamera cam = game.camera();
        float sx = w / (float) Gdx.graphics.getWidth();
        float sy = h / (float) Gdx.graphics.getHeight();
        int hx0 = Math.round(12 * sx);
        int hy0 = Math.round(12 * sy);
        int hx1 = Math.round((12 + game.hudLayout().width) * sx);
        int hy1 = Math.round((12 + game.hudLayout().height) * sy);
        System.out.printf("%sprobe hud %d %d %d %d%n", TAG, hx0, hy0, hx1, hy1);

        World world = game.plants().simulation().world();
        Heightfield t = world.terrain().heightfield();
        Vector3 s = new Vector3();
        float px = game.playerX();
        float pz = game.playerZ();
        project(cam, s.set(px, (float) t.height(px, pz) + 0.85f, pz), w, h);
        int playerSx = Math.round(s.x);
        int playerSy = Math.round(s.y);
        System.out.printf("%sprobe player %d %d%n", TAG, playerSx, playerSy);

        // bare ground: the visible ground point farthest from any plant (at least 1.3 m)
        double best = 1.3;
        int gx = -1;
        int gy = -1;
        for (double z = t.minZ() + 0.5; z < t.maxZ() - 0.5; z += 0.25) {
            for (double x = t.minX() + 0.5; x < t.maxX() - 0.5; x += 0.25) {
                double d = Math.hypot(x - cam.position.x, z - cam.position.z);
                if (d < 3 || d > 12 || Math.hypot(x - px, z - pz) < 1.5) {
                    continue;
                }
                if (!onScreen(project(cam, s.set((float) x, (float) t.height(x, z), (float) z), w, h), w, h, hy1)
                        || Math.hypot(s.x - playerSx, s.y - playerSy) < 60) {
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
        for (int p = 0; p < world.plantCount() && found < 12; p += 7) {
            float x = world.plantX(p);
            float z = world.plantZ(p);
            double d = Math.hypot(x - cam.position.x, z - cam.position.z);
            if (d < 2.5 || d > 7 || Math.hypot(x - px, z - pz) < 1.5) {
                continue;
            }
            if (onScreen(project(cam, s.set(x, world.plantY(p) + 0.12f, z), w, h), w, h, hy1)
                    && Math.hypot(s.x - playerSx, s.y - playerSy) > 60) {
                System.out.printf("%sprobe plant %d %d%n", TAG, Math.round(s.x), Math.round(s.y));
                found++;
            }
        }
        Frame f = game.plants().simulation().latestFrame();
        System.out.printf("%sbend near %.4f far %.4f%n", TAG, meanBend(world, f, px, pz, 0, 1.0),
                meanBend(world, f, px, pz, 3, 6));
    }

    /** Window coordinates of a world point, origin top left. */
    private static Vector3 project(PerspectiveCamera cam, Vector3 p, int w, int h) {
        cam.project(p, 0, 0, w, h);
        p.y = h - 1 - p.y;
        return p;
    }

    private static boolean onScreen(Vector3 s, int w, int h, int hudBottom) {
        return s.z > 0 && s.z < 1 && s.x >= 10 && s.x < w - 10 && s.y >= hudBottom + 10 && s.y < h - 10;
    }

    private static double nearestPlant(World world, double x, double z) {
        double best = Double.MAX_VALUE;
        for (int p = 0; p < world.plantCount(); p++) {
            best = Math.min(best, Math.hypot(world.plantX(p) - x, world.plantZ(p) - z));
        }
        return best;
    }

    /** Mean |pose coordinate| of the components of the plants in the ring [r0, r1) around (x, z). */
    private static double meanBend(World world, Frame frame, double x, double z, double r0, double r1) {
        double sum = 0;
        int n = 0;
        for (int p = 0; p < world.plantCount(); p++) {
            double d = Math.hypot(world.plantX(p) - x, world.plantZ(p) - z);
            if (d < r0 || d >= r1) {
                continue;
            }
            for (int c = world.firstComponent(p), e = c + world.componentsOf(p); c < e; c++) {
                sum += Math.abs(frame.poseCoord(c));
                n++;
            }
        }
        return n == 0 ? Double.NaN : sum / n;
    }
}
