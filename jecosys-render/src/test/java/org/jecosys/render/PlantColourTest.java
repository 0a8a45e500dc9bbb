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
 * mean colour over its interior pixels, and each plant's deviation is taken from the mean of its
 * species (with at least 8 such blobs; so that the species' own colours do not count as variation).
 * The standard deviations over all measured plants must reach the thresholds, and every measured
 * species must vary by itself (hue s.d. at least 2 degrees, value s.d. at least 0.03). Where plants grow
 * so densely that their blobs merge (fewer than 8 single-plant blobs of a species), a plant's colour
 * is instead the mean over the vegetation pixels within 3 cm (at least 2 pixels) of its projected
 * top, for plants whose top has no other plant's top within twice that radius on screen; only for
 * species whose component colours are all within 30 degrees of hue of each other (a window that
 * mixes petals and stalk would measure the mixture, not the plant).
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
        List<List<double[]>> cores = new ArrayList<>();
        for (int sp = 0; sp < speciesCount; sp++) {
            colours.add(new ArrayList<>());
            cores.add(new ArrayList<>());
        }
        List<String> failures = new ArrayList<>();
        List<Double> hueDev = new ArrayList<>();
        List<Double> valueDev = new ArrayList<>();
        int tested = 0;
        // the plants' own colours: without the ground cover, whose blades would join the plants' blobs
        RenderSettings bare = RenderScenes.settings(def);
        bare.setGroundCover(org.jecosys.scene.RenderDef.GroundCover.NONE);
        try (Shots s = new Shots(world, bare, W, H)) {
            collect(s, world, def, 0, 0, HEIGHT, colours, cores);
            for (int sp = 1; sp < speciesCount; sp++) {
                int c = world.densestPlant(sp, 2);
                if (c >= 0) {
                    collect(s, world, def, world.plantX(c), world.plantZ(c), PATCH_HEIGHT, colours, cores);
                }
            }
        }
        for (int sp = 0; sp < speciesCount; sp++) {
            List<double[]> hsv = colours.get(sp);
            String name = world.plants().species().get(sp).def().name();
            String how = "single-plant blobs";
            if (hsv.size() < MIN_PLANTS && oneHue(world.plants().species().get(sp))) {
                hsv = cores.get(sp);
                how = "plant cores";
            }
            if (hsv.size() < MIN_PLANTS) {
                System.out.printf("[look] meadow top view, %s: only %d single-plant blobs and %d plant cores, not"
                        + " measured%n", name, colours.get(sp).size(), cores.get(sp).size());
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
            double meanHue = circularMean(h);
            double meanValue = 0;
            for (double v : val) {
                meanValue += v / val.length;
            }
            for (int i = 0; i < h.length; i++) {
                double d = ((h[i] - meanHue) % 360 + 540) % 360 - 180;
                hueDev.add(d);
                valueDev.add(val[i] - meanValue);
            }
            System.out.printf("[look] meadow top view, %s: %d plants (%s), hue s.d. %.2f deg, value s.d. %.3f,"
                    + " mean value %.3f%n", name, h.length, how, hueSd, valueSd, meanValue);
            if (hueSd < 2 || valueSd < 0.03) {
                failures.add(String.format("%s: hue s.d. %.2f deg, value s.d. %.3f over %d plants: barely varies",
                        name, hueSd, valueSd, h.length));
            }
        }
        double hueSd = rms(hueDev);
        double valueSd = rms(valueDev);
        System.out.printf("[look] meadow top view, all %d plants, each from its species' mean: hue s.d. %.2f deg"
                + " (>= 4), value s.d. %.3f (>= 0.08)%n", hueDev.size(), hueSd, valueSd);
        if (hueSd < 4 || valueSd < 0.08) {
            failures.add(String.format("all plants: hue s.d. %.2f deg, value s.d. %.3f", hueSd, valueSd));
        }
        assertTrue(tested > 0, "no species with " + MIN_PLANTS + " single-plant blobs in the top views");
        assertTrue(failures.isEmpty(), "too little colour variation per plant: " + failures);
    }

    /** Adds the mean HSV of every single-plant blob of the top view over (x, z) to its species' list. */
    private static void collect(Shots s, World world, SceneDef def, double x, double z, double height,
                                List<List<double[]>> colours, List<List<double[]>> cores) {
        double gy = world.terrain().heightfield().height(x, z);
        ViewCamera cam = new ViewCamera();
        cam.setPosition(x, gy + height, z);
        cam.setOrientation(0, -Math.PI / 2 + 1e-3);
        cam.setLens(def.camera().fovY(), W / (double) H, 0.1, 100);
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
        double[][] means = interiorMeans(v, blobs);
        for (int l = 0; l < blobs.count(); l++) {
            if (plantsIn[l] == 1 && blobs.sizes()[l] >= MIN_BLOB) {
                colours.get(speciesOf[l]).add(ImageMetrics.hsv(means[l]));
            }
        }
        // plant cores: the tops on screen, then the mean colour near each top that has no close neighbour
        List<double[]> tops = new ArrayList<>(); // {x, y, radius, species}
        for (int p = 0; p < world.plantCount(); p++) {
            MeadowSpots.top(world, p, top);
            double[] sp = Shots.project(cam, top.x, top.y, top.z, W, H);
            if (sp != null && sp[0] >= 0 && sp[1] >= 0 && sp[0] < W && sp[1] < H) {
                double pxPerMetre = H / (2 * Math.tan(cam.fovY() / 2) * sp[2]);
                tops.add(new double[] {sp[0], sp[1], Math.max(2, 0.03 * pxPerMetre), world.plantSpecies(p)});
            }
        }
        for (double[] t : tops) {
            boolean alone = true;
            for (double[] u : tops) {
                if (u != t && Math.hypot(u[0] - t[0], u[1] - t[1]) < 2 * t[2]) {
                    alone = false;
                    break;
                }
            }
            if (!alone) {
                continue;
            }
            double[] sum = new double[3];
            int n = 0;
            int r = (int) Math.ceil(t[2]);
            for (int yy = (int) t[1] - r; yy <= (int) t[1] + r; yy++) {
                for (int xx = (int) t[0] - r; xx <= (int) t[0] + r; xx++) {
                    if (xx >= 0 && yy >= 0 && xx < W && yy < H && Math.hypot(xx + 0.5 - t[0], yy + 0.5 - t[1]) <= t[2]
                            && v.vegetation()[yy * W + xx]) {
                        int c = v.full().at(xx, yy);
                        sum[0] += ImageMetrics.r(c);
                        sum[1] += ImageMetrics.g(c);
                        sum[2] += ImageMetrics.b(c);
                        n++;
                    }
                }
            }
            if (n >= 5) {
                cores.get((int) t[3]).add(ImageMetrics.hsv(new double[] {sum[0] / n, sum[1] / n, sum[2] / n}));
            }
        }
    }

    /**
     * The mean colour of each blob over its interior pixels (all four neighbours in the same blob):
     * the plant's own colour, not its edges blended with the ground by anti-aliasing; a blob with
     * fewer than 3 interior pixels keeps the mean over all its pixels.
     */
    private static double[][] interiorMeans(Shots.View v, ImageMetrics.Blobs blobs) {
        double[][] all = ImageMetrics.blobMeans(v.full(), blobs);
        double[][] sum = new double[blobs.count()][3];
        int[] n = new int[blobs.count()];
        int[] labels = blobs.labels();
        for (int y = 1; y < H - 1; y++) {
            for (int x = 1; x < W - 1; x++) {
                int i = y * W + x;
                int l = labels[i];
                if (l < 0 || labels[i - 1] != l || labels[i + 1] != l || labels[i - W] != l || labels[i + W] != l) {
                    continue;
                }
                int c = v.full().at(x, y);
                sum[l][0] += ImageMetrics.r(c);
                sum[l][1] += ImageMetrics.g(c);
                sum[l][2] += ImageMetrics.b(c);
                n[l]++;
            }
        }
        for (int l = 0; l < sum.length; l++) {
            if (n[l] >= 3) {
                all[l] = new double[] {sum[l][0] / n[l], sum[l][1] / n[l], sum[l][2] / n[l]};
            }
        }
        return all;
    }

    private static double circularMean(double[] degrees) {
        double sx = 0;
        double sy = 0;
        for (double d : degrees) {
            sx += Math.cos(Math.toRadians(d));
            sy += Math.sin(Math.toRadians(d));
        }
        return Math.toDegrees(Math.atan2(sy, sx));
    }

    private static double rms(List<Double> xs) {
        double s = 0;
        for (double x : xs) {
            s += x * x;
        }
        return xs.isEmpty() ? 0 : Math.sqrt(s / xs.size());
    }

    /** Whether every component colour of the species is within 30 degrees of hue of every other. */
    private static boolean oneHue(org.jecosys.plant.SpeciesModel m) {
        List<Double> hues = new ArrayList<>();
        for (org.jecosys.plant.ComponentDef c : m.def().components()) {
            hues.add(ImageMetrics.hsv(new double[] {255 * c.colour().r(), 255 * c.colour().g(),
                    255 * c.colour().b()})[0]);
        }
        for (double a : hues) {
            for (double b : hues) {
                double d = Math.abs(a - b) % 360;
                if (Math.min(d, 360 - d) > 30) {
                    return false;
                }
            }
        }
        return true;
    }
}
