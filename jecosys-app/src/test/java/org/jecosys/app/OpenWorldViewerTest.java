package org.jecosys.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_B;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_ESCAPE;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_H;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_LEFT_SHIFT;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_T;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_W;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.ByteBuffer;
import java.nio.file.Files;
import java.nio.file.Path;
import org.jecosys.math.ViewCamera;
import org.jecosys.render.GlContext;
import org.jecosys.render.GlContext.DebugOutput;
import org.jecosys.render.gl.GlContexts;
import org.jecosys.render.gl.GlFramebuffer;
import org.jecosys.render.gl.Pixels;
import org.jecosys.scene.SceneDef;
import org.jecosys.scene.SceneFiles;
import org.jecosys.scene.Scenes;
import org.jecosys.sim.DrawQuality;
import org.jecosys.sim.OpenWorld;
import org.jecosys.wind.WindField;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.lwjgl.system.MemoryUtil;

/**
 * The viewer over an open world, driven headless as its window loop drives it: {@code scenes/openworld.xml}
 * with a 12 m radius. The start is loaded and every live tile has its renderer before the first frame;
 * holding W (with Shift) walks the camera east without an edge, over the hills, and new tiles stream in
 * as old ones go; the picture has sky above and plants and ground below; T sends a walker with the
 * camera into the tiles (and stops it), B sets off a blast, H returns to the start, Escape quits.
 */
class OpenWorldViewerTest {
    private static final int W = 192;
    private static final int H = 108;
    private static final double DT = 0.1;

    @TempDir
    Path dir;

    /** The shipped open world with a smaller radius, so that llvmpipe draws it in a few seconds. */
    private SceneDef scene() throws Exception {
        String xml = Files.readString(Path.of("scenes", "openworld.xml")).replace("radius=\"64\"", "radius=\"12\"");
        Path f = dir.resolve("openworld.xml");
        Files.writeString(f, xml);
        Files.copy(Path.of("scenes", "jecosys-scene.xsd"), dir.resolve("jecosys-scene.xsd"));
        SceneDef def = SceneFiles.parse(f);
        assertEquals(12, def.world().radius(), 0);
        return def;
    }

    private static double covered(ByteBuffer px, int y0, int y1) {
        return org.jecosys.render.SkyShare.covered(px, W, y0, y1);
    }

