package org.jecosys.field;

import java.util.Arrays;
import org.jecosys.math.Require;

/**
 * The quadtree of the LOD force field (paper §3.1.1), over the ground rectangle
 * [minX, maxX] x [minZ, maxZ], in flat arrays indexed by node id and by plant id.
 *
 * <p>Structure: node 0 is the root at depth 0; an internal node's four children are the
 * consecutive ids {@code firstChild .. firstChild + 3}, quadrants in the order (-X,-Z), (+X,-Z),
 * (-X,+Z), (+X,+Z) relative to the node's midpoint (a point on the midline goes to the + side);
 * each child covers exactly a quarter of its parent. A leaf holds its plants in a doubly linked
 * list (head per leaf, next/prev per plant). Per node the tree keeps the number of plants of its
 * subtree and the sums of their X and Z (so the centre of gravity of any node is O(1), paper §3.2)
 * and its height (levels from the node to its deepest leaf).
 *
 * <p>Insertion (§3.1.1): a plant goes down to the leaf containing it; when that leaf already holds
 * {@code maxObjectsPerNode} plants and is above {@code maxDepth}, it splits into four and its plants
 * move to the children, then the new plant continues down. Building is inserting the plants in
 * order, so inserting plant n after a build gives exactly the tree built with plants 0..n.
 * Nodes never merge: moving or removing plants only refines the tree. Node ids are stable.
 *
 * <p>Threads: owned by one thread (the field's); not thread-safe. Queries do not allocate;
 * {@link #insert} and {@link #move} allocate only when the preallocated arrays must grow.
 */
public final class Quadtree {
    private final int maxObjects;
    private final int maxDepth;
    private final float rootMinX;
    private final float rootMinZ;
    private final float rootMaxX;
    private final float rootMaxZ;

    private int nodeCount;
    private int leafCount;
    float[] minX;
    float[] minZ;
    float[] maxX;
    float[] maxZ;
    int[] firstChild;
    int[] parent;
    byte[] depth;
    byte[] height;
    int[] count;
    double[] sumX;
    double[] sumZ;
    private int[] head;

    private int plantCount;
    double[] px;
    double[] pz;
    int[] leafOf;
    private int[] next;
    private int[] prev;

    /**
     * An empty tree (just the root leaf).
     *
     * @param minX              west edge, metres (finite)
     * @param minZ              north edge, metres (finite)
     * @param maxX              east edge, metres, &gt; minX
     * @param maxZ              south edge, metres, &gt; minZ
     * @param maxObjectsPerNode split threshold, &gt;= 1
     * @param maxDepth          deepest level, in [0, 16]
     * @param plantCapacity     plants to preallocate for, &gt;= 0 (more may be inserted; arrays grow)
     */
    public Quadtree(double minX, double minZ, double maxX, double maxZ, int maxObjectsPerNode, int maxDepth,
                    int plantCapacity) {
        Require.finite("minX", minX);
        Require.finite("minZ", minZ);
        Require.finite("maxX", maxX);
        Require.finite("maxZ", maxZ);
        if (!(maxX > minX) || !(maxZ > minZ)) {
            throw new IllegalArgumentException("bounds must satisfy maxX > minX and maxZ > minZ, got x ["
                    + minX + ", " + maxX + "] z [" + minZ + ", " + maxZ + "]");
        }
        this.maxObjects = Require.range("maxObjectsPerNode", maxObjectsPerNode, 1, 1_000_000);
        this.maxDepth = Require.range("maxDepth", maxDepth, 0, 16);
        Require.range("plantCapacity", plantCapacity, 0, Integer.MAX_VALUE / 2);
        this.rootMinX = (float) minX;
        this.rootMinZ = (float) minZ;
        this.rootMaxX = (float) maxX;
        this.rootMaxZ = (float) maxZ;
        int nodes = Math.max(16, (int) Math.min(Integer.MAX_VALUE / 4, 2L * plantCapacity / maxObjects + 5));
        allocNodes(nodes);
        int plants = Math.max(16, plantCapacity);
        px = new double[plants];
        pz = new double[plants];
        leafOf = new int[plants];
        next = new int[plants];
        prev = new int[plants];
        newNode(-1, 0, rootMinX, rootMinZ, rootMaxX, rootMaxZ);
        leafCount = 1;
    }

    private void allocNodes(int n) {
        minX = new float[n];
        minZ = new float[n];
        maxX = new float[n];
        maxZ = new float[n];
        firstChild = new int[n];
        parent = new int[n];
        depth = new byte[n];
        height = new byte[n];
        count = new int[n];
        sumX = new double[n];
        sumZ = new double[n];
        head = new int[n];
    }

