package org.jecosys.plant;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.util.List;
import java.util.Map;
import javax.imageio.ImageIO;
import org.jecosys.math.Rgb;
import org.jecosys.terrain.ImageSource;
import org.junit.jupiter.api.Test;

/**
 * The images drawn on components, prepared once ({@link PlantTextures}): a layer per distinct image at a
 * shared power-of-two side, rows from the base (the image's bottom); the colour under transparent
 * texels bled from the nearest visible one (no dark fringe); every mip level keeping the full image's
 * coverage where plain averaging loses a thin stem; the layer's alpha-weighted mean colour; and the
 * refusals (too large, not an image), each naming the path.
 */
class PlantTexturesTest {
    private static ComponentDef leaf(String id, String texture) {
        return ComponentDef.builder(id, ComponentType.LEAF).segments(3).length(0.3).baseWidth(0.01).mass(0.001)
                .stiffness(0.2).lodSegments(3).colour(new Rgb(1, 1, 1)).texture(texture).build();
    }

    private static SpeciesDef species(ComponentDef... components) {
        return SpeciesDef.builder("s").lods(List.of(new LodDef(Double.POSITIVE_INFINITY, Primitive.TRIANGLES)))
                .components(List.of(components)).build();
    }

    /** A width x height image, every pixel {@code argb} but those {@code paint} sets. */
    private static PlantTextures.Image image(int w, int h, int argb, java.util.function.IntBinaryOperator paint) {
        int[] px = new int[w * h];
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                px[y * w + x] = paint == null ? argb : paint.applyAsInt(x, y);
            }
        }
        return new PlantTextures.Image(w, h, px);
    }

    @Test
    void aLayerPerDistinctImageAtOneSideWithRowsFromTheBase() {
        // 100 x 30: red top row, blue bottom row, green between
        PlantTextures.Image a = image(100, 30, 0, (x, y) -> y == 0 ? 0xffff0000 : y == 29 ? 0xff0000ff : 0xff00ff00);
        PlantTextures.Image b = image(8, 8, 0xff808080, null);
        PlantTextures t = PlantTextures.of(List.of(species(leaf("l", "a.png"), leaf("m", "b.png"), leaf("n", "a.png"),
                leaf("o", null))), Map.of("a.png", a, "b.png", b));
        assertEquals(2, t.layers());
        assertEquals(128, t.side(), "the largest side, rounded up to a power of two");
        assertEquals(8, t.levelCount());
        assertEquals(0, t.layer(0, 0));
        assertEquals(1, t.layer(0, 1));
        assertEquals(0, t.layer(0, 2), "the same image, the same layer");
        assertEquals(-1, t.layer(0, 3));
        byte[] level0 = t.level(0, 0);
        assertEquals(4 * 128 * 128, level0.length);
        assertTrue((level0[2] & 255) > 200 && (level0[0] & 255) < 60, "row 0 is the image's bottom row (blue)");
        int top = 4 * 127 * 128;
        assertTrue((level0[top] & 255) > 200 && (level0[top + 2] & 255) < 60, "the last row is its top row (red)");
        for (int m = 0; m < t.levelCount(); m++) {
            assertEquals(4 * (128 >> m) * (128 >> m), t.level(1, m).length);
        }
        assertSame(PlantTextures.NONE, PlantTextures.of(List.of(species(leaf("l", null))), Map.of()));
        assertThrows(IllegalArgumentException.class,
                () -> PlantTextures.of(List.of(species(leaf("l", "c.png"))), Map.of()));
    }

    @Test
    void transparentTexelsTakeTheNearestVisibleColourSoNoDarkFringeIsFiltered() {
        // a green blade in the middle third, transparent black around it (as many exporters write it)
        PlantTextures.Image img = image(48, 48, 0, (x, y) -> x >= 16 && x < 32 ? 0xff30c040 : 0x00000000);
        PlantTextures t = PlantTextures.of(List.of(species(leaf("l", "g.png"))), Map.of("g.png", img));
        for (int m = 0; m < t.levelCount(); m++) {
            byte[] l = t.level(0, m);
            for (int i = 0; i < l.length; i += 4) {
                assertTrue((l[i + 1] & 255) > 150, "level " + m + " texel " + i / 4 + ": green " + (l[i + 1] & 255)
                        + ", not the file's black");
            }
        }
        float[] mean = t.meanColour(0, new float[3]);
        assertEquals(0x30 / 255f, mean[0], 0.02);
        assertEquals(0xc0 / 255f, mean[1], 0.02);
    }

    @Test
    void everyMipLevelKeepsTheCoverageOfAThinStem() {
        // a stem two texels wide in a 64 x 64 image: 1/32 of the texels covered
        PlantTextures.Image img = image(64, 64, 0, (x, y) -> x == 32 || x == 33 ? 0xff406020 : 0x00406020);
        PlantTextures t = PlantTextures.of(List.of(species(leaf("l", "stem.png"))), Map.of("stem.png", img));
        double full = t.coverage(0);
        assertEquals(1 / 32.0, full, 1e-9);
        for (int m = 1; m < t.levelCount() - 2; m++) {
            int side = 64 >> m;
            byte[] l = t.level(0, m);
            int covered = 0;
            for (int i = 3; i < l.length; i += 4) {
                covered += (l[i] & 255) >= 128 ? 1 : 0;
            }
            double share = covered / (double) (side * side);
            // at least the full image's share; at most one column of this level (the stem cannot be thinner)
            assertTrue(share >= full * 0.99 && share <= Math.max(full, 1.0 / side) + 1e-9,
                    "level " + m + " (" + side + " a side): coverage " + share + ", the image's " + full);
        }
        // plain averaging would have lost it: two texels of alpha 1 in 8 (level 3) average to 0.25
        assertTrue(TextureFilter.alphaScale(new float[] {0, 0, 0, 0.25f, 0, 0, 0, 0f}, 0.5) >= 2f);
    }

    @Test
    void loadReadsThroughTheImageSourceAndRefusesWhatItCannotUseNamingThePath() throws IOException {
        BufferedImage png = new BufferedImage(20, 40, BufferedImage.TYPE_INT_ARGB);
        png.setRGB(3, 5, 0xffff0000);
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        ImageIO.write(png, "png", bytes);
        List<SpeciesDef> sp = List.of(species(leaf("l", "ok.png")));
        PlantTextures t = PlantTextures.load(sp, ImageSource.of(Map.of("ok.png", bytes.toByteArray()))::read);
        assertEquals(64, t.side());
        assertSame(PlantTextures.NONE, PlantTextures.load(List.of(species(leaf("l", null))), ImageSource.NONE::read));
        IOException notImage = assertThrows(IOException.class, () -> PlantTextures.load(sp,
                ImageSource.of(Map.of("ok.png", "not a png".getBytes(java.nio.charset.StandardCharsets.UTF_8)))::read));
        assertTrue(notImage.getMessage().contains("ok.png"), notImage.getMessage());
        BufferedImage big = new BufferedImage(PlantTextures.MAX_SIDE + 1, 2, BufferedImage.TYPE_INT_ARGB);
        ByteArrayOutputStream bigBytes = new ByteArrayOutputStream();
        ImageIO.write(big, "png", bigBytes);
        IOException tooBig = assertThrows(IOException.class, () -> PlantTextures.load(sp,
                ImageSource.of(Map.of("ok.png", bigBytes.toByteArray()))::read));
        assertTrue(tooBig.getMessage().contains("ok.png") && tooBig.getMessage().contains("at most"),
                tooBig.getMessage());
    }
}