    @Test
    void theViewerWalksAnOpenWorldWithoutAnEdgeAndTheTilesFollow() throws Exception {
        SceneDef def = scene();
        StringWriter log = new StringWriter();
        ByteBuffer px = MemoryUtil.memAlloc(4 * W * H);
        ViewerInput input = new ViewerInput();
        try (OpenWorld world = Scenes.openWorld(def, 2, 1);
             GlContext gl = GlContext.headless(DebugOutput.ON);
             GlFramebuffer screen = new GlFramebuffer(GlContexts.tracker(gl), W, H);
             OpenWorldViewer.Session s = new OpenWorldViewer.Session(def, world, gl, 0, input, DrawQuality.LOW,
                     W, H, new PrintWriter(log, true))) {
            assertTrue(world.liveTiles() > 0, "the start is loaded before the first frame");
            assertEquals(world.liveTiles(), s.renderer().tileRenderers(), "every live tile is drawn from the first frame");
            ViewCamera cam = s.fly().camera();
            double x0 = cam.x();
            double z0 = cam.z();
            long built0 = world.builtTiles();
            s.frame(DT, W, H, W / 2.0, H / 2.0, screen.id());
            screen.bind();
            Pixels.read(W, H, px);
            assertTrue(covered(px, H - 20, H) < 0.3, "sky at the top: " + covered(px, H - 20, H));
            assertTrue(covered(px, 0, 20) > 0.9, "plants and ground at the bottom: " + covered(px, 0, 20));

            // Shift+W for 3 s: 16 m/s east (the scene's camera looks along +X), 48 m, past the tiles' reach
            input.key(GLFW_KEY_LEFT_SHIFT, ViewerInput.PRESS, 0);
            input.key(GLFW_KEY_W, ViewerInput.PRESS, 0);
            for (int f = 0; f < 30; f++) {
                s.frame(DT, W, H, W / 2.0, H / 2.0, screen.id());
            }
            input.key(GLFW_KEY_W, ViewerInput.RELEASE, 0);
            input.key(GLFW_KEY_LEFT_SHIFT, ViewerInput.RELEASE, 0);
            double walked = Math.hypot(cam.x() - x0, cam.z() - z0);
            assertEquals(30 * DT * FlyCamera.OPEN_WALK * FlyCamera.FAST, walked, 0.5,
                    "walked at four times the open world's speed, no edge in the way");
            assertTrue(cam.x() - x0 > 40, "east, along the scene camera's heading: " + (cam.x() - x0));
            assertTrue(cam.y() > def.world().relief().height(cam.x(), cam.z()), "above the hills");
            assertTrue(world.builtTiles() > built0 + 3, "new tiles were built along the way: "
                    + (world.builtTiles() - built0));
            boolean ahead = false;
            for (int k = 0; k < world.liveTiles(); k++) {
                ahead |= world.tile(k).i() * world.tileSize() > x0 + 36;
            }
            assertTrue(ahead, "a tile alive well beyond where the walk started");
            screen.bind();
            Pixels.read(W, H, px);
            assertTrue(covered(px, 0, 20) > 0.9, "plants and ground still at the bottom after the walk");

            // T: a walker goes with the camera; T again stops it
            input.key(GLFW_KEY_T, ViewerInput.PRESS, 0);
            input.key(GLFW_KEY_T, ViewerInput.RELEASE, 0);
            s.frame(DT, W, H, W / 2.0, H / 2.0, screen.id());
            assertTrue(s.controls().walker(), s.controls().message());
            assertTrue(flowsIn(world, OpenWorldControls.WALKER), "the walker is in the tiles");
            input.key(GLFW_KEY_T, ViewerInput.PRESS, 0);
            input.key(GLFW_KEY_T, ViewerInput.RELEASE, 0);
            s.frame(DT, W, H, W / 2.0, H / 2.0, screen.id());
            assertFalse(s.controls().walker());
            s.frame(DT, W, H, W / 2.0, H / 2.0, screen.id());
            assertFalse(flowsIn(world, OpenWorldControls.WALKER), "the walker left every tile");

            input.key(GLFW_KEY_B, ViewerInput.PRESS, 0);
            input.key(GLFW_KEY_B, ViewerInput.RELEASE, 0);
            s.frame(DT, W, H, W / 2.0, H / 2.0, screen.id());
            s.frame(DT, W, H, W / 2.0, H / 2.0, screen.id());
            assertTrue(s.controls().message().startsWith("blast at"), s.controls().message());
            assertTrue(flowsIn(world, "blast-1"), "the blast is in the tiles");

            input.key(GLFW_KEY_H, ViewerInput.PRESS, 0);
            input.key(GLFW_KEY_H, ViewerInput.RELEASE, 0);
            s.frame(DT, W, H, W / 2.0, H / 2.0, screen.id());
            assertEquals(x0, cam.x(), 1e-9, "H: back to the start");
            assertEquals(z0, cam.z(), 1e-9);

            input.key(GLFW_KEY_ESCAPE, ViewerInput.PRESS, 0);
            input.key(GLFW_KEY_ESCAPE, ViewerInput.RELEASE, 0);
            s.frame(DT, W, H, W / 2.0, H / 2.0, screen.id());
            assertTrue(s.controls().quit());
            assertTrue(log.toString().contains("tiles"), log.toString());
        } finally {
            MemoryUtil.memFree((java.nio.Buffer) px);
        }
    }

    /** Whether some live tile's wind holds a flow {@code id}. */
    private static boolean flowsIn(OpenWorld world, String id) {
        for (int k = 0; k < world.liveTiles(); k++) {
            WindField wind = world.tile(k).simulation().inspect().windField();
            if (wind.indexOf(id) >= 0) {
                return true;
            }
        }
        return false;
    }
}
