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
                f.withEnabled(field),
                a.withMode(mode),
                d.seed());
    }

    /**
     * Runs every configuration {@code warm + frames} frames, interleaved, and keeps each one's last
     * {@code frames}. Configuration c is mode {@code modes[c]} with the field {@code fields[c]}, in its
     * own {@link Simulation} on the shared (immutable) world, walking the same camera path from time 0,
     * so frame i of every configuration sees the same camera. The configurations take turns in blocks
     * of {@code block} frames ({@link Turns}), so their ratios (Tables 6 and 7) compare like with like.
     *
     * @param block    frames per turn, &gt;= 1 (a few for rendered frames; hundreds for simulation-only
     *                 frames, whose state would otherwise leave the caches at every turn)
     * @param gl       the context to render with, or null for simulation only
     * @param renderer the scene's renderer (with gl), or null
     */
    static FrameRun[] measure(SceneDef scene, World world, AnimationMode[] modes, boolean[] fields, int warm,
                              int frames, int block, GlContext gl, SceneRenderer renderer, int width, int height) {
        int n = modes.length;
        FrameRun[] runs = new FrameRun[n];
        Simulation[] sims = new Simulation[n];
        try {
            for (int c = 0; c < n; c++) {
                runs[c] = new FrameRun(frames);
                sims[c] = Simulation.of(world, variant(scene, modes[c], fields[c]), 0);
                sims[c].setLodTransition(scene.render().lodTransition());
            }
            CameraWalk walk = new CameraWalk(scene.camera(), world.terrain().heightfield(), width / (double) height);
            Turns.run(n, warm + frames, block,
                    (c, k) -> frame(sims[c], walk, runs[c], k - warm, frames, gl, renderer, width, height));
        } finally {
            for (Simulation sim : sims) {
                if (sim != null) {
                    sim.close();
                }
            }
        }
        return runs;
    }

    /** One frame of one configuration; recorded at index {@code i} when {@code i >= 0} (else warm-up). */
    private static void frame(Simulation sim, CameraWalk walk, FrameRun r, int i, int frames, GlContext gl,
                              SceneRenderer renderer, int width, int height) {
        ViewCamera cam = walk.at(sim.inspect().time());
        long t0 = System.nanoTime();
        sim.stepFixed(cam);
        Frame frame = sim.latestFrame();
        if (renderer != null) {
            renderer.render(frame, cam, width, height);
            gl.finish();
        }
        long t1 = System.nanoTime();
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
