package org.jecosys.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import javax.imageio.ImageIO;
import org.jecosys.math.Progress;
import org.jecosys.math.ViewCamera;
import org.jecosys.plant.PlantTextures;
import org.jecosys.plant.SpeciesModel;
import org.jecosys.render.ImageMetrics.Img;
import org.jecosys.scene.Scene;
import org.jecosys.scene.SceneFiles;
import org.jecosys.sim.Frame;
import org.jecosys.sim.World;
import org.jecosys.sim.internal.FrameWriter;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Issue 40, "Done when": a texture of coloured stripes along v shows in order from base to tip on a
 * textured part at rest and bent, at 960x540 with the library's 4 samples. The scene: one plant whose
 * single component is a wide stalk (a ribbon that faces the eye) 1 m long, white, textured with four
 * bands from the image's bottom row to its top: red, yellow, green, magenta. Each plant pixel (the
 * picture with the plant against the one without) is given the band whose hue is nearest; each band
 * must hold at least 8% of the plant's pixels, and the bands' mean distance on screen from the
 * projected base must rise in the image's order, upright and bent 60 degrees to the right (its tip band
 * then more than 60 pixels right of where it stood). The far level (lines) takes the texture's mean
 * colour.
 */
class TexturedComponentsTest {
    private static final int W = 960;
    private static final int H = 540;
    /** The bands' colours, from the image's bottom row (the base) to its top (the tip), and their names. */
    private static final int[] BANDS = {0xff2828, 0xffff28, 0x28ff28, 0xff28ff};
    private static final String[] NAMES = {"red", "yellow", "green", "magenta"};

    @TempDir
    static Path dir;
    static World world;

    @BeforeAll
    static void scene() throws Exception {
        BufferedImage img = new BufferedImage(32, 64, BufferedImage.TYPE_INT_ARGB);
        for (int y = 0; y < 64; y++) {
            int band = 3 - y / 16; // the top rows are the tip's
            for (int x = 0; x < 32; x++) {
                img.setRGB(x, y, 0xff000000 | BANDS[band]);
            }
        }
        ImageIO.write(img, "png", dir.resolve("stripes.png").toFile());
        Files.writeString(dir.resolve("card.xml"), """
                <?xml version="1.0" encoding="UTF-8"?>
                <scene version="1" name="Textured card" seed="3">
                  <terrain sizeX="4" sizeZ="4" resolution="17"/>
                  <species id="card" name="striped card" maxBend="80">
                    <lod maxDistance="30"/>
                    <lod primitive="lines"/>
                    <variation variants="1" length="0" width="0" curvature="0" tilt="0" hue="0" value="0" dryTips="0"/>
                    <component id="stalk" type="stalk" segments="12" length="1" baseWidth="0.25" tipWidth="0.25"
                        mass="0.01" stiffness="1" colour="#ffffff" texture="stripes.png" lodSegments="12 4"/>
                  </species>
                  <plant species="card" x="0" z="0"/>
                  <camera x="0" y="0.5" z="2.2"/>
                </scene>
                """);
        Scene scene = SceneFiles.read(dir.resolve("card.xml"));
        world = World.build(scene.def().simulationDef(), scene.images(), 1, Progress.NONE);
    }

    @Test
    void theTextureIsLoadedAsALayerWithItsMeanForTheFarLevel() {
        PlantTextures t = world.plants().textures();
        assertEquals(1, t.layers());
        assertEquals("stripes.png", t.path(0));
        assertEquals(64, t.side(), "the larger side, a power of two");
        assertEquals(0, t.layer(0, 0));
        float[] mean = t.meanColour(0, new float[3]);
        // the four bands' mean: red (1, .16, .16), yellow (1, 1, .16), green (.16, 1, .16), magenta (1, .16, 1)
        assertEquals((1 + 1 + 0.157 + 1) / 4, mean[0], 0.02);
        assertEquals((0.157 + 1 + 1 + 0.157) / 4, mean[1], 0.02);
        assertEquals((0.157 + 0.157 + 0.157 + 1) / 4, mean[2], 0.02);
    }

