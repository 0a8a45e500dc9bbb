package org.jecosys.render;

import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.lwjgl.opengl.GL11C.GL_COLOR_BUFFER_BIT;
import static org.lwjgl.opengl.GL11C.GL_DEPTH_BUFFER_BIT;
import static org.lwjgl.opengl.GL11C.glClear;
import static org.lwjgl.opengl.GL11C.glClearColor;

import java.awt.image.BufferedImage;
import java.nio.ByteBuffer;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.jecosys.math.Progress;
import org.jecosys.math.ViewCamera;
import org.jecosys.render.gl.Pixels;
import org.jecosys.scene.Scene;
import org.jecosys.scene.SceneDef;
import org.jecosys.scene.SceneFiles;
import org.jecosys.sim.Frame;
import org.jecosys.sim.World;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.lwjgl.system.MemoryUtil;

/**
 * Issue 40, "Done when", alpha edges. <b>No dark fringe:</b> a card (a 25 cm ribbon facing the eye, 2.2 m
 * away, 480x270, 4 samples) textured with a band of colour over the middle 60% of its width, the rest
 * transparent with black colour (as many exporters write it), is drawn over two plain backgrounds;
 * from the two pictures each pixel's coverage and the plant's own colour there are recovered
 * (p = c plant + (1 - c) background). Where the outline crosses a pixel (coverage 0.2 to 0.8) that
 * colour's luminance is within 10/255 of the same pixel's on the same card textured opaque all over
 * (the same geometry and light, the image without an outline). <b>Motion:</b> half a pixel of camera
 * motion changes the textured meadow's default view by at most 2/255 beyond a smooth shift over the
 * vegetation ({@link AntiAliasingTest}'s measure).
 */
class TexturedEdgesTest {
    private static final int W = 960;
    private static final int H = 540;
    private static final int COLOUR = 0x96be6e;

    @TempDir
    Path dir;

    private World card(String name, boolean outline) throws Exception {
        BufferedImage img = new BufferedImage(64, 64, BufferedImage.TYPE_INT_ARGB);
        for (int y = 0; y < 64; y++) {
            for (int x = 0; x < 64; x++) {
                double u = (x + 0.5) / 64 - 0.5;
                img.setRGB(x, y, !outline || Math.abs(u) < 0.3 ? 0xff000000 | COLOUR : 0x00000000);
            }
        }
        ImageIO.write(img, "png", dir.resolve(name + ".png").toFile());
        Files.writeString(dir.resolve(name + ".xml"), """
                <?xml version="1.0" encoding="UTF-8"?>
                <scene version="1" name="Card" seed="3">
                  <terrain sizeX="4" sizeZ="4" resolution="17"/>
                  <species id="card" maxBend="80">
                    <lod/>
                    <variation variants="1" length="0" width="0" curvature="0" tilt="0" hue="0" value="0" dryTips="0"/>
                    <component id="stalk" type="stalk" segments="8" length="1" baseWidth="0.25" tipWidth="0.25"
                        mass="0.01" stiffness="1" colour="#ffffff" texture="%s.png" lodSegments="8"/>
                  </species>
                  <plant species="card" x="0" z="0"/>
                </scene>
                """.formatted(name));
        Scene scene = SceneFiles.read(dir.resolve(name + ".xml"));
        return World.build(scene.def().simulationDef(), scene.images(), 1, Progress.NONE);
    }

    /** The card's pictures: 480x270, the card about 33 pixels wide. */
    private static final int CW = 480;
    private static final int CH = 270;

    /** A picture of {@code world} with plants only, drawn over the host's background (no sky, no terrain). */
    private static Shots guest(World world) {
        RenderSettings settings = RenderSettings.standalone();
        settings.setClear(false);
        settings.setTerrain(false);
        return new Shots(world, settings, CW, CH);
    }

    /** Luminance, 0..255, of each pixel of a picture drawn over a plain background of grey {@code bg}. */
    private static double[] over(Shots s, World world, float bg, ViewCamera cam) {
        ByteBuffer px = MemoryUtil.memAlloc(4 * CW * CH);
        try {
            Frame f = TestFrames.rest(world, cam);
            s.fb.bind();
            glClearColor(bg, bg, bg, 1f);
            glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
            s.renderer.render(f, cam, CW, CH);
            s.fb.resolve();
            Pixels.read(CW, CH, px);
            double[] l = new double[CW * CH];
            for (int i = 0; i < l.length; i++) {
                l[i] = 0.2126 * (px.get(4 * i) & 255) + 0.7152 * (px.get(4 * i + 1) & 255) + 0.0722 * (px.get(4 * i + 2) & 255);
            }
            return l;
        } finally {
            MemoryUtil.memFree(px);
        }
    }

    @Test
    void theOutlineOfATexturedPartHasNoDarkFringe() throws Exception {
        ViewCamera cam = Shots.lookAt(0, 0.5, 2.2, 0, 0.5, 0, Math.toRadians(50), CW / (double) CH, 0.05, 100);
        World cut = card("cut", true);
        World full = card("full", false);
        double[] light;
        double[] dark;
        double[] opaqueLight;
        double[] opaqueDark;
        try (Shots s = guest(cut)) {
            light = over(s, cut, 0.9f, cam);
            dark = over(s, cut, 0.1f, cam);
        }
        try (Shots s = guest(full)) {
            opaqueLight = over(s, full, 0.9f, cam);
            opaqueDark = over(s, full, 0.1f, cam);
        }
        double bgLight = light[0];
        double bgDark = dark[0];
        double sum = 0;
        double ref = 0;
        int n = 0;
        for (int i = 0; i < light.length; i++) {
            double cover = 1 - (light[i] - dark[i]) / (bgLight - bgDark);
            double fullCover = 1 - (opaqueLight[i] - opaqueDark[i]) / (bgLight - bgDark);
            if (cover < 0.2 || cover > 0.8 || fullCover < 0.98) {
                continue; // not on the outline, or at the card's own edge
            }
            sum += (dark[i] - (1 - cover) * bgDark) / cover;
            ref += opaqueDark[i];
            n++;
        }
        double edge = sum / Math.max(1, n);
        double plain = ref / Math.max(1, n);
        System.out.printf("[look] textured card outline: %d pixels, the part's own luminance there %.1f/255, the"
                + " opaque card's %.1f/255 (within 10)%n", n, edge, plain);
        assertTrue(n > 100, "the outline crosses pixels: " + n);
        assertTrue(Math.abs(edge - plain) <= 10, String.format("the outline's colour %.1f/255 against %.1f/255: a"
                + " fringe", edge, plain));
    }

    @Test
    void halfAPixelOfCameraMotionChangesTheTexturedMeadowLittle() throws Exception {
        SceneDef def = RenderScenes.load("textured.xml");
        World world = RenderScenes.build(def);
        try (Shots s = new Shots(world, RenderScenes.settings(def), W, H)) {
            double residual = AntiAliasingTest.HalfPixel.of(s, def, world).residual();
            System.out.printf("[look] textured meadow half-pixel shift: %.2f/255 from a smooth shift over"
                    + " vegetation (<= 2)%n", residual);
            assertTrue(residual <= 2, String.format("half a pixel of camera motion changes the textured meadow by"
                    + " %.2f/255 beyond a smooth shift, want <= 2/255", residual));
        }
    }
}
