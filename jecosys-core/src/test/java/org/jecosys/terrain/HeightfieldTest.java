package org.jecosys.terrain;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.concurrent.atomic.AtomicLong;
import javax.imageio.ImageIO;
import org.jecosys.math.Progress;
import org.joml.Vector3f;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class HeightfieldTest {
    private static final double EPS = 1e-5;

    static TerrainDef hills(long seed, int res) {
        return new TerrainDef(40, 30, res, 5, 0.5, seed, null, ResourceMapDef.UNIFORM_FULL, ResourceMapDef.UNIFORM_FULL);
    }

    private static float[] heights(Heightfield hf) {
        return hf.copyHeights(new float[hf.resolution() * hf.resolution()]);
    }

    @Test
    void sameSeedSameHeightsDifferentSeedDifferentHeights() {
        Heightfield a = Heightfield.generate(hills(7, 65), 1, Progress.NONE);
        Heightfield b = Heightfield.generate(hills(7, 65), 1, Progress.NONE);
        Heightfield c = Heightfield.generate(hills(8, 65), 1, Progress.NONE);
        assertArrayEquals(heights(a), heights(b));
        assertFalse(Arrays.equals(heights(a), heights(c)));
    }

    @Test
    void threadCountDoesNotChangeHeights() {
        Heightfield one = Heightfield.generate(hills(3, 257), 1, Progress.NONE);
        Heightfield two = Heightfield.generate(hills(3, 257), 2, Progress.NONE);
        assertArrayEquals(heights(one), heights(two));
        assertArrayEquals(one.copyNormals(new float[3 * 257 * 257]), two.copyNormals(new float[3 * 257 * 257]));
    }

    @Test
    void resolutionBoundsAndHeightRangeAreHonoured() {
        Heightfield hf = Heightfield.generate(hills(11, 33), 1, Progress.NONE);
        assertEquals(33, hf.resolution());
        assertEquals(33 * 33, heights(hf).length);
        assertEquals(-20, hf.minX(), EPS);
        assertEquals(20, hf.maxX(), EPS);
        assertEquals(-15, hf.minZ(), EPS);
        assertEquals(15, hf.maxZ(), EPS);
        assertEquals(40.0 / 32, hf.cellX(), EPS);
        assertEquals(0, hf.minHeight(), EPS);
        assertEquals(5, hf.maxHeight(), EPS);
        for (float h : heights(hf)) {
            assertTrue(h >= 0 && h <= 5 + EPS);
        }
    }

    @Test
    void heightInterpolatesVerticesAndClampsOutside() {
        Heightfield hf = Heightfield.generate(hills(5, 17), 1, Progress.NONE);
        for (int j = 0; j < 17; j++) {
            for (int i = 0; i < 17; i++) {
                double x = hf.minX() + i * hf.cellX();
                double z = hf.minZ() + j * hf.cellZ();
                assertEquals(hf.vertexHeight(i, j), hf.height(x, z), 1e-4);
            }
        }
        double mid = hf.height(hf.minX() + 2.5 * hf.cellX(), hf.minZ() + 3 * hf.cellZ());
        assertEquals((hf.vertexHeight(2, 3) + hf.vertexHeight(3, 3)) / 2.0, mid, 1e-4);
        assertEquals(hf.height(hf.maxX(), 2), hf.height(1e6, 2), 0);
        assertEquals(hf.height(-3, hf.minZ()), hf.height(-3, -1e6), 0);
        assertEquals(hf.slope(hf.maxX(), 2), hf.slope(1e6, 2), 0);
    }

    @Test
    void flatTerrainHasZeroHeightSlopeAndUpNormals() {
        Heightfield hf = Heightfield.generate(TerrainDef.flat(), 2, Progress.NONE);
        assertEquals(0, hf.minHeight(), 0);
        assertEquals(0, hf.maxHeight(), 0);
        assertEquals(0, hf.slope(1.3, -4.2), 0);
        Vector3f n = hf.normal(3, 3, new Vector3f());
        assertEquals(1, n.y, 1e-6);
    }

    @Test
    void imageHeightmapGivesItsRampAndSlope(@TempDir Path dir) throws IOException {
        BufferedImage img = new BufferedImage(256, 64, BufferedImage.TYPE_BYTE_GRAY);
        for (int y = 0; y < 64; y++) {
            for (int x = 0; x < 256; x++) {
                img.getRaster().setSample(x, y, 0, x);
            }
        }
        Path png = dir.resolve("ramp.png");
        ImageIO.write(img, "png", png.toFile());
        TerrainDef def = new TerrainDef(50, 20, 65, 10, 0.5, 1, "ramp.png", ResourceMapDef.UNIFORM_FULL,
                ResourceMapDef.UNIFORM_FULL);
        AtomicLong reports = new AtomicLong();
        Heightfield hf = Heightfield.fromImage(def, ImageSource.folder(dir), (step, done, total) -> {
            assertEquals("terrain", step);
            reports.incrementAndGet();
        });
        assertTrue(reports.get() > 0);
        assertEquals(0, hf.height(-25, 0), 1e-4);
        assertEquals(10, hf.height(25, 0), 1e-4);
        assertEquals(5, hf.height(0, 3), 0.05);
        assertEquals(Math.atan(10.0 / 50), hf.slope(1.7, -2.2), 1e-3);
        Vector3f n = hf.normal(0, 0, new Vector3f());
        assertTrue(n.x < 0 && n.y > 0);
    }

    @Test
    void badArgumentsFailFastNamingTheArgument(@TempDir Path dir) throws IOException {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> Heightfield.generate(hills(1, 9), 0, Progress.NONE));
        assertTrue(e.getMessage().contains("workers"));
        Files.writeString(dir.resolve("x.png"), "hello");
        TerrainDef notImage = new TerrainDef(10, 10, 9, 1, 0.5, 1, "x.png", ResourceMapDef.UNIFORM_FULL,
                ResourceMapDef.UNIFORM_FULL);
        e = assertThrows(IllegalArgumentException.class,
                () -> Heightfield.fromImage(notImage, ImageSource.folder(dir), Progress.NONE));
        assertTrue(e.getMessage().contains("heightmap"));
        e = assertThrows(IllegalArgumentException.class,
                () -> Heightfield.of(10, 10, 3, new float[8]));
        assertTrue(e.getMessage().contains("heights"));
    }
}
