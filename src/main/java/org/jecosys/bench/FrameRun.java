package org.jecosys.bench;

import org.jecosys.anim.AnimationDef;
import org.jecosys.anim.AnimationMode;
import org.jecosys.field.ForceFieldDef;
import org.jecosys.math.ViewCamera;
import org.jecosys.render.GlContext;
import org.jecosys.render.SceneRenderer;
import org.jecosys.scene.SceneDef;
import org.jecosys.sim.CameraWalk;
import org.jecosys.sim.Frame;
import org.jecosys.sim.Simulation;
import org.jecosys.sim.SimulationDef;
import org.jecosys.sim.World;

/**
 * One measured run of a scene in one configuration (animation mode, field on or off): the camera
 * walks the scene's path as the paper's viewer did (section 5.2), one fixed simulation step per
 * frame, optionally rendered. Per frame it records the frame time, the field-update time and what
 * was drawn. One thread (the render thread when rendering).
 */
final class FrameRun {
    final double[] frameMs;
    final double[] fieldMs;
    double triangles;
    double lines;
    double componentsAnimated;

    private FrameRun(int frames) {
        frameMs = new double[frames];
        fieldMs = new double[frames];
    }

    /** The scene's simulation settings with another mode and field switch. */
    static SimulationDef variant(SceneDef scene, AnimationMode mode, boolean field) {
        SimulationDef d = scene.simulationDef();
        AnimationDef a = d.animation();
        ForceFieldDef f = d.field();
        return new SimulationDef(d.terrain(), d.species(), d.distributions(), d.placements(), d.flows(),
                new ForceFieldDef(field, f.maxObjectsPerNode(), f.maxDepth(), f.lodDistances()),
                new AnimationDef(mode, a.fixedStep(), a.maxSubSteps(), a.subIntervals(), a.threads(), a.seed()),
                d.seed());
    }

    /**
     * Runs {@code warm + frames} frames and keeps the last {@code frames}.
     *
     * @param gl       the context to render with, or null for simulation only
     * @param renderer the scene's renderer (with gl), or null
     */
    static FrameRun measure(SceneDef scene, World world, AnimationMode mode, boolean field, int warm, int frames,
                            GlContext gl, SceneRenderer renderer, int width, int height) {
        FrameRun r = new FrameRun(frames);
        try (Simulation sim = Simulation.of(world, variant(scene, mode, field), 0)) {
            CameraWalk walk = new CameraWalk(scene.camera(), world.terrain().heightfield(), width / (double) height);
            for (int k = 0; k < warm + frames; k++) {
                ViewCamera cam = walk.at(sim.time());
                long t0 = System.nanoTime();
                sim.stepFixed(cam);
                Frame frame = sim.latestFrame();
                if (renderer != null) {
                    renderer.render(frame, cam, width, height);
                    gl.finish();
                }
                long t1 = System.nanoTime();
                int i = k - warm;
                if (i >= 0) {
                    r.frameMs[i] = (t1 - t0) / 1e6;
                    r.fieldMs[i] = frame.fieldNanos() / 1e6;
                    r.componentsAnimated += frame.componentsAnimated() / (double) frames;
                    if (renderer != null) {
                        r.triangles += renderer.triangles() / (double) frames;
                        r.lines += renderer.lines() / (double) frames;
                    }
                }
            }
        }
        return r;
    }

    /** Frames per second, one value per frame. */
    double[] fps() {
        double[] f = new double[frameMs.length];
        for (int i = 0; i < f.length; i++) {
            f[i] = 1000.0 / Math.max(1e-6, frameMs[i]);
        }
        return f;
    }

    double fpsMean() {
        return Stats.mean(fps());
    }

    double fpsSd() {
        return Stats.sd(fps());
    }

    /** "mean ± sd" of the frame rate. */
    String fpsText() {
        return pm(fpsMean(), fpsSd());
    }

    static String pm(double mean, double sd) {
        return Table.cell(mean) + " ± " + Table.cell(sd);
    }
}
