package org.jecosys.sim;

import org.joml.FrustumIntersection;

import org.jecosys.anim.AnimationMode;
import org.jecosys.anim.AnimationState;
import org.jecosys.anim.AnimationStep;
import org.jecosys.math.Rng;

/**
 * The per-chunk work of {@link Simulation}'s fixed step, run by the workers: the fixed chunks of
 * plants (about {@code chunkComponents} components each), one random stream per chunk, and the
 * animation of a chunk into the back frame. {@link #prepare} sets one step's inputs on the stepping
 * thread before the pool starts (the workers see them through the pool's volatile generation);
 * {@link #runChunk} touches only its chunk's plants and components. Build time allocates; nothing
 * after.
 */
final class ChunkAnimator implements WorkerPool.ChunkTask {
    private final AnimationState state;
    private final FieldSampler sampler;
    private final float[][] windX;
    private final float[][] windZ;
    private final boolean[][] visible;
    private final double[][] eye;
    private final int[] chunkFirstPlant;
    private final int[] chunkCount;
    private final boolean[] chunkAtRest;
    private final DrawDecision draw;
    private final FrustumIntersection[] frustum;
    /**
     * framePackedVersion[i][p]: the AnimationState.version of plant p whose deviations frame i holds
     * (-1: none). Plants out of view keep their version, so their states are copied once per frame
     * buffer, not every step, and stay current for any view that draws them. Each entry is touched
     * only by the worker running that plant's chunk in a step.
     */
    private final long[][] framePackedVersion;
    private final Rng[] chunkRng;
    /** Per chunk, the holder of its animate inputs (refilled each step; never two chunks' at once). */
    private final AnimationStep[] chunkStep;
    /** Per chunk the box round its plants' bases ({@link DrawDecision#baseBoxes}). */
    private final float[] chunkBox;
    /** Per chunk, one byte per species: the draw decision's scratch ({@link DrawDecision#decide}). */
    private final byte[] chunkLevels;
    /** Per chunk, the inputs of its draw decision (refilled each step). */
    private final RangeDecision[] chunkRange;

    // read by the workers during a step (published by the pool's volatile generation)
    private AnimationMode stepMode;
    private Frame stepFrame;
    private int stepFrameIndex;
    private int stepBuffer;
    private long stepNumber;
    private double stepEnd;
    private boolean stamp;

    /**
     * Cuts the plants into chunks. Build time; allocates.
     *
     * @param first   per plant its first component, plus the total at the end
     * @param sampler the field's buffers: wind, visibility, views, frustum (shared with the simulation,
     *                read here)
     * @param seed    the animation seed of the chunks' random streams
     */
    ChunkAnimator(AnimationState state, int[] first, int plants, int chunkComponents, FieldSampler sampler,
                  long seed, DrawDecision draw) {
        this.state = state;
        this.sampler = sampler;
        this.draw = draw;
        this.frustum = sampler.frustum;
        this.windX = sampler.windX;
        this.windZ = sampler.windZ;
        this.visible = sampler.visible;
        this.eye = sampler.eye;
        chunkFirstPlant = chunks(first, plants, chunkComponents);
        int chunks = chunkFirstPlant.length - 1;
        chunkCount = new int[chunks];
        chunkAtRest = new boolean[chunks];
        framePackedVersion = new long[3][plants];
        chunkRng = new Rng[chunks];
        chunkStep = new AnimationStep[chunks];
        chunkBox = draw.baseBoxes(chunkFirstPlant);
        chunkLevels = new byte[chunks * draw.species()];
        chunkRange = new RangeDecision[chunks];
        for (int c = 0; c < chunks; c++) {
            chunkRange[c] = draw.range();
        }
        for (int c = 0; c < chunks; c++) {
            chunkRng[c] = Rng.forStream(seed, c);
            chunkStep[c] = new AnimationStep().bounds(chunkBox, 6 * c);
        }
    }

    private static int[] chunks(int[] first, int plants, int chunkComponents) {
        int n = 0;
        int[] tmp = new int[plants + 2];
        tmp[n++] = 0;
        int start = 0;
        for (int p = 0; p < plants; p++) {
            if (first[p + 1] - first[start] >= chunkComponents) {
                tmp[n++] = p + 1;
                start = p + 1;
            }
        }
        if (tmp[n - 1] != plants) {
            tmp[n++] = plants;
        }
        return java.util.Arrays.copyOf(tmp, n);
    }

