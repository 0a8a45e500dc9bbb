package org.jecosys.terrain;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import java.util.concurrent.atomic.AtomicLong;
import javax.imageio.ImageIO;
import org.jecosys.math.Progress;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class TerrainTest {
    @Test
    void buildResolvesImagesAgainstBaseDirAndReportsProgress(@TempDir Path dir) throws IOException {
        BufferedImage img = new BufferedImage(16, 16, BufferedImage.TYPE_BYTE_GRAY);
        for (int y = 0; y < 16; y++) {
            for (int x = 0; x < 16; x++) {
                img.getRaster().setSample(x, y, 0, y * 16);
            }
        }
        ImageIO.write(img, "png", dir.resolve("rise.png").toFile());
        TerrainDef def = new TerrainDef(20, 20, 33, 3, 0.5, 1, "rise.png",
                new ResourceMapDef(ResourceMapDef.Source.IMAGE, 16, 1, 1, "rise.png"),
                new ResourceMapDef(ResourceMapDef.Source.NOISE, 16, 0.5, 4, null));
        AtomicLong last = new AtomicLong(-1);
        Terrain t = Terrain.build(def, dir, 2, (step, done, total) -> {
            assertEquals("terrain", step);
            assertTrue(done >= last.get() && done <= total);
            last.set(done);
        });
        assertEquals(1000, last.get());
        assertTrue(t.heightfield().height(0, 9) > t.heightfield().height(0, -9));
        assertTrue(t.water().sample(0, 9) > t.water().sample(0, -9));
        assertTrue(t.nutrients().max() <= 0.5 + 1e-12);
        assertTrue(t.water().frozen() && t.nutrients().frozen());
        Terrain again = Terrain.build(def, dir, 1, Progress.NONE);
        assertEquals(t.nutrients().level(3, 4), again.nutrients().level(3, 4), 0);
    }

    @Test
    void mapsMustCoverTheHeightfield() {
        Heightfield hf = Heightfield.of(10, 10, 2, new float[4]);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new Terrain(hf, ResourceMap.uniform(12, 10, 4, 1), ResourceMap.uniform(10, 10, 4, 1)));
        assertTrue(e.getMessage().contains("water"));
    }
}
