package org.jecosys.render;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.jecosys.math.Rgb;
import org.jecosys.math.ViewCamera;
import org.jecosys.plant.ComponentDef;
import org.jecosys.plant.ComponentType;
import org.jecosys.plant.SpeciesModel;
import org.jecosys.scene.SceneDef;
import org.jecosys.sim.World;
import org.joml.Vector3f;
import org.junit.jupiter.api.Test;

/**
 * Issue 13, "Done when": every flower within 10 m of the camera shows at least 6 head-coloured pixels
 * at 960x540: in the default meadow view (which may hold none within 10 m; today it holds none), and
 * in a view of the densest patch of each flower species (from 4 m south of its middle, 1.7 m up,
 * looking at the middle on the ground), which must hold some. A flower is a plant whose species has a head or petal
 * component; its head is at the tip of its stalk at rest ({@link MeadowSpots#top}). Flowers whose head
 * projects off the picture are not counted. Around the projected head, within 4 cm (as pixels at that
 * distance) plus 2 pixels, a vegetation pixel is head-coloured when its
 * hue is nearer to a head or petal colour of the flower's species than to any other component colour
 * of the scene (hue survives lighting and shading, which mostly change value) and its saturation is at
 * least 0.2. A flower whose head is hidden by something nearer the camera may show fewer: in a dense
 * patch one flower or a tall grass leaf hides another (the clumped meadow of issue 25 grows its
 * plants in tight groups of uneven height). Hidden means that another flower's head nearer the camera
 * overlaps its circle on screen, or that fewer than 12 pixels of its circle show what is at the head's
 * distance or beyond, the rest something at least 5 cm nearer (the depth of the whole scene, read
 * back); at most 5% of the flowers of a view may be hidden so. In the views of the densest patches
 * (hundreds of flowers in tight groups of uneven height and lean since issue 25) at most 2% of the
 * others may show fewer (a head partly behind another at almost its distance, or turned grey away from
 * the light and the eye); in the default view none may.
 */
@org.junit.jupiter.api.Tag("slow") // 11-13 s; mvn -B verify -Pnightly runs it (FlowerSizeTest keeps flower heads in the default run)
class FlowerHeadsTest {
    private static final int W = 960;
    private static final int H = 540;
    private static final double RANGE = 10;
    private static final int MIN_PIXELS = 6;

    @Test
    void everyNearFlowerShowsItsHead() {
        SceneDef def = RenderScenes.load("meadow.xml");
        World world = RenderScenes.build(def);
        int speciesCount = world.plants().species().size();
        // hues of every component colour, and which are head or petal colours of which species
        List<double[]> hues = new ArrayList<>(); // {hue, species or -1 when not a head colour}
        for (int s = 0; s < speciesCount; s++) {
            for (ComponentDef c : world.plants().species().get(s).def().components()) {
                boolean head = c.type() == ComponentType.HEAD || c.type() == ComponentType.PETAL;
                hues.add(new double[] {hue(c.colour()), head ? s : -1});
            }
        }
        List<String> failures = new ArrayList<>();
        try (Shots shots = new Shots(world, RenderScenes.settings(def), W, H)) {
            check(shots, world, RenderScenes.camera(def, world, W, H), "default view", hues, false, failures);
            for (int s = 0; s < speciesCount; s++) {
                SpeciesModel m = world.plants().species().get(s);
                if (MeadowSpots.stalkSlot(m) < 0 || !hasHead(m)) {
                    continue;
                }
                int c = world.densestPlant(s, 2);
                double x = world.plantX(c);
                double y = world.plantY(c);
                double z = world.plantZ(c);
                double ey = world.terrain().heightfield().height(x, z + 4) + 1.7;
                ViewCamera cam = Shots.lookAt(x, ey, z + 4, x, y, z, def.camera().fovY(), W / (double) H, 0.05, 500);
                check(shots, world, cam, m.def().name() + " patch", hues, true, failures);
            }
        }
        assertTrue(failures.isEmpty(), "flowers within 10 m with fewer than " + MIN_PIXELS
                + " head-coloured pixels: " + failures);
    }