    /** Number of chunks. */
    int chunks() {
        return chunkCount.length;
    }

    /** Components animated in the last step, over all chunks. Stepping thread, after the pool's await. */
    int animated() {
        int animated = 0;
        for (int c = 0; c < chunkCount.length; c++) {
            animated += chunkCount[c];
        }
        return animated;
    }

    /**
     * Sets the inputs of the next step; stepping thread, before the pool starts. No allocation.
     *
     * @param steps fixed steps run before this one
     * @param end   the simulation time at the end of this step, seconds
     * @param stamp whether to stamp every component of the frame with its number (tests)
     */
    void prepare(AnimationMode mode, int buffer, Frame frame, int frameIndex, long steps,
                 double end, boolean stamp) {
        stepEnd = end;
        stepMode = mode;
        stepBuffer = buffer;
        stepFrame = frame;
        stepFrameIndex = frameIndex;
        stepNumber = steps;
        this.stamp = stamp;
    }

    /** The work of one chunk, run by a worker. */
    @Override
    public void runChunk(int chunk, int worker) {
        int p0 = chunkFirstPlant[chunk];
        int p1 = chunkFirstPlant[chunk + 1];
        AnimationMode m = stepMode;
        boolean reset = false;
        if (m == AnimationMode.STATIC) {
            if (!chunkAtRest[chunk]) {
                state.resetToRest(p0, p1);
                chunkAtRest[chunk] = true;
                reset = true;
            }
        } else {
            chunkAtRest[chunk] = false;
        }
        int b = stepBuffer;
        double[] e = eye[b];
        Frame f = stepFrame;
        int c0 = state.firstComponent(p0);
        int c1 = state.firstComponent(p1);
        FieldSampler fs = sampler;
        AnimationStep in = chunkStep[chunk].set(m, windX[b], windZ[b], visible[b])
                .views(fs.viewCount[b], fs.viewX[b], fs.viewY[b], fs.viewZ[b], fs.scale2[b], fs.fixed2[b])
                .rng(chunkRng[chunk]).time(stepEnd)
                .pushes(fs.pushX == null ? null : fs.pushX[b], fs.pushZ == null ? null : fs.pushZ[b]);
        // the frame holds deviations only: poses and azimuths are computed from them where they are
        // read (Frame.poseCoord, the renderer's resolve pass), so the step writes no per-component output
        chunkCount[chunk] = state.animate(p0, p1, in);
        System.arraycopy(visible[b], p0, f.plantVisible, p0, p1 - p0);
        state.copyLevels(p0, p1, f.plantLevel);
        if (stamp) {
            float n = (float) ((stepNumber + 1) % 1_000_000);
            for (int c = c0; c < c1; c++) {
                f.setDeviation(c, n, -n);
            }
            java.util.Arrays.fill(framePackedVersion[stepFrameIndex], p0, p1, -1L);
        } else {
            packChanged(f, framePackedVersion[stepFrameIndex], p0, p1, reset);
        }
        float[] box = chunkBox;
        int o = 6 * chunk;
        boolean inside = frustum[b].intersectAab(box[o], box[o + 1], box[o + 2], box[o + 3], box[o + 4], box[o + 5])
                == FrustumIntersection.INSIDE;
        RangeDecision range = chunkRange[chunk];
        range.setVisible(visible[b]);
        range.setEye(e[0], e[1], e[2], fs.scale2[b][0], fs.fixed2[b][0]);
        range.setFrustum(frustum[b], !inside);
        draw.decide(range, p0, p1, box, o, chunkLevels, chunk * draw.species(), f);
    }

    /**
     * Copies the deviations (the render states) of the chunk's plants whose state changed since this
     * frame buffer last received it (every animated plant, and a plant seen last in another frame
     * buffer), in runs of consecutive plants; of every plant when {@code all}. So every plant's render
     * state is current in every published frame, whichever view draws it. No allocation.
     */
    private void packChanged(Frame f, long[] packed, int p0, int p1, boolean all) {
        int p = p0;
        while (p < p1) {
            if (!all && packed[p] == state.version(p)) {
                p++;
                continue;
            }
            int start = p;
            while (p < p1 && (all || packed[p] != state.version(p))) {
                packed[p] = state.version(p);
                p++;
            }
            state.copyDeviations(state.firstComponent(start), state.firstComponent(p), f.renderStateLongs);
        }
    }
}
