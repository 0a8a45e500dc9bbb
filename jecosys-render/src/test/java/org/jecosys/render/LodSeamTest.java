package org.jecosys.render;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.jecosys.math.ViewCamera;
import org.jecosys.scene.SceneDef;
import org.jecosys.sim.DrawDecision;
import org.jecosys.sim.Frame;
import org.jecosys.sim.World;
import org.junit.jupiter.api.Test;

/**
 * Issue 13, "Done when": no visible seam at the level-of-detail boundaries: in the default meadow
 * view (960x540), the fine-detail contrast of the vegetation ({@link ImageMetrics#meanAbsLaplacian})
 * changes by at most 1.25x across each level boundary of the grass. Each pixel is placed at the
 * distance of the ground it covers (the depth of the terrain drawn alone); the near side is the band
 * from 2.5 m to 1 m before the boundary (before the transition band of {@link
 * DrawDecision#DEFAULT_TRANSITION}), the far side from the boundary to 1.5 m after it.
 */
class LodSeamTest {
    private static final int W = 960;
    private static final int H = 540;

    @Test
    void fineDetailContrastIsTheSameOnBothSidesOfEachLevelBoundary() {
        SceneDef def = RenderScenes.load("meadow.xml");
        World world = RenderScenes.build(def);
        ViewCamera cam = RenderScenes.camera(def, world, W, H);
        DrawDecision decision = DrawDecision.of(world);
        int grass = 0; // the meadow's first species, grass tuft A
        try (Shots s = new Shots(world, RenderScenes.settings(def), W, H)) {
            Frame frame = TestFrames.rest(world, cam);
            Shots.View v = s.view(frame, cam);
            double[] dist = s.groundDistance(frame, cam);
            List<String> failures = new ArrayList<>();
            for (int l = 0; l + 1 < decision.levels(grass); l++) {
                double edge = decision.edge(grass, l);
                double near = contrast(v, dist, edge - 2.5, edge - 1.0);
                double far = contrast(v, dist, edge, edge + 1.5);
                double ratio = Math.max(near, far) / Math.min(near, far);
                System.out.printf("[look] meadow LOD seam at %.0f m (level %d -> %d): contrast %.1f -> %.1f,"
                        + " ratio %.2f (<= 1.25)%n", edge, l, l + 1, near, far, ratio);
                if (!(ratio <= 1.25)) {
                    failures.add(String.format("%.0f m: %.1f -> %.1f (%.2fx)", edge, near, far, ratio));
                }
            }
            assertTrue(failures.isEmpty(), "fine-detail contrast jumps at level boundaries: " + failures);
        }
    }

    /** Mean absolute Laplacian over the vegetation pixels whose ground lies in [from, to) metres. */
    private static double contrast(Shots.View v, double[] dist, double from, double to) {
        boolean[] band = new boolean[dist.length];
        int n = 0;
        for (int i = 0; i < dist.length; i++) {
            band[i] = v.vegetation()[i] && dist[i] >= from && dist[i] < to;
            if (band[i]) {
                n++;
            }
        }
        assertTrue(n > 200, "only " + n + " vegetation pixels between " + from + " and " + to + " m");
        return ImageMetrics.meanAbsLaplacian(v.full(), band);
    }
}