    private static void check(Shots shots, World world, ViewCamera cam, String view, List<double[]> hues,
                              boolean mustHoldFlowers, List<String> failures) {
        Shots.View v = shots.view(TestFrames.rest(world, cam), cam);
        double[] depth = shots.sceneDistance(TestFrames.rest(world, cam), cam);
        int flowers = 0;
        int failing = 0;
        int fewest = Integer.MAX_VALUE;
        List<String> examples = new ArrayList<>();
        Vector3f tip = new Vector3f();
        // every flower head in view within range: screen x, y, distance, circle radius (pixels), plant
        List<double[]> heads = new ArrayList<>();
        for (int p = 0; p < world.plantCount(); p++) {
            int s = world.plantSpecies(p);
            SpeciesModel m = world.plants().species().get(s);
            if (MeadowSpots.stalkSlot(m) < 0 || !hasHead(m)) {
                continue;
            }
            MeadowSpots.top(world, p, tip);
            double dist = Math.sqrt((tip.x - cam.x()) * (tip.x - cam.x()) + (tip.y - cam.y()) * (tip.y - cam.y())
                    + (tip.z - cam.z()) * (tip.z - cam.z()));
            if (dist > RANGE) {
                continue;
            }
            double[] sp = Shots.project(cam, tip.x, tip.y, tip.z, W, H);
            if (sp == null || sp[0] < 0 || sp[1] < 0 || sp[0] >= W || sp[1] >= H) {
                continue;
            }
            double pxPerMetre = H / (2 * Math.tan(cam.fovY() / 2) * sp[2]);
            heads.add(new double[] {sp[0], sp[1], dist, 0.04 * pxPerMetre + 2, p});
        }
        int hidden = 0;
        for (double[] h : heads) {
            int p = (int) h[4];
            int s = world.plantSpecies(p);
            int n = headPixels(v, h[0], h[1], h[3], s, hues);
            flowers++;
            if (n >= MIN_PIXELS) {
                fewest = Math.min(fewest, n);
                continue;
            }
            if (hiddenAt(h, depth) || behindAnother(h, heads)) {
                hidden++;
                continue;
            }
            fewest = Math.min(fewest, n);
            failing++;
            if (examples.size() < 3) {
                examples.add(String.format("plant %d at %.1f m: %d px", p, h[2], n));
            }
        }
        if (hidden > 0.05 * flowers) {
            failures.add(String.format("%s: %d of %d flowers hidden by nearer plants (more than 5%%)", view,
                    hidden, flowers));
        }
        System.out.printf("[look] meadow %s: %d flowers within %.0f m hidden by nearer plants%n", view, hidden,
                RANGE);
        System.out.printf("[look] meadow %s: %d of %d flowers within %.0f m show >= %d head-coloured pixels"
                + " or are hidden by nearer plants (fewest of the others %s)%n", view, flowers - failing,
                flowers, RANGE, MIN_PIXELS,
                flowers == 0 ? "-" : Integer.toString(fewest));
        if (mustHoldFlowers && flowers == 0) {
            failures.add(view + ": no flower within " + RANGE + " m in view");
        }
        if (mustHoldFlowers ? failing > 0.02 * flowers : failing > 0) {
            failures.add(String.format("%s: %d of %d, e.g. %s", view, failing, flowers, examples));
        }
    }

    /** Whether fewer than 12 pixels of a head's circle show the head's distance or beyond (not something nearer). */
    private static boolean hiddenAt(double[] h, double[] depth) {
        int open = 0;
        int r = (int) Math.ceil(h[3]);
        for (int y = (int) h[1] - r; y <= (int) h[1] + r; y++) {
            for (int x = (int) h[0] - r; x <= (int) h[0] + r; x++) {
                if (x >= 0 && y >= 0 && x < W && y < H && Math.hypot(x + 0.5 - h[0], y + 0.5 - h[1]) <= h[3]
                        && depth[y * W + x] >= h[2] - 0.05) {
                    open++;
                }
            }
        }
        return open < 2 * MIN_PIXELS;
    }

    /** Whether another flower's head nearer the camera overlaps this head's circle on screen. */
    private static boolean behindAnother(double[] h, List<double[]> heads) {
        for (double[] o : heads) {
            if (o != h && o[2] < h[2] && Math.hypot(o[0] - h[0], o[1] - h[1]) < o[3] + h[3]) {
                return true;
            }
        }
        return false;
    }

    private static int headPixels(Shots.View v, double cx, double cy, double radius, int species,
                                  List<double[]> hues) {
        int n = 0;
        int r = (int) Math.ceil(radius);
        for (int y = (int) cy - r; y <= (int) cy + r; y++) {
            for (int x = (int) cx - r; x <= (int) cx + r; x++) {
                if (x < 0 || y < 0 || x >= W || y >= H || Math.hypot(x + 0.5 - cx, y + 0.5 - cy) > radius
                        || !v.vegetation()[y * W + x]) {
                    continue;
                }
                double[] hsv = ImageMetrics.hsv(v.full().at(x, y));
                if (hsv[1] >= 0.2 && nearestIsHeadOf(hsv[0], species, hues)) {
                    n++;
                }
            }
        }
        return n;
    }

    private static boolean nearestIsHeadOf(double hue, int species, List<double[]> hues) {
        double best = Double.MAX_VALUE;
        boolean head = false;
        for (double[] h : hues) {
            double d = Math.abs(hue - h[0]) % 360;
            d = Math.min(d, 360 - d);
            if (d < best || d == best && h[1] == species) {
                best = d;
                head = h[1] == species;
            }
        }
        return head;
    }

    private static double hue(Rgb c) {
        return ImageMetrics.hsv(new double[] {255 * c.r(), 255 * c.g(), 255 * c.b()})[0];
    }

    private static boolean hasHead(SpeciesModel m) {
        for (ComponentDef c : m.def().components()) {
            if (c.type() == ComponentType.HEAD || c.type() == ComponentType.PETAL) {
                return true;
            }
        }
        return false;
    }
}
