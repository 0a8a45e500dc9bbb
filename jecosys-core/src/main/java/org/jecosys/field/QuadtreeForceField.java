package org.jecosys.field;

import java.util.Arrays;
import org.jecosys.math.Require;
import org.jecosys.math.ViewLod;
import org.jecosys.math.Camera;
import org.jecosys.math.Noise;
import org.jecosys.wind.WindField;
import org.joml.Vector2d;

/**
 * The LOD quadtree force field (paper §3.1) driven by a {@link WindField} (§3.2). One
 * {@link #update} is a depth-first pass over the visible part of the tree: nodes outside the camera
 * frustum are skipped, distant subtrees collapse into one <i>effective</i> node (beyond the i-th
 * {@code lodDistances} entry, i levels), each effective node holding plants evaluates the flows once
 * at its plants' centre of gravity and fits a wind gradient to its neighbours' winds. A plant's wind
 * ({@link #wind}, {@link #gather}) is its node's wind plus the gradient times its offset, plus a
 * per-plant flutter of {@value #EDDY_GAIN} x the flows' eddy speed at {@value #EDDY_FREQUENCY} Hz.
 * Winds are in m/s, each component within +-{@link #MAX_WIND}. The update's steps and the gradient's
 * fit are in docs/model.md, "The LOD quadtree update". Visibility is stamped per node with the
 * update number, so an update costs what the visible nodes cost, not what the world's size would.
 *
 * <p>Threads: see {@link ForceField}. {@code update} and all queries allocate nothing; adding
 * plants allocates only when arrays grow.
 */
public final class QuadtreeForceField implements ForceField {
    private final ForceFieldDef def;
    private final Quadtree tree;
    private final WindField wind;
    /** The views of the last update and their frustum and LOD tests of node boxes. */
    private final FieldViews views;

    private int[] stamp;
    private int[] rep;
    private float[] windX;
    private float[] windZ;
    /** Per effective node, its plants' centre of gravity (metres) and the wind gradient (1/s). */
    private float[] centX;
    private float[] centZ;
    private float[] gradXX;
    private float[] gradXZ;
    private float[] gradZX;
    private float[] gradZZ;
    /** The flutter's amplitude (m/s) and noise coordinate at the last update. */
    private float eddy;
    /** The flutter's noise at the step's time (the same for every plant; {@link Noise.Slice1}). */
    private final Noise.Slice1 eddyNoise = new Noise.Slice1();
    /** The effective nodes of the last update, in visiting order. */
    private int[] effective;
    private int effectiveCount;
    /** The effective nodes' edge neighbours, kept while the cut stays the same. */
    private final EdgeNeighbours neighbours = new EdgeNeighbours();
    private final NodeGradient fit = new NodeGradient();
    private int current;

    private final FieldCounters counters = new FieldCounters();
    private final FieldDebugView debug;
    private final Vector2d tmp = new Vector2d();
    /** Most views one update takes: the camera and {@code MAX_VIEWS - 1} others. */
    public static final int MAX_VIEWS = 9;

    /**
     * An empty field over the terrain's bounds.
     *
     * @param def           settings (split threshold, maximum depth, LOD distances, enabled)
     * @param minX          terrain west edge, metres
     * @param minZ          terrain north edge, metres
     * @param maxX          terrain east edge, metres, &gt; minX
     * @param maxZ          terrain south edge, metres, &gt; minZ
     * @param minY          lowest terrain height, metres
     * @param maxY          highest terrain height (plus plant height if wanted), metres, &gt;= minY
     * @param wind          the flows to evaluate (read at their current time)
     * @param plantCapacity plants to preallocate for, &gt;= 0
     */
    public QuadtreeForceField(ForceFieldDef def, double minX, double minZ, double maxX, double maxZ,
                              double minY, double maxY, WindField wind, int plantCapacity) {
        this.def = Require.nonNull("def", def);
        this.wind = Require.nonNull("wind", wind);
        Require.finite("minY", minY);
        Require.finite("maxY", maxY);
        if (maxY < minY) {
            throw new IllegalArgumentException("maxY must be >= minY, got minY=" + minY + " maxY=" + maxY);
        }
        this.tree = new Quadtree(minX, minZ, maxX, maxZ, def.maxObjectsPerNode(), def.maxDepth(), plantCapacity);
        views = new FieldViews(def, (float) minY, (float) maxY);
        allocNodeState(tree.nodeCapacity());
        debug = new FieldDebugView(this);
    }

