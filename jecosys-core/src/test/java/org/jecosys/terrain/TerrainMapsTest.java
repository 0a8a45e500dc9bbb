package org.jecosys.terrain;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import javax.imageio.ImageIO;
import org.jecosys.math.Progress;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class TerrainMapsTest {
    @Test
    void writesReadableMapsOfTheRightSize(@TempDir Path dir) throws IOException {
        Terrain t = CompetitiveDistributorTest.meadow(1);
        PlantLayout l = new CompetitiveDistributor().distribute(t, List.of("A", "B", "C"),
                List.of(CompetitiveDistributorTest.tuft(200), CompetitiveDistributorTest.yellow(100)), List.of(), 1, 1,
                Progress.NONE);
        Path water = dir.resolve("maps/water.png");
        Path nutrients = dir.resolve("maps/nutrients.png");
        Path species = dir.resolve("maps/species.png");
        TerrainMaps.writeWater(t.water(), 64, 48, water);
        TerrainMaps.writeNutrients(l.remainingNutrients(), 32, 32, nutrients);
        int[] palette = {0x22AA22, 0xFFDD00, 0x8833CC};
        TerrainMaps.writeSpecies(t.heightfield(), l, palette, 400, 400, species);

        BufferedImage w = ImageIO.read(water.toFile());
        assertNotNull(w);
        assertEquals(64, w.getWidth());
        assertEquals(48, w.getHeight());
        BufferedImage n = ImageIO.read(nutrients.toFile());
        assertEquals(32, n.getWidth());
        BufferedImage s = ImageIO.read(species.toFile());
        assertEquals(400, s.getWidth());
        assertEquals(400, s.getHeight());
        // a plant's centre pixel carries its species colour
        int px = (int) ((l.x(0) + 20) / 40 * 400);
        int py = (int) ((l.z(0) + 20) / 40 * 400);
        assertEquals(palette[l.species(0)], s.getRGB(px, py) & 0xFFFFFF);
        // the water map is not one flat colour
        java.util.Set<Integer> colours = new java.util.HashSet<>();
        for (int y = 0; y < 48; y++) {
            for (int x = 0; x < 64; x++) {
                colours.add(w.getRGB(x, y));
            }
        }
        assertTrue(colours.size() > 10, "water map colours: " + colours.size());
    }

    @Test
    void levelsMapToTheRampEnds(@TempDir Path dir) throws IOException {
        ResourceMap half = ResourceMap.of(10, 10, 2, new double[] {0, 1, 0, 1});
        Path out = dir.resolve("l.png");
        TerrainMaps.writeLevels(half, 0x000000, 0xFFFFFF, 8, 2, out);
        BufferedImage img = ImageIO.read(out.toFile());
        assertEquals(0x000000, img.getRGB(0, 0) & 0xFFFFFF);
        assertEquals(0xFFFFFF, img.getRGB(7, 1) & 0xFFFFFF);
        assertTrue((img.getRGB(4, 0) & 0xFF) > 0x40);
    }

    @Test
    void paletteTooShortOrBadSizeFailsFast(@TempDir Path dir) throws IOException {
        Terrain t = CompetitiveDistributorTest.meadow(2);
        PlantLayout l = new CompetitiveDistributor().distribute(t, List.of("A", "B", "C"),
                List.of(CompetitiveDistributorTest.yellow(5)), List.of(), 1, 1, Progress.NONE);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> TerrainMaps.writeSpecies(t.heightfield(), l, new int[] {1}, 10, 10, dir.resolve("s.png")));
        assertTrue(e.getMessage().contains("palette"));
        e = assertThrows(IllegalArgumentException.class,
                () -> TerrainMaps.writeWater(t.water(), 0, 10, dir.resolve("w.png")));
        assertTrue(e.getMessage().contains("width"));
    }
}