    @Test
    void theStripesRunFromBaseToTipAtRestAndBent() {
        try (Shots s = new Shots(world, RenderScenes.settings(new SceneLike().def()), W, H)) {
            ViewCamera cam = Shots.lookAt(0, 0.55, 2.2, 0, 0.5, 0, Math.toRadians(50), W / (double) H, 0.05, 100);
            double upright = check(s, cam, TestFrames.rest(world, cam), "at rest");
            Frame bent = TestFrames.rest(world);
            SpeciesModel m = world.plants().species().get(0);
            int poses = m.slotPoseTable(0, 0).poses();
            // bent most of the way to the species' 80 degrees, toward +X: to the right in this view
            FrameWriter.set(bent, world.firstComponent(0), (float) ((poses - 1) * 0.75), 0f);
            double right = check(s, cam, TestFrames.decide(world, bent, cam), "bent");
            assertTrue(right > upright + 60, "the bent card's tip lies to the right: " + upright + " -> " + right);
        }
    }

    @Test
    void everyProgramVariantDrawsTexturedPartsWithoutAGlError() {
        // the sun's shadow map (caster and receiver programs) and a target without samples (the split
        // programs), each compiled with TEXTURED, under GL debug output
        RenderSettings settings = RenderScenes.settings(new SceneLike().def());
        settings.setShadowPath(ShadowPath.MAP);
        settings.setShadows(0.8f);
        ViewCamera cam = Shots.lookAt(0, 0.55, 2.2, 0, 0.5, 0, Math.toRadians(50), 320 / 180.0, 0.05, 100);
        try (GlContext gl = GlContext.headless(GlContext.DebugOutput.ON);
             org.jecosys.render.gl.GlFramebuffer multi = new org.jecosys.render.gl.GlFramebuffer(
                     org.jecosys.render.gl.GlContexts.tracker(gl), 320, 180, 4);
             org.jecosys.render.gl.GlFramebuffer single = new org.jecosys.render.gl.GlFramebuffer(
                     org.jecosys.render.gl.GlContexts.tracker(gl), 320, 180);
             SceneRenderer r = new SceneRenderer(gl, world, settings)) {
            Frame f = TestFrames.rest(world, cam);
            multi.bind();
            r.render(f, cam, 320, 180);
            single.bind();
            r.render(f, cam, 320, 180);
            assertTrue(r.drawCalls() > 0, "the card is drawn");
            org.jecosys.render.gl.GlContexts.debug(gl).check("textured parts in every program variant");
        }
    }

    /** Checks the bands' order and returns the tip band's mean X, pixels. */
    private static double check(Shots s, ViewCamera cam, Frame frame, String what) {
        Img with = s.render(frame, cam, true, true);
        Img without = s.render(frame, cam, false, true);
        double[] base = Shots.project(cam, world.plantX(0), world.plantY(0), world.plantZ(0), W, H);
        long[] count = new long[BANDS.length];
        double[] dist = new double[BANDS.length];
        double tipX = 0;
        long plant = 0;
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                int a = with.at(x, y);
                if (!ImageMetrics.differ(a, without.at(x, y))) {
                    continue;
                }
                plant++;
                int best = ImageMetrics.nearestHue(a, BANDS, 0.3f, 0.15f);
                if (best < 0) {
                    continue;
                }
                count[best]++;
                dist[best] += Math.hypot(x - base[0], y - base[1]);
                tipX += best == BANDS.length - 1 ? x : 0;
            }
        }
        StringBuilder report = new StringBuilder();
        for (int b = 0; b < BANDS.length; b++) {
            dist[b] /= Math.max(1, count[b]);
            report.append(String.format(Locale.ROOT, " %s %d px at %.0f px from the base;", NAMES[b], count[b], dist[b]));
        }
        System.out.println("[look] textured card " + what + ": " + plant + " plant pixels;" + report);
        assertTrue(plant > 10_000, what + ": the card is drawn large: " + plant + " pixels");
        for (int b = 0; b < BANDS.length; b++) {
            assertTrue(count[b] >= 0.08 * plant, what + ": band " + NAMES[b] + " shows:" + report);
            if (b > 0) {
                assertTrue(dist[b] > dist[b - 1] + 20, what + ": band " + NAMES[b] + " lies beyond " + NAMES[b - 1]
                        + " from the base:" + report);
            }
        }
        return tipX / Math.max(1, count[BANDS.length - 1]);
    }

    /** The render settings of the card's scene (sun, sky, haze as the schema's defaults). */
    private static final class SceneLike {
        org.jecosys.scene.SceneDef def() {
            try {
                return SceneFiles.parse(dir.resolve("card.xml"));
            } catch (Exception e) {
                throw new IllegalStateException(e);
            }
        }
    }
}
