package org.jecosys.render.ground;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import org.jecosys.math.Progress;
import org.jecosys.render.GlContext;
import org.jecosys.render.GlContext.DebugOutput;
import org.jecosys.render.RenderSettings;
import org.jecosys.render.gl.GlContexts;
import org.jecosys.scene.SceneDef;
import org.jecosys.scene.SceneFiles;
import org.jecosys.sim.World;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * A game's sun that moves a little every frame (a day passing, set through {@code Lighting} each
 * frame) rebuilds the CPU-made sun shadow map only when it has turned by more than a quarter of a
 * degree since the map was made, not at every frame, and on the ground maps' worker thread, not the
 * render thread; the same sun set again rebuilds nothing, and a larger turn rebuilds at once.
 */
class ReshadeTest {
    private static final double AZ = Math.toRadians(120);
    private static final double EL = Math.toRadians(40);

    private static SceneDef def;
    /** C1's world, built once for both tests (a world is immutable). */
    private static World world;

    @BeforeAll
    static void build() throws Exception {
        def = SceneFiles.parse(Path.of("scenes/c1.xml"));
        world = World.build(def.simulationDef(), Path.of("scenes"), 1, Progress.NONE);
    }

    /** C1 with shadows on and the sun at {@link #AZ}, {@link #EL}. */
    private static RenderSettings settings(SceneDef def) {
        RenderSettings settings = RenderSettings.of(def);
        settings.setShadows(0.6f);
        settings.lighting().setSun(AZ, EL);
        return settings;
    }

    @Test
    void aSlowlyTurningSunRebuildsTheShadowMapEverySoOften() throws Exception {
        try (GlContext gl = GlContext.headless(DebugOutput.ON);
             GroundMaps maps = new GroundMaps(GlContexts.tracker(gl), world)) {
            RenderSettings settings = settings(def);
            assertTrue(maps.prepareShadows(settings));
            assertEquals(1, maps.shadowBuilds(), "the first map");
            assertTrue(maps.prepareShadows(settings));
            assertEquals(1, maps.shadowBuilds(), "the same sun: no rebuild");
            // 100 frames of a sun turning 0.01 degrees a frame: 1 degree in all (each frame waits for the
            // worker's map, so that the count does not depend on how fast it is)
            for (int f = 1; f <= 100; f++) {
                settings.lighting().setSun(AZ + Math.toRadians(0.01 * f), EL);
                maps.prepareShadows(settings);
                maps.awaitShadows();
            }
            int builds = maps.shadowBuilds() - 1;
            assertTrue(builds >= 3 && builds <= 5, "rebuilt every quarter of a degree: " + builds + " in 100 frames");
            settings.lighting().setSun(AZ + Math.toRadians(10), EL);
            maps.prepareShadows(settings);
            assertEquals(builds + 2, maps.shadowBuilds(), "a larger turn rebuilds at once");
            assertTrue(!maps.shadowPending(), "nothing left to the worker after a larger turn");
            GlContexts.debug(gl).check("the reshade test");
        }
    }

    /**
     * A small turn (half a degree) is rebuilt on the worker: the frame that sees it keeps the map before,
     * and the map taken in afterwards is exactly the one the render thread would have made.
     */
    @Test
    void aSmallTurnIsRebuiltOnTheWorkerAndComesOutTheSame() throws Exception {
        try (GlContext gl = GlContext.headless(DebugOutput.ON);
             GroundMaps maps = new GroundMaps(GlContexts.tracker(gl), world)) {
            RenderSettings settings = settings(def);
            assertTrue(maps.prepareShadows(settings));
            float[] before = maps.shadow();
            settings.lighting().setSun(AZ + Math.toRadians(0.5), EL);
            assertTrue(maps.prepareShadows(settings));
            assertTrue(maps.shadowPending(), "half a degree goes to the worker");
            assertTrue(maps.shadow() == before, "the frame keeps the map before");
            maps.awaitShadows();
            assertTrue(!maps.shadowPending());
            var l = settings.lighting();
            float[] direct = SunShadow.of(world, maps.grid, l.sunX(), l.sunY(), l.sunZ());
            org.junit.jupiter.api.Assertions.assertArrayEquals(direct, maps.shadow(), "the worker's map");
            assertTrue(java.util.stream.IntStream.range(0, direct.length).anyMatch(i -> direct[i] != before[i]),
                    "the turn moved the shadows");
            GlContexts.debug(gl).check("the reshade test");
        }
    }
}
