package org.jecosys.plant;

import org.jecosys.math.Require;

/**
 * Render-ready mesh of one component at one level of detail (paper §4.1: "a subset of the
 * pre-computed vectors for each level of detail ... triangles or lines"): vertex references into
 * the component's {@link PoseTable} and an index list. A vertex is
 * {@code p[point] + a s[point] + b n[point]} of the pose the renderer blends.
 *
 * <h2>Point subset</h2>
 * A level using {@code n} of the skeleton's {@code S} segments uses points
 * {@code q_i = round(i S / n)}, {@code i = 0..n} (base and tip always kept); {@code n = 0} draws
 * nothing. A {@link ComponentShape#FAN} uses only the base and the tip point.
 *
 * <h2>Generation rules (exact primitive counts)</h2>
 * <table>
 * <caption>primitives of one component using n segments</caption>
 * <tr><th>shape</th><th>triangles</th><th>lines</th></tr>
 * <tr><td>STRIP, blunt (tipWidth &gt; 0)</td><td>2n: two per quad between q_i and q_(i+1)</td>
 *     <td>2n + 1: left edge n, right edge n, tip edge 1 (open at the base)</td></tr>
 * <tr><td>STRIP, pointed (tipWidth = 0)</td><td>2n - 1: the last quad is one triangle to the tip</td>
 *     <td>2n: left edge n, right edge n, meeting at the tip</td></tr>
 * <tr><td>FAN</td><td>n: a cone (a disc when short) from the base point to a rim of n vertices
 *     around the tip point, radius tipWidth / 2, in the tip's side/normal plane</td>
 *     <td>n: the closed rim polygon</td></tr>
 * </table>
 * STRIP vertices: {@code a = -1} (left) and {@code +1} (right) at each used point, {@code b = 0};
 * a pointed tip is one vertex {@code a = b = 0}. FAN: the base {@code a = b = 0}, rim vertex
 * {@code j} at {@code a = cos(2 pi j / n)}, {@code b = sin(2 pi j / n)}. Triangles are not
 * oriented consistently (draw both faces); lines are index pairs. A FAN needs {@code n >= 3} to
 * enclose an area; with 1 or 2 it yields the same count of degenerate (zero-area or zero-length)
 * primitives.
 *
 * <p>Immutable after construction; any thread; accessors do not allocate.
 */
public final class ComponentMesh {
    private final Primitive primitive;
    private final int[] vertexPoint;
    private final float[] vertexA;
    private final float[] vertexB;
    private final int[] indices;

    private ComponentMesh(Primitive primitive, int[] vertexPoint, float[] vertexA, float[] vertexB, int[] indices) {
        this.primitive = primitive;
        this.vertexPoint = vertexPoint;
        this.vertexA = vertexA;
        this.vertexB = vertexB;
        this.indices = indices;
    }

    /**
     * Primitives of one component by the rules above.
     *
     * @param shape     strip or fan
     * @param pointed   whether the component's tip width is 0 (strips only)
     * @param n         segments used, &gt;= 0
     * @param primitive triangles or lines
     * @return the count from the table above; 0 when {@code n = 0}
     */
    public static int primitiveCount(ComponentShape shape, boolean pointed, int n, Primitive primitive) {
        Require.nonNull("shape", shape);
        Require.nonNull("primitive", primitive);
        Require.range("n", n, 0, 32);
        if (n == 0) {
            return 0;
        }
        if (shape == ComponentShape.FAN) {
            return n;
        }
        if (primitive == Primitive.TRIANGLES) {
            return pointed ? 2 * n - 1 : 2 * n;
        }
        return pointed ? 2 * n : 2 * n + 1;
    }

    /**
     * The skeleton points a level uses (see the class comment). Build time; allocates the result.
     *
     * @param shape    strip or fan
     * @param segments skeleton segments S, in [1, 32]
     * @param n        segments used, in [0, S]
     * @return ascending point indices; empty when {@code n = 0}
     */
    public static int[] lodPoints(ComponentShape shape, int segments, int n) {
        Require.range("segments", segments, 1, 32);
        Require.range("n", n, 0, segments);
        if (n == 0) {
            return new int[0];
        }
        if (shape == ComponentShape.FAN) {
            return new int[] {0, segments};
        }
        int[] q = new int[n + 1];
        for (int i = 0; i <= n; i++) {
            q[i] = (int) Math.round(i * (double) segments / n);
        }
        return q;
    }

