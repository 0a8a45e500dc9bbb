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
import org.jecosys.sim.World;
import org.joml.Vector3f;
import org.junit.jupiter.api.Test;

/**
 * Issue 25, "Done when" (blade shading): close up, a grass tuft is not one flat colour. One wide-leaved
 * tuft on flat ground, 0.7 m away, drawn alone (no terrain) at 960x540; pixels are read where the
 * leaves' rest-pose points project (only pixels that show a plant: they differ from the empty render):
 * <ul>
 *   <li>lit from the front, the lower parts (first 30% of each leaf) are at most 80% as bright as the
 *       outer parts (last 40%): darker toward the base and low in the tuft;</li>
 *   <li>across a leaf, the two halves differ: the mean luma difference between points a third of the
 *       half-width either side of the midrib is at least 3 levels (the normal is folded along the
 *       midrib);</li>
 *   <li>lit from behind (looking toward the sun), the outer parts glow brighter against the lower ones
 *       than they do lit from the front: light through the thin tips.</li>
 * </ul>
 */
class BladeShadingTest {
    private static final int W = 960;
    private static final int H = 540;

    private static final String SCENE = """
            <scene version="1" name="tuft" seed="3">
              <terrain sizeX="6" sizeZ="6" resolution="13" heightScale="0"/>
              <species id="grass" name="tuft" maxBend="68.8">
                <lod maxDistance="10"/><lod maxDistance="15"/><lod primitive="lines"/>
                <component id="leaf" type="leaf" count="12" segments="6" length="0.5" baseWidth="0.03"
                    tipWidth="0.006" curvature="40" twist="10" tilt="30" mass="0.0005" stiffness="0.2"
                    dragArea="0.0025" colour="#5fa834" lodSegments="6 3 3"/>
              </species>
              <plant species="grass" x="0" z="0"/>
            </scene>
            """;

    @Test
    void bladesAreShadedFromBaseToTipAndAcross() throws Exception {
        SceneDef def = SceneFiles.parse(SCENE.getBytes(StandardCharsets.UTF_8), "tuft.xml", Path.of("scenes"));
        World world = RenderScenes.build(def);
        RenderSettings settings = RenderSettings.standalone();
        settings.lighting().setSun(Math.toRadians(90), Math.toRadians(35));
        try (Shots s = new Shots(world, settings, W, H)) {
            // the sun stands toward +Z: the front-lit camera stands on the sun's side (+Z) looking along -Z
            ViewCamera front = Shots.lookAt(0, 0.35, 0.7, 0, 0.15, 0, Math.toRadians(50), W / (double) H, 0.02, 50);
            ViewCamera back = Shots.lookAt(0, 0.35, -0.7, 0, 0.15, 0, Math.toRadians(50), W / (double) H, 0.02, 50);
            double[] f = measure(s, world, front);
            double[] b = measure(s, world, back);
            System.out.printf("[look] tuft lit from the front: lower parts %.1f, outer parts %.1f (ratio %.2f <= 0.80);"
                    + " across the midrib %.1f levels (>= 3)%n", f[0], f[1], f[0] / f[1], f[2]);
            System.out.printf("[look] tuft lit from behind: lower parts %.1f, outer parts %.1f (outer/lower %.2f,"
                    + " front-lit %.2f)%n", b[0], b[1], b[1] / b[0], f[1] / f[0]);
            assertTrue(f[0] / f[1] <= 0.80, String.format("lower parts %.1f vs outer %.1f: want <= 80%%", f[0], f[1]));
            assertTrue(f[2] >= 3, String.format("the halves of a leaf differ by %.1f levels, want >= 3", f[2]));
            assertTrue(b[1] / b[0] > f[1] / f[0], "back-lit tips glow: outer/lower " + b[1] / b[0] + " vs front-lit "
                    + f[1] / f[0]);
        }
    }

