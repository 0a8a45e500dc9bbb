package org.jecosys.render;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import org.jecosys.math.ViewCamera;
import org.jecosys.plant.PoseTable;
import org.jecosys.plant.SpeciesModel;
import org.jecosys.render.ImageMetrics.Img;
import org.jecosys.scene.SceneDef;
import org.jecosys.scene.SceneFiles;
import org.jecosys.sim.Frame;
import org.jecosys.sim.World;
import org.joml.Vector3f;
import org.junit.jupiter.api.Test;

/**
 * Issue 26, "Done when" (sun shadows, {@code <light shadows>}), on both paths: the splat of each plant's
 * rest pose onto the ground ({@link ShadowPath#GROUND}, SunShadow) and the shadow map drawn every frame
 * ({@link ShadowPath#MAP}, SunShadowMap). An isolated C1 grass tuft on flat ground. The ground's
 * darkening is the terrain rendered with shadows minus the terrain rendered without (the plants left
 * off the screen in both pictures, so only the ground is compared; they still cast into the map), read
 * at world points on a 1 cm grid round the tuft through the camera's projection:
 * <ul>
 *   <li>under a sun 30 degrees high the darkening lies away from the sun (its centroid within 14 degrees
 *       of the sun's line), elongated along the sun's heading (s.d. along at least 1.3 x across), its
 *       centroid at least 0.5 x the tuft's height from the base;</li>
 *   <li>with the sun overhead it is centred under the tuft (on the centroid of the tuft's outline seen
 *       from above, its contact-occlusion map's);</li>
 *   <li>it does not swim: moving the camera by half a pixel changes the darkening picture by at most
 *       2/255 on average where there is shadow;</li>
 *   <li>with shadows off nothing changes, bit for bit.</li>
 * </ul>
 * The map's shadow is the blades' own, with light between them, so "elongated" is 1.2 there. And on the
 * map's path plants shade plants: a tuft 0.4 m from another, away from a sun 20 degrees high, is at
 * least 1.5/255 darker over its own pixels than the same tuft standing alone (both with shadows on; the
 * other's shadow is its blades', with light between them), at least 5% of its pixels by more than
 * 4/255; on the ground path its pixels do not change (under 0.5/255 and 1%).
 */
class SunShadowTest {
    private static final int W = 480;
    private static final int H = 480;

    /** C1's grass tuft A (scenes/c1.xml), alone in the middle of a flat 6 m square. */
    private static final String SCENE = """
            <scene version="1" name="tuft" seed="3">
              <terrain sizeX="6" sizeZ="6" resolution="13" heightScale="0"/>
              <species id="grassA" name="grass tuft A" maxBend="68.8">
                <lod maxDistance="10"/><lod maxDistance="15"/><lod primitive="lines"/>
                <variation variants="8" length="0.2" width="0.15" curvature="0.3" tilt="8.6"/>
                <component id="leaf" type="leaf" count="25" segments="5" length="0.45" baseWidth="0.006"
                    tipWidth="0.0015" curvature="20.1" twist="22.9" tilt="17.2" mass="0.0004"
                    stiffness="0.2" dragArea="0.002" colour="#4f8a2b" lodSegments="5 3 3"/>
              </species>
              <plant species="grassA" x="0" z="0"/>
            </scene>
            """;

    @Test
    void aTuftsSplattedShadowFallsAwayFromTheSunIsCentredAtNoonAndDoesNotSwim() throws Exception {
        tuftShadow(ShadowPath.GROUND);
    }

    @Test
    void aTuftsMappedShadowFallsAwayFromTheSunIsCentredAtNoonAndDoesNotSwim() throws Exception {
        tuftShadow(ShadowPath.MAP);
    }

