package org.jecosys.render;

import static org.junit.jupiter.api.Assertions.assertTrue;

import org.jecosys.render.GlContext.DebugOutput;
import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.jecosys.math.ViewCamera;
import org.jecosys.scene.SceneDef;
import org.jecosys.scene.SceneFiles;
import org.jecosys.sim.World;
import org.joml.Matrix4f;
import org.joml.Vector4f;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestInstance;
import org.lwjgl.system.MemoryUtil;
import org.jecosys.render.gl.GlFramebuffer;
import org.jecosys.render.gl.Pixels;

/**
 * The sky and the ground, as images: the sky is a gradient from the horizon to the zenith colour
 * and brighter toward the sun; ground under the plants' leaves is at least 15% darker than open
 * ground and ground beyond their reach is not darkened (measured with the plants hidden, so the ground
 * itself); the sun direction of the settings lights the ground.
 */
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
class SkyAndGroundTest {
    private static final int W = 320;
    private static final int H = 200;
    /** Rose plants on flat ground, 4 m apart: open ground between them. */
    private static final double[][] BASES = {{-2, -2}, {2, -2}, {-2, 2}, {2, 2}};

    private GlContext gl;
    private GlFramebuffer fb;
    private World world;
    private SceneRenderer renderer;
    private RenderSettings settings;
    private ByteBuffer px;

    @BeforeAll
    void setUp() throws Exception {
        gl = GlContext.headless(DebugOutput.ON);
        fb = new GlFramebuffer(gl.tracker(), W, H);
        String rose = Files.readString(Path.of("scenes", "rose.xml"), StandardCharsets.UTF_8);
        StringBuilder plants = new StringBuilder();
        for (double[] b : BASES) {
            plants.append("<plant species=\"rose\" x=\"").append(b[0]).append("\" z=\"").append(b[1]).append("\"/>\n");
        }
        String xml = rose.replace("<terrain sizeX=\"4\" sizeZ=\"4\" resolution=\"17\"/>",
                        "<terrain sizeX=\"10\" sizeZ=\"10\" resolution=\"21\" heightScale=\"0\"/>")
                .replace("<plant species=\"rose\" x=\"0\" z=\"0\"/>", plants.toString());
        SceneDef def = SceneFiles.parse(xml.getBytes(StandardCharsets.UTF_8), "contact.xml", Path.of("scenes"));
        world = RenderScenes.build(def);
        settings = RenderSettings.standalone();
        settings.setPatches(10, 0, 1);
        renderer = new SceneRenderer(gl, world, settings);
        px = MemoryUtil.memAlloc(4 * W * H);
    }

    @AfterAll
    void tearDown() {
        MemoryUtil.memFree((java.nio.Buffer) px);
        if (renderer != null) {
            renderer.close();
            fb.close();
            gl.debug().check("the sky and ground test");
            gl.close();
        }
    }

    private void render(ViewCamera camera, boolean plants) {
        fb.bind();
        renderer.drawPlants = plants;
        try {
            renderer.render(TestFrames.rest(world, camera), camera, W, H);
        } finally {
            renderer.drawPlants = true;
        }
        Pixels.read(W, H, px);
    }

    private double luma(int x, int y) {
        return 0.2126 * Pixels.red(px, W, x, y) + 0.7152 * Pixels.green(px, W, x, y)
                + 0.0722 * Pixels.blue(px, W, x, y);
    }

    /** Mean luma of a 5 x 5 block at pixel (x, y) from the bottom. */
    private double block(int x, int y) {
        double s = 0;
        for (int dy = -2; dy <= 2; dy++) {
            for (int dx = -2; dx <= 2; dx++) {
                s += luma(x + dx, y + dy);
            }
        }
        return s / 25;
    }

    /** A camera at the origin, 1 m up, looking along (yaw, pitch), 60 degree vertical field. */
    private static ViewCamera look(double yaw, double pitch) {
        ViewCamera c = new ViewCamera();
        c.setPosition(0, 1, 0);
        c.setOrientation(yaw, pitch);
        c.setLens(Math.toRadians(60), W / (double) H, 0.05, 200);
        return c;
    }

    /** The yaw that looks toward compass azimuth {@code azDeg} (sun convention: 0 is +X, 90 is +Z). */
    private static double yawToward(double azDeg) {
        double az = Math.toRadians(azDeg);
        return Math.atan2(Math.cos(az), -Math.sin(az));
    }

