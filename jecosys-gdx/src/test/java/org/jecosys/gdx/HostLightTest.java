package org.jecosys.gdx;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.badlogic.gdx.backends.lwjgl3.Lwjgl3Files;
import com.badlogic.gdx.graphics.PerspectiveCamera;
import com.badlogic.gdx.graphics.g3d.Environment;
import com.badlogic.gdx.graphics.g3d.attributes.ColorAttribute;
import com.badlogic.gdx.graphics.g3d.environment.DirectionalLight;
import com.badlogic.gdx.utils.GdxNativesLoader;
import java.lang.management.ManagementFactory;
import java.nio.ByteBuffer;
import org.jecosys.render.GlContext;
import org.jecosys.render.GlContext.DebugOutput;
import org.jecosys.render.Lighting;
import org.jecosys.render.gl.GlContexts;
import org.jecosys.render.gl.GlFramebuffer;
import org.jecosys.render.gl.Pixels;
import org.jecosys.terrain.Heightfield;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.lwjgl.system.MemoryUtil;

/**
 * The game's libGDX {@link Environment} lights and fogs the plants ({@link PlantLayer#render(
 * com.badlogic.gdx.graphics.Camera, Environment)}): moving its sun and changing its fog colour change
 * the plants exactly as the same values set on the renderer's {@link Lighting} directly do (within
 * 2/255 per channel), the values are libGDX's (the sun opposite the light's direction, the fog full at
 * far / 1.09), and reading the environment every frame allocates nothing. In a headless context
 * standing in for libGDX's, over a cleared target, the paper's scene C1 seen from 4 m.
 */
class HostLightTest {
    private static final int W = 320;
    private static final int H = 180;

    @BeforeAll
    static void gdxNatives() {
        GdxNativesLoader.load();
    }

