package org.jecosys.plant;

import org.jecosys.math.Require;

/**
 * The mesh of a whole plant of one species at one level of detail, built once (paper §4.1, Tables
 * 1-3): the meshes of every component instance ("slot", see {@link SpeciesModel}) concatenated.
 * Each vertex names its slot (which component instance: its pose table, bend state and attachment),
 * the pose-table point and the side/normal coefficients {@code a, b} (vertex =
 * {@code p + a s + b n}); indices are triangles (3) or line pairs (2) into these vertices. One
 * instanced draw per species and level uses it.
 *
 * <p>Immutable; any thread; accessors do not allocate; {@code copy*} write into caller arrays.
 */
public final class LodMesh {
    private final Primitive primitive;
    private final int[] vertexSlot;
    private final int[] vertexPoint;
    private final float[] vertexA;
    private final float[] vertexB;
    private final int[] indices;
    /** {@link ComponentMesh#MESH_FLOATS} per vertex of a mesh from a file, or null when no vertex is. */
    private final float[] mesh;
    private final boolean[] fromFile;
    private final int[] vertexLook;

    LodMesh(Primitive primitive, int[] vertexSlot, int[] vertexPoint, float[] vertexA, float[] vertexB, int[] indices,
            float[] mesh, boolean[] fromFile, int[] vertexLook) {
        this.vertexLook = vertexLook;
        this.primitive = primitive;
        this.vertexSlot = vertexSlot;
        this.vertexPoint = vertexPoint;
        this.vertexA = vertexA;
        this.vertexB = vertexB;
        this.indices = indices;
        this.mesh = mesh;
        this.fromFile = fromFile;
    }

    /** Concatenates the component meshes of {@code slots} slots. Build time; allocates. */
    static LodMesh concat(Primitive primitive, int slots, int[] slotComponent, int[] slotParent,
                          ComponentMesh[] meshOfComponent) {
        int vCount = 0;
        int iCount = 0;
        for (int s = 0; s < slots; s++) {
            ComponentMesh m = meshOfComponent[slotComponent[s]];
            vCount += m.vertexCount();
            iCount += m.indexCount();
        }
        int[] vs = new int[vCount];
        int[] vp = new int[vCount];
        float[] va = new float[vCount];
        float[] vb = new float[vCount];
        int[] idx = new int[iCount];
        boolean any = false;
        for (int s = 0; s < slots; s++) {
            any |= meshOfComponent[slotComponent[s]].fromFile();
        }
        int mf = ComponentMesh.MESH_FLOATS;
        float[] mesh = any ? new float[mf * vCount] : null;
        boolean[] fromFile = new boolean[vCount];
        int[] look = new int[vCount];
        int v0 = 0;
        int i0 = 0;
        for (int s = 0; s < slots; s++) {
            ComponentMesh m = meshOfComponent[slotComponent[s]];
            for (int v = 0; v < m.vertexCount(); v++) {
                // a rigid mesh riding its parent's tip is placed by the parent's slot, looks like its own
                vs[v0 + v] = m.ridesParent() && slotParent[s] >= 0 ? slotParent[s] : s;
                look[v0 + v] = s;
                vp[v0 + v] = m.vertexPoint(v);
                va[v0 + v] = m.vertexA(v);
                vb[v0 + v] = m.vertexB(v);
                if (m.fromFile()) {
                    fromFile[v0 + v] = true;
                    for (int i = 0; i < mf; i++) {
                        mesh[mf * (v0 + v) + i] = m.meshValue(v, i);
                    }
                } else if (mesh != null) {
                    mesh[mf * (v0 + v) + ComponentMesh.MESH_POINT] = m.vertexPoint(v);
                }
            }
            for (int i = 0; i < m.indexCount(); i++) {
                idx[i0 + i] = v0 + m.index(i);
            }
            v0 += m.vertexCount();
            i0 += m.indexCount();
        }
        return new LodMesh(primitive, vs, vp, va, vb, idx, mesh, fromFile, look);
    }

