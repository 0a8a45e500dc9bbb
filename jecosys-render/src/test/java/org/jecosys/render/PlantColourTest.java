package org.jecosys.render;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.jecosys.math.ViewCamera;
import org.jecosys.scene.SceneDef;
import org.jecosys.sim.World;
import org.junit.jupiter.api.Test;

/**
 * Issue 13, "Done when": colour varies from plant to plant: per-plant hue s.d. at least 4 degrees and
 * value s.d. at least 0.08, in top views of the meadow (960x540, looking straight down: from 6 m over
 * the middle of the meadow and from 3.5 m over the densest patch of each species but the first, whose
 * small flowers would be a few pixels from higher up). Plants are the blobs (8-connected components) of the
 * vegetation mask that hold exactly one plant's top ({@link MeadowSpots#top}: the stalk tip, or the
 * base of a plant without a stalk) and at least 12 pixels; a blob's colour is its
 * mean colour, and the deviations are taken within each species with at least 8 such blobs (so that
 * the species' own colours do not count as variation). Every such species must pass.
 */
class PlantColourTest {
    private static final int W = 960;
    private static final int H = 540;
    private static final double HEIGHT = 6;
    private static final double PATCH_HEIGHT = 3.5;
    private static final int MIN_BLOB = 12;
    private static final int MIN_PLANTS = 8;

    @Test
    void colourVariesFromPlantToPlant() {
        SceneDef def = RenderScenes.load("meadow.xml");
        World world = RenderScenes.build(def);
        int speciesCount = world.plants().species().size();
        List<List<double[]>> colours = new ArrayList<>();
        for (int sp = 0; sp < speciesCount; sp++) {
            colours.add(new ArrayList<>());
        }
        List<String> failures = new ArrayList<>();
        int tested = 0;
        try (Shots s = new Shots(world, new RenderSettings(), W, H)) {
            collect(s, world, def, 0, 0, HEIGHT, colours);
            for (int sp = 1; sp < speciesCount; sp++) {
                int c = MeadowSpots.densest(world, sp, 2);
                if (c >= 0) {
                    collect(s, world, def, world.plantX(c), world.plantZ(c), PATCH_HEIGHT, colours);
                }
            }
        }
        for (int sp = 0; sp < speciesCount; sp++) {
            List<double[]> hsv = colours.get(sp);
            String name = world.plants().species().get(sp).def().name();
            if (hsv.size() < MIN_PLANTS) {
                System.out.printf("[look] meadow top view, %s: only %d single-plant blobs, not measured%n", name,
                        hsv.size());
                continue;
            }
            tested++;
            double[] h = new double[hsv.size()];
            double[] val = new double[hsv.size()];
            for (int i = 0; i < h.length; i++) {
                h[i] = hsv.get(i)[0];
                val[i] = hsv.get(i)[2];
            }
            double hueSd = ImageMetrics.circularSdDegrees(h);
            double valueSd = ImageMetrics.sd(val);
            System.out.printf("[look] meadow top view, %s: %d plants, hue s.d. %.2f deg (>= 4), value s.d. %.3f"
                    + " (>= 0.08)%n", name, h.length, hueSd, valueSd);
            if (hueSd < 4 || valueSd < 0.08) {
                failures.add(String.format("%s: hue s.d. %.2f deg, value s.d. %.3f over %d plants", name, hueSd,
                        valueSd, h.length));
            }
        }
        assertTrue(tested > 0, "no species with " + MIN_PLANTS + " single-plant blobs in the top views");
        assertTrue(failures.isEmpty(), "too little colour variation per plant: " + failures);
    }

    /** Adds the mean HSV of every single-plant blob of the top view over (x, z) to its species' list. */
    private static void collect(Shots s, World world, SceneDef def, double x, double z, double height,
                                List<List<double[]>> colours) {
        double gy = world.terrain().heightfield().height(x, z);
        ViewCamera cam = new ViewCamera().setPosition(x, gy + height, z).setOrientation(0, -Math.PI / 2 + 1e-3)
                .setLens(def.camera().fovY(), W / (double) H, 0.1, 100);
        Shots.View v = s.view(TestFrames.rest(world, cam), cam);
        ImageMetrics.Blobs blobs = ImageMetrics.blobs(v.vegetation(), W, H);
        int[] plantsIn = new int[blobs.count()];
        int[] speciesOf = new int[blobs.count()];
        org.joml.Vector3f top = new org.joml.Vector3f();
        for (int p = 0; p < world.plantCount(); p++) {
            MeadowSpots.top(world, p, top);
            double[] sp = Shots.project(cam, top.x, top.y, top.z, W, H);
            if (sp == null || sp[0] < 0 || sp[1] < 0 || sp[0] >= W || sp[1] >= H) {
                continue;
            }
            int l = blobs.labels()[(int) sp[1] * W + (int) sp[0]];
            if (l >= 0) {
                plantsIn[l]++;
                speciesOf[l] = world.plantSpecies(p);
            }
        }
        double[][] means = ImageMetrics.blobMeans(v.full(), blobs);
        for (int l = 0; l < blobs.count(); l++) {
            if (plantsIn[l] == 1 && blobs.sizes()[l] >= MIN_BLOB) {
                colours.get(speciesOf[l]).add(ImageMetrics.hsv(means[l]));
            }
        }
    }
}