    private static void tuftShadow(ShadowPath path) throws Exception {
        SceneDef def = SceneFiles.parse(SCENE.getBytes(StandardCharsets.UTF_8), "tuft.xml", Path.of("scenes"));
        World world = RenderScenes.build(def);
        double height = height(world);
        RenderSettings settings = RenderSettings.standalone();
        settings.setContactShadow(0.5f);
        settings.setShadowPath(path);
        try (Shots s = new Shots(world, settings, W, H)) {
            ViewCamera above = new ViewCamera();
            above.setPosition(0, 3, 0);
            above.setOrientation(0, -Math.PI / 2 + 1e-4);
            above.setLens(Math.toRadians(60), 1, 0.05, 50);
            Frame frame = TestFrames.rest(world, above);
            ViewCamera a = Shots.lookAt(0, 1.5, 1.5, 0, 0, 0, Math.toRadians(50), 1, 0.05, 50);
            settings.lighting().setSun(Math.toRadians(0), Math.toRadians(30));
            Img neverOn = s.render(frame, a, true, true);

            settings.lighting().setSun(Math.toRadians(0), Math.toRadians(30));
            double[] low = moments(s, settings, frame, above);
            double along = -low[1];                       // the sun stands toward +X: its shadow toward -X
            double across = Math.abs(low[2]);
            double elongation = Math.sqrt(low[3] / Math.max(1e-12, low[4]));
            System.out.printf("[look] " + path + ": tuft %.2f m high, sun 30 deg up: shadow centroid %.3f m away from the"
                            + " sun (%.2f x the height, >= 0.5), %.3f m across; spread along/across %.2f; %.0f dark-level"
                            + " cm2%n",
                    height, along, along / height, across, elongation, low[0]);
            assertTrue(low[0] > 0, "the tuft casts a shadow");
            assertTrue(along >= 0.5 * height, String.format("centroid %.3f m from the base, want >= %.3f", along,
                    0.5 * height));
            assertTrue(across <= 0.25 * along, String.format("centroid %.3f m off the sun's line", across));
            // the splat is each plant's hull, the map the blades' own shadows, with light between them
            double elongated = path == ShadowPath.MAP ? 1.2 : 1.3;
            assertTrue(elongation >= elongated, String.format("elongated along the sun: %.2f", elongation));

            settings.lighting().setSun(Math.toRadians(0), Math.toRadians(90));
            double[] noon = moments(s, settings, frame, above);
            double[] under = footprintCentroid(world);
            double off = Math.hypot(noon[1] - under[0], noon[2] - under[1]);
            System.out.printf("[look] " + path + ": sun overhead: shadow centroid %.3f m from the centroid of the tuft's outline "
                    + "seen from above (<= 0.1 x height; %.3f m from the base)%n", off, Math.hypot(noon[1], noon[2]));
            assertTrue(noon[0] > 0, "an overhead sun still shades the ground under the tuft");
            assertTrue(off <= 0.1 * height, String.format("centroid %.3f m from the tuft's own outline's", off));

            // half a pixel sideways, seen from 2 m at 45 degrees
            settings.lighting().setSun(Math.toRadians(0), Math.toRadians(30));
            double pixel = 2 * Math.hypot(1.5, 1.5) * Math.tan(Math.toRadians(25)) / H;
            ViewCamera b = Shots.lookAt(0.5 * pixel, 1.5, 1.5, 0.5 * pixel, 0, 0, Math.toRadians(50), 1, 0.05, 50);
            double[] da = darkening(s, settings, frame, a);
            double[] db = darkening(s, settings, frame, b);
            double sum = 0;
            int n = 0;
            for (int i = 0; i < da.length; i++) {
                if (da[i] > 1 || db[i] > 1) {
                    sum += Math.abs(da[i] - db[i]);
                    n++;
                }
            }
            double swim = sum / Math.max(1, n);
            System.out.printf("[look] " + path + ": camera moved half a pixel: shadowed ground changes by %.2f/255 on average over"
                    + " %d pixels (<= 2)%n", swim, n);
            assertTrue(n > 100, "shadowed pixels in the oblique view: " + n);
            assertTrue(swim <= 2, String.format("the shadow swims by %.2f/255", swim));

            // switched off again: the picture (plants, ground cover, terrain) is exactly as before they were on
            settings.setShadows(0);
            settings.lighting().setSun(Math.toRadians(0), Math.toRadians(30));
            Img offAgain = s.render(frame, a, true, true);
            assertTrue(java.util.Arrays.equals(neverOn.rgb(), offAgain.rgb()), "shadows off gives today's picture");
        }
    }

    @Test
    void inTheMapsPathPlantsShadeEachOther() throws Exception {
        // a tuft 0.4 m away from the sun of another, with and without that other one
        String one = "<plant species=\"grassA\" x=\"0\" z=\"0\"/>";
        String alone = SCENE.replace(one, "<plant species=\"grassA\" x=\"-0.4\" z=\"0\"/>");
        // the shaded one first in both, so it is the same plant (variant and rest azimuth go by index)
        String behind = SCENE.replace(one, "<plant species=\"grassA\" x=\"-0.4\" z=\"0\"/>" + one);
        ShadowPath[] paths = {ShadowPath.GROUND, ShadowPath.MAP};
        double[] darker = new double[2];
        double[] share = new double[2];
        for (int k = 0; k < 2; k++) {
            Img[] off = new Img[2];
            Img[] on = new Img[2];
            Img bare = null;
            String[] scenes = {alone, behind};
            for (int w = 0; w < 2; w++) {
                SceneDef def = SceneFiles.parse(scenes[w].getBytes(StandardCharsets.UTF_8), "row.xml", Path.of("scenes"));
                World world = RenderScenes.build(def);
                RenderSettings settings = RenderSettings.standalone();
                settings.setShadowPath(paths[k]);
                settings.lighting().setSun(Math.toRadians(0), Math.toRadians(20));
                settings.lighting().setSunIntensity(1.6f);
                try (Shots s = new Shots(world, settings, W, H)) {
                    Frame frame = TestFrames.rest(world, SIDE);
                    settings.setShadows(0);
                    // the plants alone (no terrain: only the plants' own pixels differ from the empty sky)
                    if (w == 0) {
                        bare = s.render(frame, SIDE, false, false);
                    }
                    off[w] = s.render(frame, SIDE, true, false);
                    settings.setShadows(0.8f);
                    on[w] = s.render(frame, SIDE, true, false);
                }
            }
            // the shaded tuft's pixels: a plant alone (it is the only one there), the same without shadows
            // with the other one there (not hidden by it)
            double sum = 0;
            int dark = 0;
            int n = 0;
            for (int i = 0; i < W * H; i++) {
                if (!ImageMetrics.differ(bare.rgb()[i], off[0].rgb()[i])
                        || ImageMetrics.differ(off[0].rgb()[i], off[1].rgb()[i])) {
                    continue;
                }
                double d = ImageMetrics.luma(on[0].rgb()[i]) - ImageMetrics.luma(on[1].rgb()[i]);
                sum += d;
                dark += d > 4 ? 1 : 0;
                n++;
            }
            assertTrue(n > 200, "pixels of the shaded tuft: " + n);
            darker[k] = sum / n;
            share[k] = dark / (double) n;
            System.out.printf("[look] %s: a tuft 0.4 m from another, away from a sun 20 deg up: %.2f/255 darker over"
                    + " %d of its pixels than standing alone, %.1f%% of them by more than 4/255%n", paths[k], darker[k],
                    n, 100 * share[k]);
        }
        assertTrue(darker[1] >= 1.5 && share[1] >= 0.05, String.format("map: a tuft in another's shadow darkens by"
                + " %.2f/255, %.3f of its pixels by more than 4/255", darker[1], share[1]));
        assertTrue(Math.abs(darker[0]) < 0.5 && share[0] < 0.01, String.format("ground path: the plants are not"
                + " shaded (%.2f/255, %.3f)", darker[0], share[0]));
    }