    private void growNodes() {
        int n = minX.length * 2;
        minX = Arrays.copyOf(minX, n);
        minZ = Arrays.copyOf(minZ, n);
        maxX = Arrays.copyOf(maxX, n);
        maxZ = Arrays.copyOf(maxZ, n);
        firstChild = Arrays.copyOf(firstChild, n);
        parent = Arrays.copyOf(parent, n);
        depth = Arrays.copyOf(depth, n);
        height = Arrays.copyOf(height, n);
        count = Arrays.copyOf(count, n);
        sumX = Arrays.copyOf(sumX, n);
        sumZ = Arrays.copyOf(sumZ, n);
        head = Arrays.copyOf(head, n);
    }

    private void growPlants() {
        int n = px.length * 2;
        px = Arrays.copyOf(px, n);
        pz = Arrays.copyOf(pz, n);
        leafOf = Arrays.copyOf(leafOf, n);
        next = Arrays.copyOf(next, n);
        prev = Arrays.copyOf(prev, n);
    }

    private int newNode(int par, int d, float x0, float z0, float x1, float z1) {
        if (nodeCount == minX.length) {
            growNodes();
        }
        int n = nodeCount++;
        minX[n] = x0;
        minZ[n] = z0;
        maxX[n] = x1;
        maxZ[n] = z1;
        firstChild[n] = -1;
        parent[n] = par;
        depth[n] = (byte) d;
        height[n] = 0;
        count[n] = 0;
        sumX[n] = 0;
        sumZ[n] = 0;
        head[n] = -1;
        return n;
    }

    /**
     * Inserts a plant at ground point (x, z) (metres, inside the bounds) and returns its id
     * (ids are 0, 1, 2, ... in insertion order). Splits leaves as described in the class comment.
     * Allocates only when arrays must grow.
     *
     * @param x ground X, metres, in [minX, maxX]
     * @param z ground Z, metres, in [minZ, maxZ]
     * @return the new plant's id, {@code plantCount() - 1}
     * @throws IllegalArgumentException when (x, z) is outside the bounds
     */
    public int insert(double x, double z) {
        Require.range("x", x, rootMinX, rootMaxX);
        Require.range("z", z, rootMinZ, rootMaxZ);
        if (plantCount == px.length) {
            growPlants();
        }
        int p = plantCount++;
        px[p] = x;
        pz[p] = z;
        place(p);
        return p;
    }

    /**
     * Moves a plant (a movable object, §3.1.1) to (x, z), metres, clamped into the bounds, and
     * re-locates it in the leaf now containing it (which may split). O(depth). No allocation
     * unless arrays must grow.
     *
     * @param plant plant id, in [0, plantCount())
     * @param x     new ground X, metres (finite; clamped into the bounds)
     * @param z     new ground Z, metres (finite; clamped into the bounds)
     * @throws IllegalArgumentException when the id is out of range or a coordinate is not finite
     */
    public void move(int plant, double x, double z) {
        Require.range("plant", plant, 0, plantCount - 1);
        Require.finite("x", x);
        Require.finite("z", z);
        x = Math.min(Math.max(x, rootMinX), rootMaxX);
        z = Math.min(Math.max(z, rootMinZ), rootMaxZ);
        int leaf = leafOf[plant];
        unlink(plant, leaf);
        for (int n = leaf; n >= 0; n = parent[n]) {
            count[n]--;
            sumX[n] -= px[plant];
            sumZ[n] -= pz[plant];
        }
        px[plant] = x;
        pz[plant] = z;
        place(plant);
    }

    private void place(int p) {
        double x = px[p];
        double z = pz[p];
        int n = 0;
        while (true) {
            count[n]++;
            sumX[n] += x;
            sumZ[n] += z;
            if (firstChild[n] >= 0) {
                n = childFor(n, x, z);
                continue;
            }
            if (count[n] - 1 < maxObjects || depth[n] >= maxDepth) {
                link(p, n);
                return;
            }
            split(n);
            n = childFor(n, x, z);
        }
    }

    private void split(int n) {
        float x0 = minX[n];
        float z0 = minZ[n];
        float x1 = maxX[n];
        float z1 = maxZ[n];
        float mx = (x0 + x1) * 0.5f;
        float mz = (z0 + z1) * 0.5f;
        int d = depth[n] + 1;
        int fc = newNode(n, d, x0, z0, mx, mz);
        newNode(n, d, mx, z0, x1, mz);
        newNode(n, d, x0, mz, mx, z1);
        newNode(n, d, mx, mz, x1, z1);
        firstChild[n] = fc;
        leafCount += 3;
        int q = head[n];
        head[n] = -1;
        while (q >= 0) {
            int nq = next[q];
            int c = childFor(n, px[q], pz[q]);
            count[c]++;
            sumX[c] += px[q];
            sumZ[c] += pz[q];
            link(q, c);
            q = nq;
        }
        for (int a = n; a >= 0; a = parent[a]) {
            int h = d - depth[a];
            if (height[a] >= h) {
                break;
            }
            height[a] = (byte) h;
        }
    }