    @Test
    void theEnvironmentsSunAndFogLightThePlantsAsTheSameValuesSetDirectly() throws Exception {
        ByteBuffer px = MemoryUtil.memAlloc(4 * W * H);
        try (GlContext owner = GlContext.headless(DebugOutput.ON)) {
            GlFramebuffer target = new GlFramebuffer(GlContexts.tracker(owner), W, H);
            PlantLayer layer = PlantLayer.load(new Lwjgl3Files().local("scenes/c1.xml"));
            try {
                Heightfield t = layer.simulation().world().terrain().heightfield();
                PerspectiveCamera cam = new PerspectiveCamera(55, W, H);
                cam.near = 0.05f;
                cam.far = 12f; // the fog reaches into the plants
                cam.position.set(0, (float) t.height(0, 4) + 1.2f, 4);
                cam.lookAt(0, (float) t.height(0, 0), 0);
                cam.update();
                DirectionalLight sun = new DirectionalLight().set(0.95f, 0.9f, 0.75f, -0.4f, -0.8f, -0.3f);
                Environment env = new Environment();
                env.set(new ColorAttribute(ColorAttribute.AmbientLight, 0.35f, 0.4f, 0.5f, 1f));
                env.set(new ColorAttribute(ColorAttribute.Fog, 0.8f, 0.6f, 0.5f, 1f));
                env.add(sun);
                target.bind();
                for (int i = 0; i < 10; i++) {
                    layer.update(1 / 30f, cam);
                }

                int[] hosted = shot(layer, cam, env, target, px);
                Lighting l = layer.settings().lighting();
                float len = (float) Math.sqrt(0.16 + 0.64 + 0.09);
                assertEquals(0.4f / len, l.sunX(), 1e-5f, "toward the sun: opposite the light's direction");
                assertEquals(0.8f / len, l.sunY(), 1e-5f);
                assertEquals(0.95f, l.sunR(), 0f);
                assertEquals(1f, l.sunIntensity(), 0f);
                assertEquals(0.4f, l.ambientG(), 0f);
                assertEquals(0.6f, l.skyG(), 0f, "the fog colour");
                assertEquals(0f, l.fogStart(), 0f);
                assertEquals(12f / 1.09f, l.fogEnd(), 1e-3f, "libGDX's fog: full at far / 1.09");

                // the same values set on the renderer's light directly, after a reset to the scene's own
                l.set(new Lighting());
                l.setSunDirection(0.4f, 0.8f, 0.3f);
                l.setSunColour(0.95f, 0.9f, 0.75f);
                l.setSunIntensity(1f);
                l.setAmbient(0.35f, 0.4f, 0.5f);
                l.setSky(0.8f, 0.6f, 0.5f);
                l.setFog(0f, 12f / 1.09f);
                int[] direct = shot(layer, cam, null, target, px);
                int[] none = shot(layer, cam, EMPTY, target, px);
                double plantsShare = changed(hosted, none, 8);
                // flower parts keep a least size in proportion to the picture (8 px at 540 rows): at 180 rows
                // a third of that, so C1's sparse plants cover about 0.9% of it
                assertTrue(plantsShare > 0.005, "plants in the picture (C1's tufts are sparse): " + plantsShare);
                assertTrue(maxDiff(hosted, direct) <= 2, "the environment's light vs the same values set directly: "
                        + maxDiff(hosted, direct));

                // moving the engine's sun and changing its fog colour change the plants; directly the same
                sun.setDirection(0.6f, -0.5f, 0.2f);
                ((ColorAttribute) env.get(ColorAttribute.Fog)).color.set(0.3f, 0.4f, 0.9f, 1f);
                int[] moved = shot(layer, cam, env, target, px);
                l.setSunDirection(-0.6f, 0.5f, -0.2f);
                l.setSky(0.3f, 0.4f, 0.9f);
                int[] movedDirect = shot(layer, cam, null, target, px);
                double change = changed(hosted, moved, 6);
                System.out.printf("[look] libGDX environment: plants %.3f of the picture; moving the sun and the fog "
                        + "colour changed %.3f of it; max channel difference to the same light set directly %d/255%n",
                        plantsShare, change, maxDiff(moved, movedDirect));
                assertTrue(change > 0.5 * plantsShare, "the plants changed with the sun and fog: " + change);
                assertTrue(maxDiff(moved, movedDirect) <= 2, "moved: " + maxDiff(moved, movedDirect));

                // no fog attribute: no haze at all; no directional light: no sun
                env.remove(ColorAttribute.Fog);
                env.remove(sun);
                shot(layer, cam, env, target, px);
                assertTrue(!l.hasFog(), "no fog in the environment, none on the plants");
                assertEquals(0f, l.sunIntensity(), 0f, "no directional light, no sun");

                env.add(sun);
                env.set(new ColorAttribute(ColorAttribute.Fog, 0.8f, 0.6f, 0.5f, 1f));
                com.sun.management.ThreadMXBean mx =
                        (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
                long self = Thread.currentThread().getId();
                for (int i = 0; i < 200; i++) { // warm up
                    layer.update(1 / 60f, cam);
                    layer.render(cam, env);
                }
                long least = Long.MAX_VALUE;
                for (int run = 0; run < 4; run++) {
                    long before = mx.getThreadAllocatedBytes(self);
                    for (int i = 0; i < 20; i++) {
                        layer.update(1 / 60f, cam);
                        layer.render(cam, env);
                    }
                    least = Math.min(least, mx.getThreadAllocatedBytes(self) - before);
                }
                assertEquals(0, least, "bytes allocated by 20 frames lit by the environment");
            } finally {
                layer.dispose();
                target.close();
                MemoryUtil.memFree(px);
            }
            GlContexts.debug(owner).check("the host light test");
        }
    }

    /** A marker for the shot without plants: only the clear colour. */
    private static final Environment EMPTY = new Environment();

    /** Draws over a cleared target; with {@code env} {@link #EMPTY} only the clear colour (no plants drawn). */
    private static int[] shot(PlantLayer layer, PerspectiveCamera cam, Environment env, GlFramebuffer target,
                              ByteBuffer px) {
        target.bind();
        org.lwjgl.opengl.GL11C.glClearColor(0.2f, 0.2f, 0.2f, 1f);
        org.lwjgl.opengl.GL11C.glClear(org.lwjgl.opengl.GL11C.GL_COLOR_BUFFER_BIT
                | org.lwjgl.opengl.GL11C.GL_DEPTH_BUFFER_BIT);
        if (env == null) {
            layer.render(cam);
        } else if (env != EMPTY) {
            layer.render(cam, env);
        }
        Pixels.read(W, H, px);
        int[] rgb = new int[W * H];
        for (int i = 0; i < W * H; i++) {
            rgb[i] = (px.get(4 * i) & 255) << 16 | (px.get(4 * i + 1) & 255) << 8 | (px.get(4 * i + 2) & 255);
        }
        return rgb;
    }

    private static int maxDiff(int[] a, int[] b) {
        int m = 0;
        for (int i = 0; i < a.length; i++) {
            for (int s = 0; s <= 16; s += 8) {
                m = Math.max(m, Math.abs((a[i] >> s & 255) - (b[i] >> s & 255)));
            }
        }
        return m;
    }

    /** The share of pixels where a channel differs by more than {@code tolerance}. */
    private static double changed(int[] a, int[] b, int tolerance) {
        int n = 0;
        for (int i = 0; i < a.length; i++) {
            for (int s = 0; s <= 16; s += 8) {
                if (Math.abs((a[i] >> s & 255) - (b[i] >> s & 255)) > tolerance) {
                    n++;
                    break;
                }
            }
        }
        return n / (double) a.length;
    }
}
