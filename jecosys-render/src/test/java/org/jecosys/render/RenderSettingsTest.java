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
        assertEquals(l.sunAzimuth(), s.lighting().sunAzimuth(), 1e-12);
        assertEquals(l.sunElevation(), s.lighting().sunElevation(), 1e-12);
        assertEquals(l.sunColour(), s.lighting().sunColour());
        assertEquals(l.sunIntensity(), s.lighting().sunIntensity(), 1e-6);
        assertEquals(l.skyZenith(), s.lighting().skyZenith());
        assertEquals(l.ambient(), s.lighting().ambient());
        assertEquals(l.contactShadow(), s.contactShadow(), 1e-6);
        assertEquals(l.fogStart(), s.lighting().fogStart(), 1e-6);
        assertEquals(l.fogEnd(), s.lighting().fogEnd(), 1e-6);
        assertEquals(p.scale(), s.patchScale(), 1e-6);
        assertEquals(p.strength(), s.patchStrength(), 1e-6);
        assertEquals(p.seed(), s.patchSeed());
        assertEquals(RenderDef.defaults().sky(), s.lighting().sky(), "the horizon is the old sky colour");
        assertNotEquals(s.lighting().sky(), s.lighting().skyZenith(), "a gradient by default");
    }

    @Test
    void sunVectorIsTowardTheSun() {
        RenderSettings s = new RenderSettings();
        assertTrue(s.lighting().sunX() < 0 && s.lighting().sunZ() > 0 && s.lighting().sunY() > 0.7, "default: high, behind-left of a -Z camera");
        float[][] cases = {{0, 0, 1, 0, 0}, {90, 0, 0, 0, 1}, {180, 0, -1, 0, 0}, {-90, 0, 0, 0, -1},
            {0, 90, 0, 1, 0}, {30, 40, 0, 0, 0}};
        for (float[] c : cases) {
            s.lighting().setSun(Math.toRadians(c[0]), Math.toRadians(c[1]));
            assertEquals(Math.toRadians(c[0]), s.lighting().sunAzimuth());
            assertEquals(Math.toRadians(c[1]), s.lighting().sunElevation());
            double az = Math.toRadians(c[0]);
            double el = Math.toRadians(c[1]);
            assertEquals(Math.cos(el) * Math.cos(az), s.lighting().sunX(), 1e-6);
            assertEquals(Math.sin(el), s.lighting().sunY(), 1e-6);
            assertEquals(Math.cos(el) * Math.sin(az), s.lighting().sunZ(), 1e-6);
            assertEquals(1, Math.sqrt(s.lighting().sunX() * s.lighting().sunX() + s.lighting().sunY() * s.lighting().sunY() + s.lighting().sunZ() * s.lighting().sunZ()), 1e-6);
        }
    }

    @Test
    void settersCheckTheirRanges() {
        RenderSettings s = new RenderSettings();
        s.lighting().setSun(Math.toRadians(10), Math.toRadians(20));
        s.setContactShadow(0.3f);
        s.setPatches(5, 0.5f, 9);
        assertThrows(IllegalArgumentException.class, () -> s.lighting().setSun(Math.toRadians(0), Math.toRadians(91)));
        assertThrows(IllegalArgumentException.class, () -> s.lighting().setSun(Math.toRadians(0), Math.toRadians(-1)));
        assertThrows(IllegalArgumentException.class, () -> s.lighting().setSun(Math.toRadians(361), Math.toRadians(10)));
        assertThrows(IllegalArgumentException.class, () -> s.lighting().setSun(Double.NaN, 0.1));
        assertThrows(IllegalArgumentException.class, () -> s.setContactShadow(1.1f));
        assertThrows(IllegalArgumentException.class, () -> s.lighting().setSunIntensity(5));
        assertThrows(IllegalArgumentException.class, () -> s.setPatches(0.1f, 0.5f, 1));
        assertThrows(IllegalArgumentException.class, () -> s.setPatches(10, -0.5f, 1));
        assertThrows(IllegalArgumentException.class, () -> s.lighting().setSunColour(null));
        assertThrows(IllegalArgumentException.class, () -> s.lighting().setSkyZenith(null));
        assertThrows(IllegalArgumentException.class, () -> s.lighting().setAmbient(null));
        assertEquals(Math.toRadians(10), s.lighting().sunAzimuth(), "a refused value leaves the setting as it was");
        assertEquals(Math.toRadians(20), s.lighting().sunElevation());
        assertEquals(0.3f, s.contactShadow());
        assertEquals(5, s.patchScale());
        assertEquals(0.5f, s.patchStrength());
        assertEquals(9, s.patchSeed());
        Rgb c = new Rgb(1, 0.5f, 0.25f);
        s.lighting().setSunColour(c);
        s.lighting().setSkyZenith(c);
        s.lighting().setAmbient(c);
        assertEquals(c, s.lighting().sunColour());
        assertEquals(c, s.lighting().skyZenith());
        assertEquals(c, s.lighting().ambient());
    }

    @Test
    void patchesAreSeededBoundedAndVaryOverTheirScale() {
        RenderSettings a = new RenderSettings();
        RenderSettings b = new RenderSettings();
        RenderSettings c = new RenderSettings();
        a.setPatches(10, 1, 3);
        b.setPatches(10, 1, 3);
        c.setPatches(10, 1, 4);
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

    @Test
    void everySetterReturnsNothingAndItsGetterReadsTheValueBack() throws Exception {
        for (java.lang.reflect.Method m : RenderSettings.class.getMethods()) {
            if (m.getDeclaringClass() == RenderSettings.class && m.getName().startsWith("set")) {
                assertEquals(void.class, m.getReturnType(), m.getName() + " returns nothing: one setter style");
            }
        }
        RenderSettings s = new RenderSettings();
        s.setSheen(1.5f);
        s.setShadows(0.4f);
        s.setShadowPath(ShadowPath.MAP);
        s.setShadowReach(30);
        s.lighting().setFog(5, 60);
        s.setClear(true);
        s.setTerrain(true);
        s.setTint(RenderDef.Tint.WATER);
        assertEquals(1.5f, s.sheen());
        assertEquals(0.4f, s.shadows());
        assertEquals(ShadowPath.MAP, s.shadowPath());
        assertEquals(30f, s.shadowReach());
        assertEquals(5f, s.lighting().fogStart());
        assertEquals(60f, s.lighting().fogEnd());
        assertTrue(s.clear() && s.terrain());
        assertEquals(RenderDef.Tint.WATER, s.tint());
        assertThrows(IllegalArgumentException.class, () -> s.setSheen(2.5f));
        assertThrows(IllegalArgumentException.class, () -> s.setShadows(-0.1f));
        assertThrows(IllegalArgumentException.class, () -> s.setShadowPath(null));
        assertThrows(IllegalArgumentException.class, () -> s.setShadowReach(1));
        assertThrows(IllegalArgumentException.class, () -> s.lighting().setFog(10, 10));
        assertThrows(IllegalArgumentException.class, () -> s.setTint(null));
        assertThrows(IllegalArgumentException.class, () -> s.setGroundCover(null));
        assertEquals(1.5f, s.sheen(), "a refused value leaves the setting as it was");
        assertEquals(5f, s.lighting().fogStart());
    }

    @Test
    void theOverlaysAreHiddenByDefaultAndASceneCanShowThem() {
        RenderSettings s = new RenderSettings();
        assertTrue(!s.overlays().showField() && !s.overlays().showWind(), "hidden by default");
        s.overlays().setShowWind(true);
        assertTrue(s.overlays().showWind() && !s.overlays().showField());
        RenderDef d = RenderDef.defaults();
        RenderDef shown = new RenderDef(d.width(), d.height(), d.sky(), d.lodTransition(), d.terrainTint(), true, false,
                d.light(), d.patches(), d.antialiasing(), d.groundCover());
        RenderSettings of = RenderSettings.of(shown);
        assertTrue(of.overlays().showField() && !of.overlays().showWind(), "the scene's showField and showWind");
    }

    @Test
    void aContextsDebugOutputIsNamedNotAFlag() {
        // refused before any GL call: no context is needed
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> GlContext.current(null));
        assertTrue(e.getMessage().contains("DebugOutput"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> GlContext.headless(null));
        assertThrows(IllegalArgumentException.class, () -> GlContext.windowed("t", 64, 64, null));
    }

    @Test
    void aGamesLightIsSetFromFloatsWithoutAllocation() {
        Lighting l = new RenderSettings().lighting();
        l.setSunDirection(0f, 2f, -2f);
        assertEquals(0, l.sunX(), 1e-6);
        assertEquals(Math.sqrt(0.5), l.sunY(), 1e-6);
        assertEquals(-Math.sqrt(0.5), l.sunZ(), 1e-6);
        assertEquals(Math.toRadians(45), l.sunElevation(), 1e-6);
        assertEquals(Math.toRadians(-90), l.sunAzimuth(), 1e-6);
        l.setSunDirection(1f, -1f, 0f);
        assertEquals(Math.toRadians(-45), l.sunElevation(), 1e-6, "a sun under the horizon, from a direction");
        assertThrows(IllegalArgumentException.class, () -> l.setSunDirection(0f, 0f, 0f));
        assertThrows(IllegalArgumentException.class, () -> l.setSunDirection(Float.NaN, 1f, 0f));
        l.setSunColour(1.5f, 1.2f, 0.9f);
        assertEquals(1.5f, l.sunR());
        assertEquals(new org.jecosys.math.Rgb(1f, 1f, 0.9f), l.sunColour(), "the Rgb getter clamps to [0, 1]");
        assertThrows(IllegalArgumentException.class, () -> l.setSunColour(4.5f, 0f, 0f));
        assertThrows(IllegalArgumentException.class, () -> l.setAmbient(-0.1f, 0f, 0f));
        assertThrows(IllegalArgumentException.class, () -> l.setSky(1.1f, 0f, 0f));
        assertEquals(1.5f, l.sunR(), "a refused value leaves the light as it was");
        assertTrue(l.hasFog());
        l.setNoFog();
        assertTrue(!l.hasFog() && l.fogStart() > 1e20f, "no haze within any view's reach");
        l.setFog(0f, 90f);
        assertTrue(l.hasFog());
        assertThrows(IllegalArgumentException.class, () -> l.setFog(10f, Float.POSITIVE_INFINITY));
        Lighting copy = new Lighting();
        copy.set(l);
        assertEquals(l.sunX(), copy.sunX());
        assertEquals(l.fogEnd(), copy.fogEnd());
        com.sun.management.ThreadMXBean mx =
                (com.sun.management.ThreadMXBean) java.lang.management.ManagementFactory.getThreadMXBean();
        long self = Thread.currentThread().getId();
        long least = Long.MAX_VALUE;
        for (int run = 0; run < 5; run++) {
            long before = mx.getThreadAllocatedBytes(self);
            for (int i = 0; i < 1000; i++) {
                l.setSunDirection(0.3f, 0.8f + i * 1e-4f, 0.1f);
                l.setSunColour(1f, 0.9f, 0.8f);
                l.setAmbient(0.4f, 0.4f, 0.5f);
                l.setSky(0.6f, 0.7f, 0.8f);
                l.setFog(0f, 100f + i);
            }
            least = Math.min(least, mx.getThreadAllocatedBytes(self) - before);
        }
        assertEquals(0, least, "bytes allocated by 1000 frames of a game's light");
    }
}