    private int childFor(int n, double x, double z) {
        float mx = (minX[n] + maxX[n]) * 0.5f;
        float mz = (minZ[n] + maxZ[n]) * 0.5f;
        return firstChild[n] + (x >= mx ? 1 : 0) + (z >= mz ? 2 : 0);
    }

    private void link(int p, int leaf) {
        int h = head[leaf];
        next[p] = h;
        prev[p] = -1;
        if (h >= 0) {
            prev[h] = p;
        }
        head[leaf] = p;
        leafOf[p] = leaf;
    }

    private void unlink(int p, int leaf) {
        int a = prev[p];
        int b = next[p];
        if (a >= 0) {
            next[a] = b;
        } else {
            head[leaf] = b;
        }
        if (b >= 0) {
            prev[b] = a;
        }
    }

    /** {@return the number of plants} */
    public int plantCount() {
        return plantCount;
    }

    /** {@return the number of nodes (ids are 0 .. nodeCount - 1; 0 is the root)} */
    public int nodeCount() {
        return nodeCount;
    }

    /** {@return the number of leaves} */
    public int leafCount() {
        return leafCount;
    }

    /** {@return the split threshold (plants per leaf above the maximum depth)} */
    public int maxObjectsPerNode() {
        return maxObjects;
    }

    /** {@return the deepest level a node may have (root 0)} */
    public int maxDepth() {
        return maxDepth;
    }

    /**
     * {@return the leaf node holding a plant}
     *
     * @param plant plant id, in [0, plantCount())
     */
    public int leafOf(int plant) {
        return leafOf[plant];
    }

    /**
     * {@return a plant's X, metres}
     *
     * @param plant plant id, in [0, plantCount())
     */
    public double plantX(int plant) {
        return px[plant];
    }

    /**
     * {@return a plant's Z, metres}
     *
     * @param plant plant id, in [0, plantCount())
     */
    public double plantZ(int plant) {
        return pz[plant];
    }

    /**
     * {@return the first of the four children of a node, or -1 for a leaf}
     *
     * @param node node id, in [0, nodeCount())
     */
    public int firstChild(int node) {
        return firstChild[node];
    }

    /**
     * {@return the parent of a node, or -1 for the root}
     *
     * @param node node id, in [0, nodeCount())
     */
    public int parent(int node) {
        return parent[node];
    }

    /**
     * {@return the depth of a node (root 0)}
     *
     * @param node node id, in [0, nodeCount())
     */
    public int depth(int node) {
        return depth[node];
    }

    /**
     * {@return the height of a node: levels between it and its deepest leaf (0 for a leaf)}
     *
     * @param node node id, in [0, nodeCount())
     */
    public int height(int node) {
        return height[node];
    }

    /**
     * {@return the number of plants in a node's subtree}
     *
     * @param node node id, in [0, nodeCount())
     */
    public int plantsIn(int node) {
        return count[node];
    }

    /**
     * {@return the node's west edge (lowest X), metres}
     *
     * @param node node id, in [0, nodeCount())
     */
    public float minX(int node) {
        return minX[node];
    }

    /**
     * {@return the node's north edge (lowest Z), metres}
     *
     * @param node node id, in [0, nodeCount())
     */
    public float minZ(int node) {
        return minZ[node];
    }

    /**
     * {@return the node's east edge (highest X), metres}
     *
     * @param node node id, in [0, nodeCount())
     */
    public float maxX(int node) {
        return maxX[node];
    }

    /**
     * {@return the node's south edge (highest Z), metres}
     *
     * @param node node id, in [0, nodeCount())
     */
    public float maxZ(int node) {
        return maxZ[node];
    }

    /**
     * {@return the X of the centre of gravity of a node's plants (§3.2), or of the node's centre when empty, metres}
     *
     * @param node node id, in [0, nodeCount())
     */
    public double centroidX(int node) {
        int c = count[node];
        return c > 0 ? sumX[node] / c : (minX[node] + maxX[node]) * 0.5;
    }

    /**
     * {@return the Z of the centre of gravity of a node's plants (§3.2), or of the node's centre when empty, metres}
     *
     * @param node node id, in [0, nodeCount())
     */
    public double centroidZ(int node) {
        int c = count[node];
        return c > 0 ? sumZ[node] / c : (minZ[node] + maxZ[node]) * 0.5;
    }

    /**
     * {@return the first plant of a leaf's list, or -1 when empty} Continue with {@link #nextPlant}.
     *
     * @param leaf a leaf's node id
     */
    public int firstPlant(int leaf) {
        return head[leaf];
    }

    /**
     * {@return the plant after {@code plant} in its leaf's list, or -1 at the end}
     *
     * @param plant plant id, in [0, plantCount())
     */
    public int nextPlant(int plant) {
        return next[plant];
    }

    /** Current node array capacity (for owners that keep parallel per-node arrays). */
    int nodeCapacity() {
        return minX.length;
    }
}