    /**
     * Builds the mesh of one component type at one level. Build time; allocates.
     *
     * @param shape     strip or fan
     * @param pointed   whether the tip width is 0 (strips only)
     * @param segments  skeleton segments S, in [1, 32]
     * @param n         segments used, in [0, S]
     * @param primitive triangles or lines
     * @return the mesh; empty when {@code n = 0}
     */
    public static ComponentMesh build(ComponentShape shape, boolean pointed, int segments, int n, Primitive primitive) {
        Require.nonNull("shape", shape);
        Require.nonNull("primitive", primitive);
        int[] q = lodPoints(shape, segments, n);
        int count = primitiveCount(shape, pointed, n, primitive);
        int[] idx = new int[count * (primitive == Primitive.TRIANGLES ? 3 : 2)];
        if (n == 0) {
            return new ComponentMesh(primitive, new int[0], new float[0], new float[0], idx);
        }
        if (shape == ComponentShape.FAN) {
            int[] vp = new int[n + 1];
            float[] va = new float[n + 1];
            float[] vb = new float[n + 1];
            vp[0] = 0;
            for (int j = 0; j < n; j++) {
                double ang = 2 * Math.PI * j / n;
                vp[j + 1] = segments;
                va[j + 1] = (float) Math.cos(ang);
                vb[j + 1] = (float) Math.sin(ang);
            }
            int w = 0;
            for (int j = 0; j < n; j++) {
                int r0 = 1 + j;
                int r1 = 1 + (j + 1) % n;
                if (primitive == Primitive.TRIANGLES) {
                    idx[w++] = 0;
                    idx[w++] = r0;
                    idx[w++] = r1;
                } else {
                    idx[w++] = r0;
                    idx[w++] = r1;
                }
            }
            return new ComponentMesh(primitive, vp, va, vb, idx);
        }
        // STRIP: left vertex 2i, right vertex 2i+1 for i < n (or <= n when blunt); pointed tip last
        int pairs = pointed ? n : n + 1;
        int vCount = 2 * pairs + (pointed ? 1 : 0);
        int[] vp = new int[vCount];
        float[] va = new float[vCount];
        float[] vb = new float[vCount];
        for (int i = 0; i < pairs; i++) {
            vp[2 * i] = q[i];
            va[2 * i] = -1f;
            vp[2 * i + 1] = q[i];
            va[2 * i + 1] = 1f;
        }
        int tip = pointed ? vCount - 1 : -1;
        if (pointed) {
            vp[tip] = q[n];
        }
        int w = 0;
        if (primitive == Primitive.TRIANGLES) {
            for (int i = 0; i < n; i++) {
                int l0 = 2 * i;
                int r0 = 2 * i + 1;
                if (pointed && i == n - 1) {
                    idx[w++] = l0;
                    idx[w++] = r0;
                    idx[w++] = tip;
                } else {
                    idx[w++] = l0;
                    idx[w++] = r0;
                    idx[w++] = r0 + 2;
                    idx[w++] = l0;
                    idx[w++] = r0 + 2;
                    idx[w++] = l0 + 2;
                }
            }
        } else {
            for (int i = 0; i < n; i++) {
                int l0 = 2 * i;
                int r0 = 2 * i + 1;
                boolean last = pointed && i == n - 1;
                idx[w++] = l0;
                idx[w++] = last ? tip : l0 + 2;
                idx[w++] = r0;
                idx[w++] = last ? tip : r0 + 2;
            }
            if (!pointed) {
                idx[w++] = 2 * n;
                idx[w++] = 2 * n + 1;
            }
        }
        return new ComponentMesh(primitive, vp, va, vb, idx);
    }

    /** {@return the primitive: triangles or lines} */
    public Primitive primitive() {
        return primitive;
    }

    /** {@return the number of triangles or line segments in this mesh} */
    public int primitiveCount() {
        return indices.length / (primitive == Primitive.TRIANGLES ? 3 : 2);
    }

    /** {@return the number of vertices in this mesh} */
    public int vertexCount() {
        return vertexPoint.length;
    }

    /**
     * {@return the pose-table point index of vertex {@code v}}
     *
     * @param v vertex index, in [0, vertexCount())
     */
    public int vertexPoint(int v) {
        return vertexPoint[v];
    }

    /**
     * {@return the side-vector coefficient {@code a} of vertex {@code v}, in [-1, 1]}
     *
     * @param v vertex index, in [0, vertexCount())
     */
    public float vertexA(int v) {
        return vertexA[v];
    }

    /**
     * {@return the normal-vector coefficient {@code b} of vertex {@code v}, in [-1, 1]}
     *
     * @param v vertex index, in [0, vertexCount())
     */
    public float vertexB(int v) {
        return vertexB[v];
    }

    /** {@return the index count: 3 per triangle or 2 per line} */
    public int indexCount() {
        return indices.length;
    }

    /**
     * {@return index {@code i}, a vertex of this mesh}
     *
     * @param i position in the index list, in [0, indexCount())
     */
    public int index(int i) {
        return indices[i];
    }
}