    /** From above the sun's side, past the shading tuft, at the shaded one. */
    private static final ViewCamera SIDE = Shots.lookAt(1.3, 1.2, 1.8, -0.4, 0.12, 0, Math.toRadians(40), 1, 0.05,
            50);

    /** Height of the tuft's tallest rest-pose point above its base, metres. */
    private static double height(World world) {
        SpeciesModel m = world.plants().species().get(0);
        Vector3f q = new Vector3f();
        double top = 0;
        for (int slot = 0; slot < m.slotCount(); slot++) {
            PoseTable t = m.slotPoseTable(slot, world.plantVariant(0));
            for (int k = 0; k < t.points(); k++) {
                top = Math.max(top, t.position(0, k, q).y);
            }
        }
        return top;
    }

    /** The centroid (X, Z) of the tuft's outline seen from straight above: its contact-occlusion map's. */
    private static double[] footprintCentroid(World world) {
        org.jecosys.render.ground.ContactOcclusion map = org.jecosys.render.ground.ContactOcclusion.of(world);
        double sw = 0;
        double sx = 0;
        double sz = 0;
        for (int i = -150; i <= 150; i++) {
            for (int j = -150; j <= 150; j++) {
                double w = map.sample(i * 0.01, j * 0.01);
                sw += w;
                sx += w * i * 0.01;
                sz += w * j * 0.01;
            }
        }
        return new double[] {sx / sw, sz / sw};
    }

    /** Per pixel, the terrain's luma without shadows minus with them (strength 0.8), plants left out. */
    private static double[] darkening(Shots s, RenderSettings settings, Frame frame, ViewCamera cam) {
        settings.setShadows(0);
        Img bare = s.render(frame, cam, false, true);
        settings.setShadows(0.8f);
        Img shaded = s.render(frame, cam, false, true);
        double[] d = new double[bare.width() * bare.height()];
        for (int i = 0; i < d.length; i++) {
            d[i] = ImageMetrics.luma(bare.rgb()[i]) - ImageMetrics.luma(shaded.rgb()[i]);
        }
        return d;
    }

    /**
     * The darkening read at world points on a 1 cm grid within 1.5 m of the base: {total (levels x cm2),
     * centroid X, centroid Z, variance along X, variance along Z}, metres.
     */
    private static double[] moments(Shots s, RenderSettings settings, Frame frame, ViewCamera cam) {
        double[] d = darkening(s, settings, frame, cam);
        double sw = 0;
        double sx = 0;
        double sz = 0;
        double sxx = 0;
        double szz = 0;
        for (int i = -150; i <= 150; i++) {
            for (int j = -150; j <= 150; j++) {
                double x = i * 0.01;
                double z = j * 0.01;
                double[] p = Shots.project(cam, x, 0, z, W, H);
                if (p == null || p[0] < 0 || p[1] < 0 || p[0] >= W || p[1] >= H) {
                    continue;
                }
                double w = Math.max(0, d[(int) p[1] * W + (int) p[0]]); // GL rows, as Pixels.read leaves them
                sw += w;
                sx += w * x;
                sz += w * z;
                sxx += w * x * x;
                szz += w * z * z;
            }
        }
        if (sw <= 0) {
            return new double[5];
        }
        double cx = sx / sw;
        double cz = sz / sw;
        return new double[] {sw, cx, cz, sxx / sw - cx * cx, szz / sw - cz * cz};
    }
}
