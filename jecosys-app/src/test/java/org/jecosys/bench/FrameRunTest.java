package org.jecosys.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import org.jecosys.anim.AnimationMode;
import org.jecosys.math.Progress;
import org.jecosys.scene.SceneDef;
import org.jecosys.scene.SceneFiles;
import org.jecosys.sim.World;
import org.junit.jupiter.api.Test;

/** Configurations measured in turns: each runs all its frames, in lockstep with the same camera walk. */
class FrameRunTest {
    @Test
    void configurationsTakingTurnsEachRunAllTheirFramesOnTheSameWalk() throws Exception {
        SceneDef scene = SceneFiles.parse(Path.of("scenes", "c1.xml"));
        World world = World.build(scene.simulationDef(), Path.of("scenes"), 2, Progress.NONE);
        AnimationMode[] modes = {AnimationMode.CONSTRAINT, AnimationMode.STATIC, AnimationMode.CONSTRAINT};
        boolean[] fields = {true, true, true};
        // 7 frames after 2 warm-up in turns of 3: the last turn of every configuration is a partial one
        FrameRun[] runs = FrameRun.measure(scene, world, modes, fields, 2, 7, 3, null, null, 1280, 720);
        assertEquals(3, runs.length);
        for (FrameRun r : runs) {
            assertEquals(7, r.frameMs.length);
            for (double ms : r.frameMs) {
                assertTrue(ms > 0, "every frame was run and timed");
            }
        }
        assertTrue(runs[0].componentsAnimated > 0);
        assertEquals(0, runs[1].componentsAnimated, "a static scene animates nothing");
        // the same configuration twice, in its own simulation each, sees the same frames
        assertEquals(runs[0].componentsAnimated, runs[2].componentsAnimated);
    }
}
