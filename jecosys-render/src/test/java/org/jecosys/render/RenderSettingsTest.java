package org.jecosys.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.jecosys.math.Rgb;
import org.jecosys.scene.RenderDef;
import org.junit.jupiter.api.Test;

/**
 * The light, sky and patch settings: defaults equal the scene file's, the sun vector follows the
 * documented formula, setters check their ranges and keep the previous value on a bad one, and the
 * patch noise is seeded, bounded and varies over its scale.
 */
class RenderSettingsTest {
    @Test
    void defaultsAreTheSceneFilesDefaults() {
        RenderSettings s = new RenderSettings();
        RenderDef.Light l = RenderDef.Light.DEFAULT;
        RenderDef.Patches p = RenderDef.Patches.DEFAULT;
        assertEquals(l.sunAzimuth(), s.sunAzimuth(), 1e-12);
        assertEquals(l.sunElevation(), s.sunElevation(), 1e-12);
        assertEquals(l.sunColour(), s.sunColour());
        assertEquals(l.sunIntensity(), s.sunIntensity(), 1e-6);
        assertEquals(l.skyZenith(), s.skyZenith());
        assertEquals(l.ambient(), s.ambient());
        assertEquals(l.contactShadow(), s.contactShadow(), 1e-6);
        assertEquals(l.fogStart(), s.fogStart(), 1e-6);
        assertEquals(l.fogEnd(), s.fogEnd(), 1e-6);
        assertEquals(p.scale(), s.patchScale(), 1e-6);
        assertEquals(p.strength(), s.patchStrength(), 1e-6);
        assertEquals(p.seed(), s.patchSeed());
        assertEquals(RenderDef.defaults().sky(), s.sky(), "the horizon is the old sky colour");
        assertNotEquals(s.sky(), s.skyZenith(), "a gradient by default");
    }

    @Test
    void sunVectorIsTowardTheSun() {
        RenderSettings s = new RenderSettings();
        assertTrue(s.sunX() < 0 && s.sunZ() > 0 && s.sunY() > 0.7, "default: high, behind-left of a -Z camera");
        float[][] cases = {{0, 0, 1, 0, 0}, {90, 0, 0, 0, 1}, {180, 0, -1, 0, 0}, {-90, 0, 0, 0, -1},
            {0, 90, 0, 1, 0}, {30, 40, 0, 0, 0}};
        for (float[] c : cases) {
            assertSame(s, s.sun(Math.toRadians(c[0]), Math.toRadians(c[1])));
            assertEquals(Math.toRadians(c[0]), s.sunAzimuth());
            assertEquals(Math.toRadians(c[1]), s.sunElevation());
            double az = Math.toRadians(c[0]);
            double el = Math.toRadians(c[1]);
            assertEquals(Math.cos(el) * Math.cos(az), s.sunX(), 1e-6);
            assertEquals(Math.sin(el), s.sunY(), 1e-6);
            assertEquals(Math.cos(el) * Math.sin(az), s.sunZ(), 1e-6);
            assertEquals(1, Math.sqrt(s.sunX() * s.sunX() + s.sunY() * s.sunY() + s.sunZ() * s.sunZ()), 1e-6);
        }
    }

    @Test
    void settersCheckTheirRanges() {
        RenderSettings s = new RenderSettings().sun(Math.toRadians(10), Math.toRadians(20)).contactShadow(0.3f).patches(5, 0.5f, 9);
        assertThrows(IllegalArgumentException.class, () -> s.sun(Math.toRadians(0), Math.toRadians(91)));
        assertThrows(IllegalArgumentException.class, () -> s.sun(Math.toRadians(0), Math.toRadians(-1)));
        assertThrows(IllegalArgumentException.class, () -> s.sun(Math.toRadians(361), Math.toRadians(10)));
        assertThrows(IllegalArgumentException.class, () -> s.sun(Double.NaN, 0.1));
        assertThrows(IllegalArgumentException.class, () -> s.contactShadow(1.1f));
        assertThrows(IllegalArgumentException.class, () -> s.sunIntensity(5));
        assertThrows(IllegalArgumentException.class, () -> s.patches(0.1f, 0.5f, 1));
        assertThrows(IllegalArgumentException.class, () -> s.patches(10, -0.5f, 1));
        assertThrows(IllegalArgumentException.class, () -> s.sunColour(null));
        assertThrows(IllegalArgumentException.class, () -> s.skyZenith(null));
        assertThrows(IllegalArgumentException.class, () -> s.ambient(null));
        assertEquals(Math.toRadians(10), s.sunAzimuth(), "a refused value leaves the setting as it was");
        assertEquals(Math.toRadians(20), s.sunElevation());
        assertEquals(0.3f, s.contactShadow());
        assertEquals(5, s.patchScale());
        assertEquals(0.5f, s.patchStrength());
        assertEquals(9, s.patchSeed());
        Rgb c = new Rgb(1, 0.5f, 0.25f);
        assertSame(c, s.sunColour(c).sunColour());
        assertSame(c, s.skyZenith(c).skyZenith());
        assertSame(c, s.ambient(c).ambient());
    }

    @Test
    void patchesAreSeededBoundedAndVaryOverTheirScale() {
        RenderSettings a = new RenderSettings().patches(10, 1, 3);
        RenderSettings b = new RenderSettings().patches(10, 1, 3);
        RenderSettings c = new RenderSettings().patches(10, 1, 4);
        int dry = 0;
        int healthy = 0;
        int differ = 0;
        double smooth = 0;
        for (int i = 0; i < 100; i++) {
            for (int j = 0; j < 100; j++) {
                float x = i * 0.9f - 45;
                float z = j * 0.9f - 45;
                float v = a.patchLevel(x, z);
                assertTrue(v >= 0 && v <= 1, "level in [0, 1]: " + v);
                assertEquals(v, b.patchLevel(x, z), "same seed, same patches");
                if (v != c.patchLevel(x, z)) {
                    differ++;
                }
                dry += v > 0.9 ? 1 : 0;
                healthy += v < 0.1 ? 1 : 0;
                smooth = Math.max(smooth, Math.abs(a.patchLevel(x + 0.1f, z) - v));
            }
        }
        assertTrue(dry > 500 && healthy > 500, "both healthy and dry patches: " + healthy + ", " + dry);
        assertTrue(differ > 5000, "another seed, other patches: " + differ);
        assertTrue(smooth < 0.2, "smooth over 10 cm at a 10 m scale: " + smooth);
    }
}
