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
 * <h2>Meshes from files</h2>
 * {@link #fromMesh} places a glTF mesh's triangles instead ({@link MeshDef}): each vertex has a
 * fractional point (its height along the skeleton), offsets in metres along the unit side, tangent and
 * face normal of the skeleton there, a normal in that frame and texture coordinates
 * ({@link #MESH_FLOATS} per vertex, {@link #meshValue}); see {@link #place} for where it goes.
 *
 * <p>Immutable after construction; any thread; accessors do not allocate.
 */
public final class ComponentMesh {
    /**
     * Floats per vertex of a mesh from a file: the fractional point, the tangent offset c (metres),
     * u and v on the component's image (v up from the image's bottom row), and the normal's side,
     * tangent and face-normal components.
     */
    public static final int MESH_FLOATS = 7;
    /** {@link #meshValue} index: the fractional pose-table point, in [0, segments]. */
    public static final int MESH_POINT = 0;
    /** {@link #meshValue} index: the offset along the skeleton's unit tangent, metres. */
    public static final int MESH_C = 1;
    /** {@link #meshValue} index: u on the component's image. */
    public static final int MESH_U = 2;
    /** {@link #meshValue} index: v on the component's image, 0 at its bottom row. */
    public static final int MESH_V = 3;
    /** {@link #meshValue} index: the first of the normal's three components (side, tangent, face normal). */
    public static final int MESH_NORMAL = 4;

    private final Primitive primitive;
    private final int[] vertexPoint;
    private final float[] vertexA;
    private final float[] vertexB;
    private final int[] indices;
    private final float[] mesh;
    private final boolean ridesParent;

    private ComponentMesh(Primitive primitive, int[] vertexPoint, float[] vertexA, float[] vertexB, int[] indices) {
        this(primitive, vertexPoint, vertexA, vertexB, indices, null, false);
    }

    private ComponentMesh(Primitive primitive, int[] vertexPoint, float[] vertexA, float[] vertexB, int[] indices,
                          float[] mesh, boolean ridesParent) {
        this.primitive = primitive;
        this.vertexPoint = vertexPoint;
        this.vertexA = vertexA;
        this.vertexB = vertexB;
        this.indices = indices;
        this.mesh = mesh;
        this.ridesParent = ridesParent;
    }

    /**
     * {@link #fromMesh(MeshDef, int, double, boolean)} on the component's own skeleton.
     *
     * @param def      the mesh
     * @param segments skeleton segments S, in [1, 32]
     * @param length   skeleton length, metres, &gt; 0
     * @return a triangle mesh whose vertices all refer to points in [0, S]
     * @throws IllegalArgumentException when a bound mesh has no height along +Y
     */
    public static ComponentMesh fromMesh(MeshDef def, int segments, double length) {
        return fromMesh(def, segments, length, false);
    }

    /**
     * The triangles of a glTF mesh placed on a component's skeleton of {@code segments} segments and
     * {@code length} metres. {@link MeshMode#BOUND}: the mesh's height along +Y (lowest to highest
     * vertex) spans the skeleton, so a vertex at height y gets the fractional point
     * {@code segments (y - ymin) / (ymax - ymin)}; its X and Z, scaled by
     * {@code length / (ymax - ymin)} and by the def's scale, are its side and face-normal offsets in
     * metres. {@link MeshMode#RIGID}: every vertex at the tip point, X, Y and Z times the def's scale
     * its side, tangent and face-normal offsets. Texture coordinates are the file's with v turned to
     * run up from the image's bottom row (0 where the file has none). A rigid mesh may ride the tip of
     * the component it is attached to ({@code onParent}: {@code segments} are then the parent's, and the
     * vertices refer to the parent's slot, {@link #ridesParent}), so it turns with that tip (a flower
     * head on its stalk). Build time; allocates.
     *
     * @param def      the mesh
     * @param segments skeleton segments S of the skeleton it follows (the parent's when onParent), in [1, 32]
     * @param length   the component's skeleton length, metres, &gt; 0
     * @param onParent whether a rigid mesh rides its parent's tip (ignored for a bound mesh)
     * @return a triangle mesh whose vertices all refer to points in [0, S]
     * @throws IllegalArgumentException when a bound mesh has no height along +Y
     */
    public static ComponentMesh fromMesh(MeshDef def, int segments, double length, boolean onParent) {
        Require.nonNull("def", def);
        Require.range("segments", segments, 1, 32);
        Require.positive("length", length);
        MeshGeometry g = def.geometry();
        int n = g.vertexCount();
        float ylo = g.bound(1, false);
        float h = g.bound(1, true) - ylo;
        boolean bound = def.mode() == MeshMode.BOUND;
        if (bound && !(h > 1e-9)) {
            throw new IllegalArgumentException("mesh '" + def.path() + "' has no height along +Y to bind along the "
                    + "skeleton");
        }
        double k = bound ? length / h * def.scale() : def.scale();
        int[] vp = new int[n];
        float[] va = new float[n];
        float[] vb = new float[n];
        float[] m = new float[MESH_FLOATS * n];
        for (int v = 0; v < n; v++) {
            float point = bound ? (float) Math.min(segments, Math.max(0, segments * (g.position(v, 1) - ylo) / h))
                    : segments;
            vp[v] = (int) Math.floor(point);
            va[v] = (float) (g.position(v, 0) * k);
            vb[v] = (float) (g.position(v, 2) * k);
            int o = MESH_FLOATS * v;
            m[o + MESH_POINT] = point;
            m[o + MESH_C] = bound ? 0f : (float) (g.position(v, 1) * k);
            m[o + MESH_U] = g.hasUvs() ? g.uv(v, 0) : 0f;
            m[o + MESH_V] = g.hasUvs() ? 1f - g.uv(v, 1) : 0f;
            for (int i = 0; i < 3; i++) {
                m[o + MESH_NORMAL + i] = g.normal(v, i);
            }
        }
        int[] idx = new int[3 * g.triangleCount()];
        for (int i = 0; i < idx.length; i++) {
            idx[i] = g.index(i);
        }
        return new ComponentMesh(Primitive.TRIANGLES, vp, va, vb, idx, m, onParent && !bound);
    }

    /**
     * Where vertex {@code v} of a mesh from a file lies in the component's frame, in pose {@code pose}
     * of {@code table} (the placement the plant shader does, on the CPU): with {@code i0} the point
     * below its fractional point {@code q} (at most S - 1) and {@code f = q - i0}, the position
     * {@code mix(p[i0], p[i0+1], f)}, the unit tangent along {@code p[i0+1] - p[i0]}, the unit side
     * {@code mix(s[i0], s[i0+1], f)} (leaning to {@code s[i0]} where the tip's width is 0) made normal
     * to the tangent, the face normal tangent x side; plus a side + c tangent + b normal (the shader then
     * turns a flower part toward the viewer about that point, as it turns petals). No allocation.
     *
     * @param table the component's pose table
     * @param pose  pose, in [0, table.poses())
     * @param v     a vertex of this mesh, which must be from a file
     * @param out   receives x, y, z, metres, in the component's frame
     * @throws IllegalStateException when this mesh is not from a file
     */
    public void place(PoseTable table, int pose, int v, float[] out) {
        if (mesh == null) {
            throw new IllegalStateException("not a mesh from a file");
        }
        float q = mesh[MESH_FLOATS * v + MESH_POINT];
        int i0 = Math.min((int) Math.floor(q), table.points() - 2);
        float f = q - i0;
        int r0 = table.offset(pose, i0);
        int r1 = table.offset(pose, i0 + 1);
        double tx = table.get(r1) - table.get(r0);
        double ty = table.get(r1 + 1) - table.get(r0 + 1);
        double tz = table.get(r1 + 2) - table.get(r0 + 2);
        double tl = Math.sqrt(tx * tx + ty * ty + tz * tz);
        tx /= tl;
        ty /= tl;
        tz /= tl;
        double w0 = 1 - f + 1e-3;
        double sx = table.get(r0 + 3) * w0 + table.get(r1 + 3) * f;
        double sy = table.get(r0 + 4) * w0 + table.get(r1 + 4) * f;
        double sz = table.get(r0 + 5) * w0 + table.get(r1 + 5) * f;
        double d = sx * tx + sy * ty + sz * tz;
        sx -= d * tx;
        sy -= d * ty;
        sz -= d * tz;
        double sl = Math.sqrt(sx * sx + sy * sy + sz * sz);
        sx /= sl;
        sy /= sl;
        sz /= sl;
        double nx = ty * sz - tz * sy;
        double ny = tz * sx - tx * sz;
        double nz = tx * sy - ty * sx;
        double a = vertexA[v];
        double b = vertexB[v];
        double c = mesh[MESH_FLOATS * v + MESH_C];
        out[0] = (float) (table.get(r0) + (table.get(r1) - table.get(r0)) * f + a * sx + c * tx + b * nx);
        out[1] = (float) (table.get(r0 + 1) + (table.get(r1 + 1) - table.get(r0 + 1)) * f + a * sy + c * ty + b * ny);
        out[2] = (float) (table.get(r0 + 2) + (table.get(r1 + 2) - table.get(r0 + 2)) * f + a * sz + c * tz + b * nz);
    }

    /**
     * {@return whether this rigid mesh rides the tip of the component its component is attached to: its
     * vertices refer to the parent's pose table and slot, its look stays its own component's}
     */
    public boolean ridesParent() {
        return ridesParent;
    }

    /** {@return whether this mesh's triangles come from a file ({@link #fromMesh})} */
    public boolean fromFile() {
        return mesh != null;
    }

    /**
     * {@return value {@code i} of vertex {@code v} of a mesh from a file (see {@link #MESH_FLOATS})}
     *
     * @param v vertex, in [0, vertexCount())
     * @param i one of the {@code MESH_*} indices, in [0, MESH_FLOATS)
     * @throws IllegalStateException when this mesh is not from a file
     */
    public float meshValue(int v, int i) {
        if (mesh == null) {
            throw new IllegalStateException("not a mesh from a file");
        }
        return mesh[MESH_FLOATS * v + i];
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