    /** {@return the primitive: triangles or lines} */
    public Primitive primitive() {
        return primitive;
    }

    /** {@return the primitives (triangles or line segments) of one plant at this level} */
    public int primitiveCount() {
        return indices.length / (primitive == Primitive.TRIANGLES ? 3 : 2);
    }

    /** {@return the number of vertices of one plant at this level} */
    public int vertexCount() {
        return vertexPoint.length;
    }

    /** {@return the number of indices: 3 per triangle, 2 per line} */
    public int indexCount() {
        return indices.length;
    }

    /**
     * {@return the slot (component instance) whose pose and place vertex {@code v} follows}
     *
     * @param v vertex index, in [0, vertexCount())
     */
    public int vertexSlot(int v) {
        return vertexSlot[v];
    }

    /**
     * {@return the pose-table point of vertex {@code v}}
     *
     * @param v vertex index, in [0, vertexCount())
     */
    public int vertexPoint(int v) {
        return vertexPoint[v];
    }

    /**
     * {@return the slot whose component gives vertex {@code v} its look (colour, kind, texture): its own
     * slot, also for a rigid mesh placed by its parent's slot ({@link #vertexSlot})}
     *
     * @param v vertex index, in [0, vertexCount())
     */
    public int vertexLookSlot(int v) {
        return vertexLook[v];
    }

    /**
     * {@return whether vertex {@code v} belongs to a mesh from a file (its values in {@link #meshValue})}
     *
     * @param v vertex index, in [0, vertexCount())
     */
    public boolean vertexFromFile(int v) {
        return fromFile[v];
    }

    /**
     * {@return value {@code i} of vertex {@code v} ({@link ComponentMesh#MESH_FLOATS}); for a vertex not
     * from a file: its point, and 0 for the rest}
     *
     * @param v vertex index, in [0, vertexCount())
     * @param i one of {@link ComponentMesh}'s {@code MESH_*} indices
     */
    public float meshValue(int v, int i) {
        if (mesh == null) {
            return i == ComponentMesh.MESH_POINT ? vertexPoint[v] : 0f;
        }
        return mesh[ComponentMesh.MESH_FLOATS * v + i];
    }

    /**
     * {@return the side coefficient {@code a} of vertex {@code v}}
     *
     * @param v vertex index, in [0, vertexCount())
     */
    public float vertexA(int v) {
        return vertexA[v];
    }

    /**
     * {@return the normal coefficient {@code b} of vertex {@code v}}
     *
     * @param v vertex index, in [0, vertexCount())
     */
    public float vertexB(int v) {
        return vertexB[v];
    }

    /**
     * {@return index {@code i}, a vertex of this mesh}
     *
     * @param i position in the index list, in [0, indexCount())
     */
    public int index(int i) {
        return indices[i];
    }

    /**
     * Writes interleaved vertex attributes for upload, 4 floats per vertex
     * {@code (slot, point, a, b)} (slot and point exact as floats), into {@code dest} from
     * {@code offset}. No allocation.
     *
     * @param dest   receives {@code 4 * vertexCount()} floats
     * @param offset first index written, in [0, dest.length - 4 * vertexCount()]
     * @throws IllegalArgumentException when dest is null or too short from offset
     */
    public void copyVertices(float[] dest, int offset) {
        Require.nonNull("dest", dest);
        Require.range("offset", offset, 0, dest.length - 4 * vertexPoint.length);
        for (int v = 0; v < vertexPoint.length; v++) {
            int o = offset + 4 * v;
            dest[o] = vertexSlot[v];
            dest[o + 1] = vertexPoint[v];
            dest[o + 2] = vertexA[v];
            dest[o + 3] = vertexB[v];
        }
    }

    /**
     * Copies the index list into {@code dest} from {@code offset}. No allocation.
     *
     * @param dest   receives {@link #indexCount()} ints
     * @param offset first index written
     */
    public void copyIndices(int[] dest, int offset) {
        System.arraycopy(indices, 0, dest, offset, indices.length);
    }
}