    @Test
    void skyIsAGradientFromHorizonToZenith() {
        settings.lighting().setSun(Math.toRadians(135), Math.toRadians(50));
        // looking up 55 degrees, away from the sun: the top row is 85 degrees up
        render(look(yawToward(-45), Math.toRadians(55)), true);
        int[] top = {Pixels.red(px, W, W / 2, H - 3), Pixels.green(px, W, W / 2, H - 3), Pixels.blue(px, W, W / 2, H - 3)};
        // looking level: 5 pixels above the centre row is about 1.5 degrees above the horizon
        render(look(yawToward(-45), 0), true);
        int[] low = {Pixels.red(px, W, W / 2, H / 2 + 5), Pixels.green(px, W, W / 2, H / 2 + 5),
            Pixels.blue(px, W, W / 2, H / 2 + 5)};
        int[] zenith = rgb(settings.lighting().skyZenith());
        int[] horizon = rgb(settings.lighting().sky());
        int diff = Math.abs(top[0] - low[0]) + Math.abs(top[1] - low[1]) + Math.abs(top[2] - low[2]);
        System.out.printf("sky: near zenith %d,%d,%d, just above the horizon %d,%d,%d%n", top[0], top[1], top[2], low[0], low[1],
                low[2]);
        assertTrue(diff >= 40, "the zenith differs from the horizon by " + diff + " / 255 (sum of channels)");
        assertTrue(distance(top, zenith) < distance(top, horizon), "near the zenith the colour is the zenith's");
        assertTrue(distance(low, horizon) < distance(low, zenith), "low in the sky the colour is the horizon's");
    }

    @Test
    void skyIsBrighterTowardTheSun() {
        settings.lighting().setSun(Math.toRadians(135), Math.toRadians(30));
        render(look(yawToward(135), Math.toRadians(30)), true);
        double toward = block(W / 2, H / 2);
        double beside = block(W / 2 + 60, H / 2);
        render(look(yawToward(135 + 180), Math.toRadians(30)), true);
        double away = block(W / 2, H / 2);
        settings.lighting().setSun(Math.toRadians(135), Math.toRadians(50));
        System.out.printf("sky luma: toward the sun %.1f, 13 degrees beside %.1f, away %.1f%n", toward, beside, away);
        assertTrue(toward >= 250, "the sun's disc is near white: " + toward);
        assertTrue(beside > away + 8, "the glow around the sun: " + beside + " vs " + away);
    }

