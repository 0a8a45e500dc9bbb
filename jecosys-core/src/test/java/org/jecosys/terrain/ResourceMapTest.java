package org.jecosys.terrain;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.jecosys.math.Progress;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class ResourceMapTest {
    private static final Heightfield FLAT = Heightfield.generate(TerrainDef.flat(), 1, Progress.NONE);

    @Test
    void uniformIsAmountEverywhere() throws IOException {
        ResourceMap m = ResourceMap.build(new ResourceMapDef(ResourceMapDef.Source.UNIFORM, 16, 0.7, 1, null), FLAT, 1, null);
        assertEquals(16, m.resolution());
        assertEquals(0.7, m.min(), 1e-12);
        assertEquals(0.7, m.max(), 1e-12);
        assertEquals(0.7, m.sample(3.3, -7.1), 1e-12);
        assertEquals(0.7, m.footprintLevel(0, 0, 0.2), 1e-12);
    }

    @Test
    void noiseIsSeededAndSpansZeroToAmount() throws IOException {
        ResourceMapDef def = new ResourceMapDef(ResourceMapDef.Source.NOISE, 64, 0.8, 6, null);
        ResourceMap a = ResourceMap.build(def, FLAT, 42, null);
        ResourceMap b = ResourceMap.build(def, FLAT, 42, null);
        ResourceMap c = ResourceMap.build(def, FLAT, 43, null);
        assertEquals(0, a.min(), 1e-12);
        assertEquals(0.8, a.max(), 1e-12);
        double diff = 0;
        for (int j = 0; j < 64; j++) {
            for (int i = 0; i < 64; i++) {
                assertEquals(a.level(i, j), b.level(i, j), 0);
                diff += Math.abs(a.level(i, j) - c.level(i, j));
            }
        }
        assertTrue(diff > 1);
    }

    @Test
    void valleysAreWetterThanHilltops() throws IOException {
        TerrainDef def = new TerrainDef(60, 60, 129, 8, 0.5, 9, null, ResourceMapDef.UNIFORM_FULL, ResourceMapDef.UNIFORM_FULL);
        Heightfield hf = Heightfield.generate(def, 1, Progress.NONE);
        ResourceMap w = ResourceMap.build(new ResourceMapDef(ResourceMapDef.Source.VALLEYS, 64, 1, 1, null), hf, 0, null);
        double lowSum = 0;
        double highSum = 0;
        int low = 0;
        int high = 0;
        double range = hf.maxHeight() - hf.minHeight();
        for (int j = 0; j < 64; j++) {
            for (int i = 0; i < 64; i++) {
                double x = -30 + (i + 0.5) * 60 / 64.0;
                double z = -30 + (j + 0.5) * 60 / 64.0;
                double t = (hf.height(x, z) - hf.minHeight()) / range;
                assertTrue(w.level(i, j) >= 0 && w.level(i, j) <= 1);
                if (t < 0.25) {
                    lowSum += w.level(i, j);
                    low++;
                } else if (t > 0.75) {
                    highSum += w.level(i, j);
                    high++;
                }
            }
        }
        assertTrue(low > 0 && high > 0);
        assertTrue(lowSum / low > highSum / high + 0.2, "low " + lowSum / low + " high " + highSum / high);
    }

    @Test
    void flatValleysAreWetEverywhere() throws IOException {
        ResourceMap w = ResourceMap.build(new ResourceMapDef(ResourceMapDef.Source.VALLEYS, 8, 0.5, 1, null), FLAT, 0, null);
        assertEquals(0.5, w.min(), 1e-12);
    }

    @Test
    void imageIsResampledAndScaled(@TempDir Path dir) throws IOException {
        BufferedImage img = new BufferedImage(2, 1, BufferedImage.TYPE_INT_RGB);
        img.setRGB(0, 0, 0x000000);
        img.setRGB(1, 0, 0xFFFFFF);
        Path png = dir.resolve("w.png");
        ImageIO.write(img, "png", png.toFile());
        ResourceMap m = ResourceMap.build(new ResourceMapDef(ResourceMapDef.Source.IMAGE, 8, 0.5, 1, "w.png"), FLAT, 0, ImageSource.folder(dir));
        assertEquals(0, m.level(0, 3), 1e-9);
        assertEquals(0.5, m.level(7, 3), 1e-9);
        assertTrue(m.sample(-5, 0) < m.sample(5, 0));
    }

    @Test
    void consumptionNeverGoesBelowZeroAndConservesWhileAvailable() {
        ResourceMap m = ResourceMap.uniform(40, 40, 64, 1.0);
        double before = m.total();
        double r = 0.2;
        m.consume(0.1, 0.1, r, 0.3);
        assertEquals(0.3 * Math.PI * r * r, before - m.total(), 0.03 * 0.3 * Math.PI * r * r);
        for (int k = 0; k < 200; k++) {
            m.consume(0.1, 0.1, r, 1);
        }
        assertTrue(m.min() >= 0);
        assertEquals(0, m.footprintLevel(0.1, 0.1, r), 1e-12);
        ResourceMap big = ResourceMap.uniform(40, 40, 64, 0.4);
        big.consume(3, 3, 5, 1);
        assertTrue(big.min() >= 0);
        assertEquals(0, big.footprintLevel(3, 3, 1), 1e-12);
    }

    @Test
    void frozenMapRefusesConsumptionAndCopiesAreMutable() {
        ResourceMap m = ResourceMap.uniform(10, 10, 4, 1).freeze();
        assertThrows(IllegalStateException.class, () -> m.consume(0, 0, 1, 0.5));
        ResourceMap c = m.copy();
        c.consume(0, 0, 1, 0.5);
        assertTrue(c.total() < m.total());
    }

    @Test
    void badArgumentsFailFast() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> ResourceMap.of(10, 10, 2, new double[] {0, 0.5, 1.5, 0}));
        assertTrue(e.getMessage().contains("levels"));
        TerrainDef def = new TerrainDef(10, 10, 9, 1, 0.5, 1, "hm.png", ResourceMapDef.UNIFORM_FULL, ResourceMapDef.UNIFORM_FULL);
        java.io.IOException io = assertThrows(java.io.IOException.class,
                () -> Terrain.build(def, ImageSource.NONE, 1, Progress.NONE));
        assertTrue(io.getMessage().contains("'hm.png'"), io.getMessage());
    }
}
