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
 * Issue 26, "Done when" (sun shadows, the software path: {@code <light shadows>}, SunShadow): an
 * isolated C1 grass tuft on flat ground. The ground's darkening is the terrain rendered with shadows
 * minus the terrain rendered without (the plants left out of both pictures, so only the ground is
 * compared), read at world points on a 1 cm grid round the tuft through the camera's projection:
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
    void aTuftsShadowFallsAwayFromTheSunIsCentredAtNoonAndDoesNotSwim() throws Exception {
        SceneDef def = SceneFiles.parse(SCENE.getBytes(StandardCharsets.UTF_8), "tuft.xml", Path.of("scenes"));
        World world = RenderScenes.build(def);
        double height = height(world);
        RenderSettings settings = RenderSettings.standalone().contactShadow(0.5f);
        try (Shots s = new Shots(world, settings, W, H)) {
            ViewCamera above = new ViewCamera().setPosition(0, 3, 0).setOrientation(0, -Math.PI / 2 + 1e-4)
                    .setLens(Math.toRadians(60), 1, 0.05, 50);
            Frame frame = TestFrames.rest(world, above);
            ViewCamera a = Shots.lookAt(0, 1.5, 1.5, 0, 0, 0, Math.toRadians(50), 1, 0.05, 50);
            settings.sun(0, 30);
            Img neverOn = s.render(frame, a, true, true);

            settings.sun(0, 30);
            double[] low = moments(s, settings, frame, above);
            double along = -low[1];                       // the sun stands toward +X: its shadow toward -X
            double across = Math.abs(low[2]);
            double elongation = Math.sqrt(low[3] / Math.max(1e-12, low[4]));
            System.out.printf("[look] tuft %.2f m high, sun 30 deg up: shadow centroid %.3f m away from the sun "
                            + "(%.2f x the height, >= 0.5), %.3f m across; spread along/across %.2f; %.0f dark-level cm2%n",
                    height, along, along / height, across, elongation, low[0]);
            assertTrue(low[0] > 0, "the tuft casts a shadow");
            assertTrue(along >= 0.5 * height, String.format("centroid %.3f m from the base, want >= %.3f", along,
                    0.5 * height));
            assertTrue(across <= 0.25 * along, String.format("centroid %.3f m off the sun's line", across));
            assertTrue(elongation >= 1.3, String.format("elongated along the sun: %.2f", elongation));

            settings.sun(0, 90);
            double[] noon = moments(s, settings, frame, above);
            double[] under = footprintCentroid(world);
            double off = Math.hypot(noon[1] - under[0], noon[2] - under[1]);
            System.out.printf("[look] sun overhead: shadow centroid %.3f m from the centroid of the tuft's outline "
                    + "seen from above (<= 0.1 x height; %.3f m from the base)%n", off, Math.hypot(noon[1], noon[2]));
            assertTrue(noon[0] > 0, "an overhead sun still shades the ground under the tuft");
            assertTrue(off <= 0.1 * height, String.format("centroid %.3f m from the tuft's own outline's", off));

            // half a pixel sideways, seen from 2 m at 45 degrees
            settings.sun(0, 30);
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
            System.out.printf("[look] camera moved half a pixel: shadowed ground changes by %.2f/255 on average over"
                    + " %d pixels (<= 2)%n", swim, n);
            assertTrue(n > 100, "shadowed pixels in the oblique view: " + n);
            assertTrue(swim <= 2, String.format("the shadow swims by %.2f/255", swim));

            // switched off again: the picture (plants, ground cover, terrain) is exactly as before they were on
            settings.shadows(0);
            settings.sun(0, 30);
            Img offAgain = s.render(frame, a, true, true);
            assertTrue(java.util.Arrays.equals(neverOn.rgb(), offAgain.rgb()), "shadows off gives today's picture");
        }
    }

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
        settings.shadows(0);
        Img bare = s.render(frame, cam, false, true);
        settings.shadows(0.8f);
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
