package org.jecosys.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import org.jecosys.math.Progress;
import org.jecosys.math.ViewCamera;
import org.jecosys.scene.SceneDef;
import org.jecosys.scene.SceneFiles;
import org.jecosys.sim.Simulation;
import org.jecosys.terrain.Heightfield;
import org.jecosys.wind.FlowDef;
import org.jecosys.wind.FlowKind;
import org.jecosys.wind.WindSource;
import org.joml.Vector2d;
import org.junit.jupiter.api.Test;

/** A flow added at the cursor is scaled to the scene, and bends the plants around it at once. */
class FlowDefaultsTest {
    private static Heightfield flat(double size) {
        return Heightfield.of(size, size, 2, new float[4]);
    }

    @Test
    void radiusAndStrengthFollowTheSceneSizeAndItsWind() {
        FlowDefaults meadow = FlowDefaults.of(flat(80), List.of(FlowDef.uniform("b", 2.5, 0)));
        assertEquals(8, meadow.radius(), "a tenth of the 80 m meadow");
        assertEquals(4, meadow.targetSpeed(), "at least MIN_SPEED");
        FlowDefaults rose = FlowDefaults.of(flat(4), List.of(FlowDef.uniform("b", 1.5, 0),
                FlowDef.builder("g", FlowKind.GUST).strength(2).build()));
        assertEquals(0.4, rose.radius());
        assertEquals(5.3, rose.targetSpeed(), 1e-12, "1.5 x (1.5 + 2) m/s, two digits");
        for (FlowDefaults d : new FlowDefaults[] {meadow, rose}) {
            for (FlowKind k : new FlowKind[] {FlowKind.SOURCE, FlowKind.SINK, FlowKind.VORTEX}) {
                double s = d.strength(k, d.radius());
                FlowDef f = FlowDef.builder("f", k).strength(s).coreRadius(d.coreRadius())
                        .influenceRadius(d.radius()).build();
                double v = WindSource.of(f).velocity(d.radius() / 2, 0, 0, new Vector2d()).length();
                assertEquals(d.targetSpeed(), v, 0.03 * d.targetSpeed(), k + ": the target speed at half the radius");
            }
            assertEquals(d.targetSpeed(), d.strength(FlowKind.UNIFORM, d.radius()));
        }
        // the old default, a 4 m^2/s source, blew 0.4 m/s at 1.5 m; the scaled one on the meadow
        assertTrue(meadow.strength(FlowKind.SOURCE, 8) > 40, "" + meadow.strength(FlowKind.SOURCE, 8));
    }

    @Test
    void aDefaultFlowBendsThePlantsWithinItsRadiusAtOnce() throws Exception {
        SceneDef def = SceneFiles.parse(Path.of("scenes/c1.xml"));
        FlowDefaults d = FlowDefaults.of(Heightfield.of(def.terrain().sizeX(), def.terrain().sizeZ(), 2, new float[4]),
                def.flows());
        float[] without = bend(def, null);
        for (FlowKind k : new FlowKind[] {FlowKind.SOURCE, FlowKind.VORTEX}) {
            FlowDef scaled = FlowDef.builder("f", k).centre(0, 2).strength(d.strength(k, d.radius()))
                    .coreRadius(d.coreRadius()).influenceRadius(d.radius()).build();
            // the viewer's old defaults: strength 4 m^2/s, radius 3 m, core 0.5 m
            FlowDef old = FlowDef.builder("f", k).centre(0, 2).strength(4).influenceRadius(3).build();
            double now = change(without, bend(def, scaled), def);
            double before = change(without, bend(def, old), def);
            assertTrue(now > 1, k + ": plants within the radius bend visibly more, by " + now + " pose steps on average");
            assertTrue(now > 4 * before, k + ": " + now + " pose steps against " + before + " with the old defaults");
        }
    }

    /** Mean absolute change of the pose coordinate of the components of plants within 2 m of (0, 2). */
    private static double change(float[] a, float[] b, SceneDef def) throws Exception {
        double sum = 0;
        int n = 0;
        for (int c = 0; c < a.length; c++) {
            if (!Float.isNaN(a[c])) {
                sum += Math.abs(a[c] - b[c]);
                n++;
            }
        }
        assertTrue(n > 20, "components near the flow: " + n);
        return sum / n;
    }

    /** Pose coordinates after 1 s with an extra flow; NaN for components of plants farther than 2 m from (0, 2). */
    private static float[] bend(SceneDef def, FlowDef extra) throws Exception {
        try (Simulation sim = Simulation.create(def.simulationDef(), Path.of("scenes"), 1, Progress.NONE)) {
            if (extra != null) {
                sim.addFlow(extra);
            }
            // 9 m south of the flow, looking at it (C1's start camera before issue 13 moved it)
            ViewCamera cam = new ViewCamera();
            cam.setPosition(0, 1.7, 11);
            cam.setOrientation(0, Math.toRadians(-12));
            cam.setLens(Math.toRadians(60), 16 / 9.0, 0.1, 500);
            for (int i = 0; i < 60; i++) {
                sim.step(1 / 60.0, cam);
            }
            float[] pose = new float[sim.componentCount()];
            java.util.Arrays.fill(pose, Float.NaN);
            for (int p = 0; p < sim.plantCount(); p++) {
                if (Math.hypot(sim.world().plantX(p), sim.world().plantZ(p) - 2) < 2) {
                    int first = sim.world().firstComponent(p);
                    for (int c = first; c < first + sim.world().componentsOf(p); c++) {
                        pose[c] = sim.latestFrame().poseCoord(c);
                    }
                }
            }
            return pose;
        }
    }
}