    /**
     * A field built by inserting plants {@code 0 .. n-1} at (xs[i], zs[i]) in order. Allocates.
     *
     * @param def  settings (split threshold, maximum depth, LOD distances, enabled)
     * @param minX terrain west edge, metres
     * @param minZ terrain north edge, metres
     * @param maxX terrain east edge, metres, &gt; minX
     * @param maxZ terrain south edge, metres, &gt; minZ
     * @param minY lowest terrain height, metres
     * @param maxY highest terrain height plus the tallest plant, metres, &gt;= minY
     * @param wind the flows to evaluate
     * @param xs   plant X, metres, one per plant, inside the bounds
     * @param zs   plant Z, metres, same length as xs
     * @return the field with n plants; call {@link #update} before reading winds
     * @throws IllegalArgumentException when the arrays differ in length or a bound or plant is invalid
     */
    public static QuadtreeForceField build(ForceFieldDef def, double minX, double minZ, double maxX, double maxZ,
                                           double minY, double maxY, WindField wind, float[] xs, float[] zs) {
        Require.nonNull("xs", xs);
        Require.nonNull("zs", zs);
        if (xs.length != zs.length) {
            throw new IllegalArgumentException("xs and zs must have the same length, got " + xs.length + " and "
                    + zs.length);
        }
        QuadtreeForceField f = new QuadtreeForceField(def, minX, minZ, maxX, maxZ, minY, maxY, wind, xs.length);
        for (int i = 0; i < xs.length; i++) {
            f.addPlant(xs[i], zs[i]);
        }
        return f;
    }

    private void allocNodeState(int n) {
        stamp = stamp == null ? new int[n] : Arrays.copyOf(stamp, n);
        rep = rep == null ? new int[n] : Arrays.copyOf(rep, n);
        windX = windX == null ? new float[n] : Arrays.copyOf(windX, n);
        windZ = windZ == null ? new float[n] : Arrays.copyOf(windZ, n);
        centX = centX == null ? new float[n] : Arrays.copyOf(centX, n);
        centZ = centZ == null ? new float[n] : Arrays.copyOf(centZ, n);
        gradXX = gradXX == null ? new float[n] : Arrays.copyOf(gradXX, n);
        gradXZ = gradXZ == null ? new float[n] : Arrays.copyOf(gradXZ, n);
        gradZX = gradZX == null ? new float[n] : Arrays.copyOf(gradZX, n);
        gradZZ = gradZZ == null ? new float[n] : Arrays.copyOf(gradZZ, n);
        effective = effective == null ? new int[n] : Arrays.copyOf(effective, n);
        neighbours.resize(n);
    }

    /** Largest wind component stored, m/s: far beyond any real wind (a faster flow is capped). */
    public static final float MAX_WIND = 1e9f;
    /** Frequency of the per-plant flutter (unresolved eddies), Hz. */
    public static final double EDDY_FREQUENCY = 1.5;
    /** Flutter amplitude per m/s of the flows' eddy speed (dimensionless). */
    public static final double EDDY_GAIN = 0.5;

    /** {@return the settings} */
    public ForceFieldDef def() {
        return def;
    }

    /** {@return the quadtree (read-only use: structure queries)} */
    public Quadtree tree() {
        return tree;
    }

    /** {@return the flows this field evaluates} */
    public WindField windField() {
        return wind;
    }

    @Override
    public int addPlant(double x, double z) {
        int p = tree.insert(x, z);
        ensureNodeState();
        neighbours.invalidate(); // node bounds may have changed
        return p;
    }

    @Override
    public void movePlant(int plant, double x, double z) {
        tree.move(plant, x, z);
        ensureNodeState();
        neighbours.invalidate();
    }

    private void ensureNodeState() {
        if (stamp.length < tree.nodeCapacity()) {
            allocNodeState(tree.nodeCapacity());
        }
    }

    @Override
    public int plantCount() {
        return tree.plantCount();
    }

    @Override
    public void update(Camera camera) {
        update(camera, NO_VIEWS, 0);
    }

    private static final Camera[] NO_VIEWS = {};

    /**
     * Recomputes visibility, LOD and the wind of every effective node for several views at once: a node
     * is visible when any view's frustum meets it (or it holds any eye), and a node collapses into an
     * ancestor only as far as every view allows, each view's distances measured by projected size
     * ({@link ViewLod}: through the lens {@link ForceFieldDef#lodFovY()}). With no other view this is
     * {@link #update(Camera)}. No allocation.
     *
     * @param camera the main view
     * @param others further views (a second player, a minimap, a shadow map's light), the first
     *               {@code count} of them read
     * @param count  how many of {@code others}, in [0, {@link #MAX_VIEWS} - 1]
     */
    @Override
    public void update(Camera camera, Camera[] others, int count) {
        Require.nonNull("camera", camera);
        Require.range("count", count, 0, MAX_VIEWS - 1);
        ensureNodeState();
        if (current == Integer.MAX_VALUE) {
            Arrays.fill(stamp, 0);
            current = 0;
        }
        current++;
        views.set(camera, others, count);
        FieldCounters c = counters;
        c.nodes = tree.nodeCount();
        c.leaves = tree.leafCount();
        c.visibleNodes = 0;
        c.visibleLeaves = 0;
        c.effectiveNodes = 0;
        c.flowEvaluations = 0;
        effectiveCount = 0;
        neighbours.begin();
        eddyNoise.at(wind.time() * EDDY_FREQUENCY);
        eddy = def.enabled() ? finite(EDDY_GAIN * wind.eddySpeed()) : 0f;
        visit(0, 0, -1);
        boolean sameCut = neighbours.keep();
        for (int i = 0; i < effectiveCount; i++) {
            gradient(effective[i], 4 * i, sameCut);
        }
    }