    /**
     * Contact darkening under what casts it (issue 25 sizes it to each plant's footprint; issue 13 asked
     * for a fixed 0.2 m disc round every base, which a thin rose does not shade): the ground under the
     * roses' leaves is at least 15% darker than open ground, and 0.3 m beyond the leaves' reach it is
     * not darkened (within 2%).
     */
    @Test
    void groundUnderThePlantsIsDarkerThanOpenGround() {
        ViewCamera top = new ViewCamera();
        top.setPosition(0, 9, 0.001);
        top.setOrientation(0, Math.toRadians(-89.9));
        top.setLens(Math.toRadians(50), W / (double) H, 0.05, 200);
        render(top, false);
        Matrix4f vp = top.viewProjection(new Matrix4f());
        double under = 0;
        int underCount = 0;
        double reach = 0;
        org.joml.Vector3f q = new org.joml.Vector3f();
        for (int p = 0; p < world.plantCount(); p++) {
            org.jecosys.plant.SpeciesModel m = world.plants().species().get(world.plantSpecies(p));
            for (int slot = 0; slot < m.slotCount(); slot++) {
                if (m.slotParent(slot) >= 0
                        || m.def().components().get(m.slotComponent(slot)).type() != org.jecosys.plant.ComponentType.LEAF) {
                    continue;
                }
                org.jecosys.plant.PoseTable t = m.slotPoseTable(slot, world.plantVariant(p));
                double az = world.plantRestAzimuth(p) + m.slotAzimuth(slot);
                for (int k = 1; k < t.points(); k++) {
                    t.position(0, k, q);
                    double x = m.slotBaseX(slot) + q.x;   // leaves stand at the base (no offset in this scene)
                    double z = m.slotBaseZ(slot) + q.z;
                    double wx = world.plantX(p) + x * Math.cos(az) - z * Math.sin(az);
                    double wz = world.plantZ(p) + x * Math.sin(az) + z * Math.cos(az);
                    reach = Math.max(reach, Math.hypot(wx - world.plantX(p), wz - world.plantZ(p)));
                    under += groundLuma(vp, wx, wz);
                    underCount++;
                }
            }
        }
        double open = 0;
        double[][] opens = {{0, 0}, {0, -2}, {0, 2}, {-2, 0}, {2, 0}, {-3.5, 0}, {3.5, 0}};
        for (double[] o : opens) {
            for (int k = 0; k < 16; k++) {
                double a = 2 * Math.PI * k / 16;
                open += groundLuma(vp, o[0] + 0.3 * Math.cos(a), o[1] + 0.3 * Math.sin(a));
            }
        }
        open /= opens.length * 16;
        under /= underCount;
        double beyond = 0;
        for (double[] b : BASES) {
            for (int k = 0; k < 16; k++) {
                double a = 2 * Math.PI * k / 16;
                beyond += groundLuma(vp, b[0] + (reach + 0.3) * Math.cos(a), b[1] + (reach + 0.3) * Math.sin(a));
            }
        }
        beyond /= BASES.length * 16;
        double darker = 1 - under / open;
        System.out.printf("ground luma under the leaves %.1f (%d points), open ground %.1f: %.1f%% darker; %.2f m from"
                + " the bases %.1f%n", under, underCount, open, 100 * darker, reach + 0.3, beyond);
        assertTrue(underCount > 10, "leaf points found: " + underCount);
        assertTrue(darker >= 0.15, "ground under the leaves is " + 100 * darker + "% darker than open ground");
        assertTrue(Math.abs(1 - beyond / open) <= 0.02, "ground 0.3 m beyond the leaves is not darkened: " + beyond
                + " vs open " + open);
        assertTrue(renderer.terrain().occlusion(0, 0) == 0 && renderer.terrain().occlusion(2, 2) > 0.5,
                "the occlusion map: open between the plants, high at a base");

        settings.setContactShadow(0);
        render(top, false);
        double plain = groundLuma(vp, 2.03, 2) / groundLuma(vp, 0, 0);
        settings.setContactShadow(0.5f);
        assertTrue(Math.abs(plain - 1) < 0.02, "no contact shadow: the same ground everywhere, ratio " + plain);
    }

    @Test
    void theSunLightsTheGround() {
        ViewCamera top = new ViewCamera();
        top.setPosition(0, 9, 0.001);
        top.setOrientation(0, Math.toRadians(-89.9));
        top.setLens(Math.toRadians(50), W / (double) H, 0.05, 200);
        Matrix4f vp = top.viewProjection(new Matrix4f());
        settings.lighting().setSun(Math.toRadians(135), Math.toRadians(80));
        render(top, false);
        double high = groundLuma(vp, 0, 0);
        settings.lighting().setSun(Math.toRadians(135), Math.toRadians(10));
        render(top, false);
        double low = groundLuma(vp, 0, 0);
        settings.lighting().setSun(Math.toRadians(135), Math.toRadians(50));
        System.out.printf("open ground luma, sun at 80 degrees %.1f, at 10 degrees %.1f%n", high, low);
        assertTrue(high > low * 1.3, "a high sun lights flat ground more than a low one: " + high + " vs " + low);
    }

    private double groundLuma(Matrix4f vp, double x, double z) {
        Vector4f p = vp.transform(new Vector4f((float) x, 0, (float) z, 1));
        int sx = (int) Math.floor((p.x / p.w * 0.5 + 0.5) * W);
        int sy = (int) Math.floor((p.y / p.w * 0.5 + 0.5) * H);
        assertTrue(sx >= 0 && sx < W && sy >= 0 && sy < H, "ground point in view: " + x + ", " + z);
        return luma(sx, sy);
    }

    private static int[] rgb(org.jecosys.math.Rgb c) {
        return new int[] {Math.round(c.r() * 255), Math.round(c.g() * 255), Math.round(c.b() * 255)};
    }

    private static int distance(int[] a, int[] b) {
        return Math.abs(a[0] - b[0]) + Math.abs(a[1] - b[1]) + Math.abs(a[2] - b[2]);
    }
}
