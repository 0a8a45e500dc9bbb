package org.jecosys.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashSet;
import java.util.Set;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code jecosys gallery}: every view is written, at the asked size, and shows more than one colour
 * (tagged slow: it builds every gallery scene, about 25 s under CI, so it runs with {@code -Pnightly};
 * the default run keeps the flag checks).
 */
class GalleryCommandTest {
    @TempDir
    Path dir;

    @Test
    @org.junit.jupiter.api.Tag("slow")
    void writesEveryViewAtTheAskedSize() throws Exception {
        Path out = dir.resolve("gallery");
        CliTest.Result r = CliTest.run("gallery", "--out", out.toString(), "--size", "160x90");
        assertEquals(0, r.code(), r.err());
        for (String name : Gallery.FILES) {
            Path f = out.resolve(name);
            assertTrue(Files.isRegularFile(f), name + " missing; wrote: " + r.out());
            BufferedImage img = ImageIO.read(f.toFile());
            assertEquals(160, img.getWidth(), name);
            assertEquals(90, img.getHeight(), name);
            Set<Integer> colours = new HashSet<>();
            for (int y = 0; y < img.getHeight(); y++) {
                for (int x = 0; x < img.getWidth(); x++) {
                    colours.add(img.getRGB(x, y) & 0xFFFFFF);
                }
            }
            assertTrue(colours.size() >= 20, name + " is nearly blank: " + colours.size() + " colours");
        }
        assertTrue(r.out().contains("meadow-default.png"), r.out());
    }

    @Test
    void badFlagsAreBadInput() {
        CliTest.Result size = CliTest.run("gallery", "--out", dir.toString(), "--size", "10x10");
        assertEquals(2, size.code());
        assertTrue(size.err().contains("each side must be in [16, 8192]"), size.err());
        CliTest.Result unknown = CliTest.run("gallery", "--out", dir.toString(), "--bogus");
        assertEquals(2, unknown.code());
        assertTrue(unknown.err().contains("Unknown option: '--bogus'"), unknown.err());
        assertTrue(unknown.err().contains("Usage: jecosys gallery"), unknown.err());
        CliTest.Result noOut = CliTest.run("gallery");
        assertEquals(2, noOut.code());
        assertTrue(noOut.err().contains("--out"), noOut.err());
        CliTest.Result scenes = CliTest.run("gallery", "--out", dir.toString(), "--scenes", dir.toString());
        assertEquals(2, scenes.code());
        assertTrue(scenes.err().contains("--scenes") && scenes.err().contains("no meadow.xml"), scenes.err());
    }
}