    /**
     * @param inside bit v set: node n's parent lies wholly inside view v's frustum (so n does too)
     */
    private void visit(int n, int inside, int r) {
        Quadtree t = tree;
        if (inside == 0) {
            inside = views.cover(t, n);
            if (inside < 0) {
                return;
            }
        }
        stamp[n] = current;
        counters.visibleNodes++;
        if (r < 0) {
            neighbours.visited(n);
        }
        int fc = t.firstChild[n];
        if (r < 0 && (fc < 0 || views.collapses(t, n))) {
            r = n;
            counters.effectiveNodes++;
            effective[effectiveCount++] = n;
            evaluate(n);
        }
        rep[n] = r;
        if (fc < 0) {
            counters.visibleLeaves++;
            return;
        }
        visit(fc, inside, r);
        visit(fc + 1, inside, r);
        visit(fc + 2, inside, r);
        visit(fc + 3, inside, r);
    }

    private void evaluate(int n) {
        Quadtree t = tree;
        int cnt = t.count[n];
        centX[n] = (float) t.centroidX(n);
        centZ[n] = (float) t.centroidZ(n);
        gradXX[n] = 0;
        gradXZ[n] = 0;
        gradZX[n] = 0;
        gradZZ[n] = 0;
        if (!def.enabled() || cnt == 0) {
            windX[n] = 0;
            windZ[n] = 0;
            return;
        }
        wind.velocity(t.sumX[n] / cnt, t.sumZ[n] / cnt, tmp);
        windX[n] = finite(tmp.x);
        windZ[n] = finite(tmp.y);
        counters.flowEvaluations++;
    }

    private static float finite(double v) {
        return v == v ? (float) Math.max(-MAX_WIND, Math.min(MAX_WIND, v)) : 0f;
    }

    /**
     * Fits effective node n's wind gradient to its edge neighbours and weighs it by how well it
     * predicts them ({@link NodeGradient}; see the class comment). No flow evaluation; no allocation.
     */
    private void gradient(int n, int o, boolean sameCut) {
        Quadtree t = tree;
        if (!def.enabled() || t.count[n] == 0) {
            return;
        }
        float cx = centX[n];
        float cz = centZ[n];
        int[] probe = neighbours.probes();
        if (!sameCut) {
            neighbours.lookUp(t, n, o, cx, cz, stamp, rep, current);
        }
        NodeGradient g = fit;
        g.clear();
        for (int i = 0; i < 4; i++) {
            int m = probe[o + i];
            if (m < 0 || m == n || t.count[m] == 0 || (i > 0 && m == probe[o + i - 1])
                    || (i > 1 && m == probe[o + i - 2]) || (i > 2 && m == probe[o])) {
                continue;
            }
            g.add(centX[m] - cx, centZ[m] - cz, windX[m] - windX[n], windZ[m] - windZ[n]);
        }
        if (g.solve(Math.max(t.maxX[n] - cx, cx - t.minX[n]), Math.max(t.maxZ[n] - cz, cz - t.minZ[n]))) {
            gradXX[n] = (float) g.xx;
            gradXZ[n] = (float) g.xz;
            gradZX[n] = (float) g.zx;
            gradZZ[n] = (float) g.zz;
        }
    }

    /** Makes the next update look every edge neighbour up again (tests: the reuse changes nothing). */
    void forgetNeighbours() {
        neighbours.invalidate();
    }

    /** {@return how many updates reused the edge neighbours of the one before (tests)} */
    long neighbourReuses() {
        return neighbours.reuses();
    }

    /** Whether node n passed the frustum test at the last update. */
    boolean nodeVisible(int n) {
        return stamp[n] == current && current != 0;
    }

    /** The effective node representing visible node n at the last update, or -1. */
    int representative(int n) {
        return nodeVisible(n) ? rep[n] : -1;
    }

    float nodeWindX(int n) {
        int r = representative(n);
        return r < 0 ? 0 : windX[r];
    }

    float nodeWindZ(int n) {
        int r = representative(n);
        return r < 0 ? 0 : windZ[r];
    }

