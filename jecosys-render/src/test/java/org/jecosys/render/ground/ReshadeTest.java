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
import org.junit.jupiter.api.Test;

/**
 * A game's sun that moves a little every frame (a day passing, set through {@code Lighting} each
 * frame) rebuilds the CPU-made sun shadow map only when it has turned by more than a quarter of a
 * degree since the map was made, not at every frame; the same sun set again rebuilds nothing, and a
 * larger turn rebuilds at once.
 */
class ReshadeTest {
    @Test
    void aSlowlyTurningSunRebuildsTheShadowMapEverySoOften() throws Exception {
        SceneDef def = SceneFiles.parse(Path.of("scenes/c1.xml"));
        World world = World.build(def.simulationDef(), Path.of("scenes"), 1, Progress.NONE);
        try (GlContext gl = GlContext.headless(DebugOutput.ON);
             GroundMaps maps = new GroundMaps(GlContexts.tracker(gl), world)) {
            RenderSettings settings = RenderSettings.of(def);
            settings.setShadows(0.6f);
            double az = Math.toRadians(120);
            double el = Math.toRadians(40);
            settings.lighting().setSun(az, el);
            assertTrue(maps.prepareShadows(settings));
            assertEquals(1, maps.shadowBuilds(), "the first map");
            assertTrue(maps.prepareShadows(settings));
            assertEquals(1, maps.shadowBuilds(), "the same sun: no rebuild");
            // 100 frames of a sun turning 0.01 degrees a frame: 1 degree in all
            for (int f = 1; f <= 100; f++) {
                settings.lighting().setSun(az + Math.toRadians(0.01 * f), el);
                maps.prepareShadows(settings);
            }
            int builds = maps.shadowBuilds() - 1;
            assertTrue(builds >= 3 && builds <= 5, "rebuilt every quarter of a degree: " + builds + " in 100 frames");
            settings.lighting().setSun(az + Math.toRadians(10), el);
            maps.prepareShadows(settings);
            assertEquals(builds + 2, maps.shadowBuilds(), "a larger turn rebuilds at once");
            GlContexts.debug(gl).check("the reshade test");
        }
    }
}
