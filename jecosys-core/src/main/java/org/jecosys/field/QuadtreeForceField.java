package org.jecosys.field;

import java.util.Arrays;
import org.jecosys.math.Require;
import org.jecosys.math.Camera;
import org.jecosys.wind.WindField;
import org.joml.FrustumIntersection;
import org.joml.Matrix4f;
import org.joml.Vector2d;

/**
 * The LOD quadtree force field (paper §3.1) driven by a {@link WindField} (§3.2).
 *
 * <p><b>Update</b> ({@link #update}), one depth-first pass over the visible part of the tree:
 * <ol>
 * <li>Frustum: each node's box [minX, maxX] x [minY, maxY] x [minZ, maxZ] (terrain height range)
 * is tested against the camera frustum (JOML's plane test, conservative: a box reported outside
 * is outside; a few boxes near frustum corners may be kept). An invisible node's subtree is skipped;
 * a node fully inside passes its descendants without further tests. A node whose XZ rectangle
 * contains the eye is always visible (the plants at the viewer's feet).</li>
 * <li>Distance LOD: for a visible node not yet represented, with d the distance from the eye to the
 * node's box and L = the number of {@code lodDistances} smaller than d ("beyond the i-th distance,
 * i levels collapse"), the node becomes <i>effective</i> when it is a leaf or when its whole
 * subtree is at most L levels deep ({@code height <= L}); its descendants are then represented by
 * it (no leaf is represented by an ancestor more than L levels up). A collapsed full subtree of
 * height h spares 4^h - 1 evaluations.</li>
 * <li>Wind: each effective node holding plants evaluates the sum of all active flows once, at the
 * centre of gravity of the plants of its subtree (§3.2), and stores the velocity (m/s). A field
 * whose def is disabled evaluates nothing and stores zero wind.</li>
 * </ol>
 * Visibility is stamped per node with the update number, so invisible subtrees cost nothing:
 * the update's cost follows the visible nodes, not the size of the world.
 *
 * <p>Threads: see {@link ForceField}. {@code update} and all queries allocate nothing; adding
 * plants allocates only when arrays grow.
 */
public final class QuadtreeForceField implements ForceField {
    private final ForceFieldDef def;
    private final Quadtree tree;
    private final WindField wind;
    private final float minY;
    private final float maxY;
    private final double[] lod2;

    private int[] stamp;
    private int[] rep;
    private float[] windX;
    private float[] windZ;
    private int current;

    private final FieldCounters counters = new FieldCounters();
    private final FieldDebugView debug;
    private final Matrix4f viewProj = new Matrix4f();
    private final FrustumIntersection frustum = new FrustumIntersection();
    private final Vector2d tmp = new Vector2d();
    private float eyeX;
    private float eyeY;
    private float eyeZ;

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
        this.minY = (float) minY;
        this.maxY = (float) maxY;
        this.tree = new Quadtree(minX, minZ, maxX, maxZ, def.maxObjectsPerNode(), def.maxDepth(), plantCapacity);
        lod2 = new double[def.lodDistances().size()];
        for (int i = 0; i < lod2.length; i++) {
            double d = def.lodDistances().get(i);
            lod2[i] = d * d;
        }
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
    }

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
        return p;
    }

    @Override
    public void movePlant(int plant, double x, double z) {
        tree.move(plant, x, z);
        ensureNodeState();
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
        Require.nonNull("camera", camera);
        ensureNodeState();
        if (current == Integer.MAX_VALUE) {
            Arrays.fill(stamp, 0);
            current = 0;
        }
        current++;
        camera.viewProjection(viewProj);
        frustum.set(viewProj, false);
        eyeX = (float) camera.x();
        eyeY = (float) camera.y();
        eyeZ = (float) camera.z();
        FieldCounters c = counters;
        c.nodes = tree.nodeCount();
        c.leaves = tree.leafCount();
        c.visibleNodes = 0;
        c.visibleLeaves = 0;
        c.effectiveNodes = 0;
        c.flowEvaluations = 0;
        visit(0, false, -1);
    }

    private void visit(int n, boolean inside, int r) {
        Quadtree t = tree;
        if (!inside) {
            int res = frustum.intersectAab(t.minX[n], minY, t.minZ[n], t.maxX[n], maxY, t.maxZ[n]);
            if (res == FrustumIntersection.INSIDE) {
                inside = true;
            } else if (res != FrustumIntersection.INTERSECT && !holdsEye(n)) {
                return;
            }
        }
        stamp[n] = current;
        counters.visibleNodes++;
        int fc = t.firstChild[n];
        if (r < 0 && (fc < 0 || (lod2.length > 0 && t.height[n] <= lodLevel(n)))) {
            r = n;
            counters.effectiveNodes++;
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

    private boolean holdsEye(int n) {
        Quadtree t = tree;
        return eyeX >= t.minX[n] && eyeX <= t.maxX[n] && eyeZ >= t.minZ[n] && eyeZ <= t.maxZ[n];
    }

    /** Levels that may collapse at node n: how many LOD distances lie below the eye-to-box distance. */
    private int lodLevel(int n) {
        Quadtree t = tree;
        double dx = Math.max(Math.max(t.minX[n] - eyeX, eyeX - t.maxX[n]), 0);
        double dy = Math.max(Math.max(minY - eyeY, eyeY - maxY), 0);
        double dz = Math.max(Math.max(t.minZ[n] - eyeZ, eyeZ - t.maxZ[n]), 0);
        double d2 = dx * dx + dy * dy + dz * dz;
        int l = 0;
        while (l < lod2.length && d2 > lod2[l]) {
            l++;
        }
        return l;
    }

    private void evaluate(int n) {
        Quadtree t = tree;
        int cnt = t.count[n];
        if (!def.enabled() || cnt == 0) {
            windX[n] = 0;
            windZ[n] = 0;
            return;
        }
        wind.velocity(t.sumX[n] / cnt, t.sumZ[n] / cnt, tmp);
        windX[n] = (float) tmp.x;
        windZ[n] = (float) tmp.y;
        counters.flowEvaluations++;
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
        return r < 0 ? dest.set(0, 0) : dest.set(windX[r], windZ[r]);
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
        for (int i = 0; i < n; i++) {
            int leaf = leafOf[first + i];
            boolean v = stamp[leaf] == cur && cur != 0;
            visible[i] = v;
            if (v) {
                int r = rep[leaf];
                wx[i] = windX[r];
                wz[i] = windZ[r];
            }
        }
    }

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
