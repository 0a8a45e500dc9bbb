package org.jecosys.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.jecosys.math.ViewCamera;
import org.jecosys.plant.ComponentDef;
import org.jecosys.plant.ComponentType;
import org.jecosys.plant.SpeciesModel;
import org.jecosys.scene.SceneDef;
import org.jecosys.scene.SceneFiles;
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
 * distance) plus 2 pixels, a pixel is head-coloured when the head and petals put at least
 * {@link #HEAD_SHARE}/255 into its brightest channel: the same view is drawn a second time from the
 * same meadow with its head and petal colours black, and the two pictures are compared pixel by pixel
 * (lighting, sheen and fog add the same to both, so the difference is what the head's own colour
 * brings). Until the meadow's grasses came into flower this test classified a pixel by its hue,
 * nearest to a head or petal colour of the flower's species than to any other component colour of the
 * scene; the grasses' straw culms and panicles (hue 45-53 degrees) then stood between the yellow
 * flower's orange head (39) and its petals (51), and lit petals were counted as straw.
 * A flower whose head is hidden by something nearer the camera may show fewer: in a dense
 * patch one flower or a tall grass leaf hides another (the clumped meadow of issue 25 grows its
 * plants in tight groups of uneven height). Hidden means that another flower's head nearer the camera
 * overlaps its circle on screen, or that fewer than 12 pixels of its circle show what is at the head's
 * distance or beyond, the rest something at least 5 cm nearer (the depth of the whole scene, read
 * back); at most 5% of the flowers of a view may be hidden so. In the views of the densest patches
 * (hundreds of flowers in tight groups of uneven height and lean since issue 25) at most 2% of the
 * others may show fewer (a head partly behind another at almost its distance, or turned away from
 * the light and the eye); in the default view none may.
 */
@org.junit.jupiter.api.Tag("slow") // 11-13 s; mvn -B verify -Pnightly runs it (FlowerSizeTest keeps flower heads in the default run)
class FlowerHeadsTest {
    private static final int W = 960;
    private static final int H = 540;
    private static final double RANGE = 10;
    private static final int MIN_PIXELS = 6;
    /** The least the head's colour adds to a pixel's brightest channel for the pixel to count (0..255). */
    static final int HEAD_SHARE = 40;

    @Test
    void everyNearFlowerShowsItsHead() throws Exception {
        String xml = Files.readString(Path.of("scenes", "meadow.xml"));
        SceneDef def = SceneFiles.parse(xml.getBytes(StandardCharsets.UTF_8), "meadow.xml", Path.of("scenes"));
        SceneDef keyed = SceneFiles.parse(blackHeads(xml).getBytes(StandardCharsets.UTF_8), "meadow-keyed.xml",
                Path.of("scenes"));
        World world = RenderScenes.build(def);
        World keyedWorld = RenderScenes.build(keyed);
        assertEquals(world.plantCount(), keyedWorld.plantCount(), "the keyed meadow grows the same plants");
        for (int p = 0; p < world.plantCount(); p += 997) {
            assertEquals(world.plantX(p), keyedWorld.plantX(p), "plant " + p + " x");
            assertEquals(world.plantZ(p), keyedWorld.plantZ(p), "plant " + p + " z");
            assertEquals(world.plantVariant(p), keyedWorld.plantVariant(p), "plant " + p + " variant");
        }
        // the views: the default one, then one of each flower species' densest patch
        List<String> names = new ArrayList<>();
        List<ViewCamera> cams = new ArrayList<>();
        List<Boolean> mustHold = new ArrayList<>();
        names.add("default view");
        cams.add(RenderScenes.camera(def, world, W, H));
        mustHold.add(false);
        for (int s = 0; s < world.plants().species().size(); s++) {
            SpeciesModel m = world.plants().species().get(s);
            if (MeadowSpots.stalkSlot(m) < 0 || !hasHead(m)) {
                continue;
            }
            int c = world.densestPlant(s, 2);
            double x = world.plantX(c);
            double y = world.plantY(c);
            double z = world.plantZ(c);
            double ey = world.terrain().heightfield().height(x, z + 4) + 1.7;
            names.add(m.def().name() + " patch");
            cams.add(Shots.lookAt(x, ey, z + 4, x, y, z, def.camera().fovY(), W / (double) H, 0.05, 500));
            mustHold.add(true);
        }
        // one GL context at a time (each Shots makes its own current): the meadow's pictures and depths
        // first, then the keyed meadow's pictures
        List<ImageMetrics.Img> pictures = new ArrayList<>();
        List<double[]> depths = new ArrayList<>();
        try (Shots shots = new Shots(world, RenderScenes.settings(def), W, H)) {
            for (ViewCamera cam : cams) {
                pictures.add(shots.render(TestFrames.rest(world, cam), cam, true, true));
                depths.add(shots.sceneDistance(TestFrames.rest(world, cam), cam));
            }
        }
        List<ImageMetrics.Img> keyedPictures = new ArrayList<>();
        try (Shots shots = new Shots(keyedWorld, RenderScenes.settings(keyed), W, H)) {
            for (ViewCamera cam : cams) {
                keyedPictures.add(shots.render(TestFrames.rest(keyedWorld, cam), cam, true, true));
            }
        }
        List<String> failures = new ArrayList<>();
        for (int i = 0; i < cams.size(); i++) {
            check(world, pictures.get(i), keyedPictures.get(i), depths.get(i), cams.get(i), names.get(i),
                    mustHold.get(i), failures);
        }
        assertTrue(failures.isEmpty(), "flowers within 10 m with fewer than " + MIN_PIXELS
                + " head-coloured pixels: " + failures);
    }

    /** The scene with every head and petal component's colour black (and nothing else changed). */
    static String blackHeads(String xml) {
        Matcher m = Pattern.compile("<component\\b[^>]*>", Pattern.DOTALL).matcher(xml);
        StringBuilder out = new StringBuilder();
        int keyedParts = 0;
        while (m.find()) {
            String tag = m.group();
            if (tag.contains("type=\"head\"") || tag.contains("type=\"petal\"")) {
                tag = tag.replaceFirst("colour=\"#[0-9a-fA-F]{6}\"", "colour=\"#000000\"");
                keyedParts++;
            }
            m.appendReplacement(out, Matcher.quoteReplacement(tag));
        }
        m.appendTail(out);
        assertTrue(keyedParts >= 3, "the meadow's head and petal components: " + keyedParts);
        return out.toString();
    }

    private static void check(World world, ImageMetrics.Img picture, ImageMetrics.Img keyed, double[] depth,
                              ViewCamera cam, String view, boolean mustHoldFlowers, List<String> failures) {
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
            int n = headPixels(picture, keyed, h[0], h[1], h[3]);
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

    /**
     * Pixels within radius of (cx, cy) where the head's colour adds at least {@link #HEAD_SHARE} to the
     * brightest channel: the picture against the same one with black heads and petals.
     */
    private static int headPixels(ImageMetrics.Img picture, ImageMetrics.Img keyed, double cx, double cy,
                                  double radius) {
        int n = 0;
        int r = (int) Math.ceil(radius);
        for (int y = (int) cy - r; y <= (int) cy + r; y++) {
            for (int x = (int) cx - r; x <= (int) cx + r; x++) {
                if (x < 0 || y < 0 || x >= W || y >= H || Math.hypot(x + 0.5 - cx, y + 0.5 - cy) > radius) {
                    continue;
                }
                int a = picture.at(x, y);
                int b = keyed.at(x, y);
                int added = Math.max(ImageMetrics.r(a) - ImageMetrics.r(b), Math.max(
                        ImageMetrics.g(a) - ImageMetrics.g(b), ImageMetrics.b(a) - ImageMetrics.b(b)));
                if (added >= HEAD_SHARE) {
                    n++;
                }
            }
        }
        return n;
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