    /** {mean luma of the lower parts, of the outer parts, mean |left - right| across the midrib}. */
    private static double[] measure(Shots s, World world, ViewCamera cam) {
        Img plants = s.render(TestFrames.rest(world, cam), cam, true, false);
        Img empty = s.render(TestFrames.rest(world, cam), cam, false, false);
        SpeciesModel m = world.plants().species().get(0);
        Vector3f q = new Vector3f();
        Vector3f side = new Vector3f();
        double lower = 0;
        int nl = 0;
        double outer = 0;
        int no = 0;
        double across = 0;
        int na = 0;
        for (int slot = 0; slot < m.slotCount(); slot++) {
            PoseTable t = m.slotPoseTable(slot, world.plantVariant(0));
            double az = world.plantRestAzimuth(0) + m.slotAzimuth(slot);
            double c = Math.cos(az);
            double sn = Math.sin(az);
            int last = t.points() - 1;
            for (int k = 0; k <= last; k++) {
                double along = k / (double) last;
                t.position(0, k, q);
                t.side(0, k, side);
                double[] centre = world(world, c, sn, q.x, q.y, q.z);
                double l = luma(plants, empty, cam, centre);
                if (!Double.isNaN(l)) {
                    if (along <= 0.3) {
                        lower += l;
                        nl++;
                    } else if (along >= 0.6) {
                        outer += l;
                        no++;
                    }
                }
                if (along > 0.15 && along < 0.7) {
                    double[] left = world(world, c, sn, q.x - side.x / 3, q.y - side.y / 3, q.z - side.z / 3);
                    double[] right = world(world, c, sn, q.x + side.x / 3, q.y + side.y / 3, q.z + side.z / 3);
                    double a = luma(plants, empty, cam, left);
                    double b = luma(plants, empty, cam, right);
                    if (!Double.isNaN(a) && !Double.isNaN(b)) {
                        across += Math.abs(a - b);
                        na++;
                    }
                }
            }
        }
        assertTrue(nl > 5 && no > 5 && na > 5, "leaf points in view: " + nl + ", " + no + ", " + na);
        return new double[] {lower / nl, outer / no, across / na};
    }

    private static double[] world(World world, double c, double s, double x, double y, double z) {
        return new double[] {world.plantX(0) + x * c - z * s, world.plantY(0) + y, world.plantZ(0) + x * s + z * c};
    }

    /**
     * Luma of the plant pixel where a world point projects, NaN off screen or where no plant shows. A thin
     * part under two pixels wide may fall just beside the pixel its centre line projects into: where that
     * pixel shows no plant, the pixel of the 3x3 around it that differs most from the empty render is taken.
     */
    private static double luma(Img plants, Img empty, ViewCamera cam, double[] p) {
        double[] px = Shots.project(cam, p[0], p[1], p[2], W, H);
        if (px == null) {
            return Double.NaN;
        }
        int x0 = (int) px[0];
        int y0 = (int) px[1];
        if (x0 >= 0 && y0 >= 0 && x0 < W && y0 < H && ImageMetrics.differ(plants.at(x0, y0), empty.at(x0, y0))) {
            return ImageMetrics.luma(plants.at(x0, y0));
        }
        int best = -1;
        int most = -1;
        for (int y = y0 - 1; y <= y0 + 1; y++) {
            for (int x = x0 - 1; x <= x0 + 1; x++) {
                if (x < 0 || y < 0 || x >= W || y >= H) {
                    continue;
                }
                int a = plants.at(x, y);
                int e = empty.at(x, y);
                int d = Math.abs(ImageMetrics.r(a) - ImageMetrics.r(e)) + Math.abs(ImageMetrics.g(a) - ImageMetrics.g(e))
                        + Math.abs(ImageMetrics.b(a) - ImageMetrics.b(e));
                if (ImageMetrics.differ(a, e) && d > most) {
                    most = d;
                    best = a;
                }
            }
        }
        return most < 0 ? Double.NaN : ImageMetrics.luma(best);
    }
}