    @Override
    public boolean isVisible(int plant) {
        return nodeVisible(tree.leafOf[checkPlant(plant)]);
    }

    @Override
    public int effectiveNode(int plant) {
        return representative(tree.leafOf[checkPlant(plant)]);
    }

    @Override
    public int leafNode(int plant) {
        return tree.leafOf[checkPlant(plant)];
    }

    @Override
    public int depth(int plant) {
        return tree.depth[tree.leafOf[checkPlant(plant)]];
    }

    @Override
    public Vector2d wind(int plant, Vector2d dest) {
        int r = effectiveNode(plant);
        return r < 0 ? dest.set(0, 0) : dest.set(plantWindX(r, plant), plantWindZ(r, plant));
    }

    /**
     * Wind X at a plant of effective node r: the node's wind plus its gradient times the offset, plus
     * the plant's flutter, m/s.
     */
    private float plantWindX(int r, int plant) {
        float dx = (float) (tree.plantX(plant) - centX[r]);
        float dz = (float) (tree.plantZ(plant) - centZ[r]);
        return windX[r] + gradXX[r] * dx + gradXZ[r] * dz + flutter(plant, FLUTTER_X);
    }

    private float plantWindZ(int r, int plant) {
        float dx = (float) (tree.plantX(plant) - centX[r]);
        float dz = (float) (tree.plantZ(plant) - centZ[r]);
        return windZ[r] + gradZX[r] * dx + gradZZ[r] * dz + flutter(plant, FLUTTER_Z);
    }

    /** One component of a plant's flutter (see the class comment); 0 without turbulence. */
    private float flutter(int plant, long salt) {
        float a = eddy;
        return a == 0 ? 0 : a * (float) eddyNoise.value(salt + plant * 0x9E3779B97F4A7C15L);
    }

    @Override
    public void gather(int first, int n, float[] wx, float[] wz, boolean[] visible) {
        Require.range("first", first, 0, tree.plantCount());
        Require.range("n", n, 0, tree.plantCount() - first);
        if (wx.length < n || wz.length < n || visible.length < n) {
            throw new IllegalArgumentException("windX, windZ and visible must hold n=" + n + " values, got "
                    + wx.length + ", " + wz.length + ", " + visible.length);
        }
        int[] leafOf = tree.leafOf;
        int cur = current;
        // plants come in spatial order, so neighbours share their leaf: its node's wind, gradient and
        // centre of gravity are read once per run of plants of one leaf, and the run's plants in a loop
        // of their own (the arithmetic of plantWindX and plantWindZ, term for term: wind(plant) must
        // give the same bits; without flutter it adds 0, as flutter() returns then)
        double[] px = tree.px;
        double[] pz = tree.pz;
        float eddyNow = eddy;
        int i = 0;
        while (i < n) {
            int leaf = leafOf[first + i];
            int e = i + 1;
            while (e < n && leafOf[first + e] == leaf) {
                e++;
            }
            boolean v = stamp[leaf] == cur && cur != 0;
            java.util.Arrays.fill(visible, i, e, v);
            if (v) {
                int r = rep[leaf];
                float ux = windX[r];
                float uz = windZ[r];
                float xx = gradXX[r];
                float xz = gradXZ[r];
                float zx = gradZX[r];
                float zz = gradZZ[r];
                float cx = centX[r];
                float cz = centZ[r];
                if (eddyNow == 0) {
                    for (int k = i; k < e; k++) {
                        float dx = (float) (px[first + k] - cx);
                        float dz = (float) (pz[first + k] - cz);
                        wx[k] = ux + xx * dx + xz * dz + 0f;
                        wz[k] = uz + zx * dx + zz * dz + 0f;
                    }
                } else {
                    for (int k = i; k < e; k++) {
                        int plant = first + k;
                        float dx = (float) (px[plant] - cx);
                        float dz = (float) (pz[plant] - cz);
                        wx[k] = ux + xx * dx + xz * dz + flutter(plant, FLUTTER_X);
                        wz[k] = uz + zx * dx + zz * dz + flutter(plant, FLUTTER_Z);
                    }
                }
            }
            i = e;
        }
    }

    /** The salts of a plant's flutter along X and along Z. */
    private static final long FLUTTER_X = 0x3C6EF372FE94F82BL;
    private static final long FLUTTER_Z = 0xA54FF53A5F1D36F1L;

    private int checkPlant(int plant) {
        if (plant < 0 || plant >= tree.plantCount()) {
            throw new IllegalArgumentException("plant must be in [0, " + (tree.plantCount() - 1) + "], got " + plant);
        }
        return plant;
    }

    @Override
    public FieldCounters counters() {
        return counters;
    }

    @Override
    public FieldDebugView debugView() {
        return debug;
    }
}
