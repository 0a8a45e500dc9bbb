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

    LodMesh(Primitive primitive, int[] vertexSlot, int[] vertexPoint, float[] vertexA, float[] vertexB, int[] indices) {
        this.primitive = primitive;
        this.vertexSlot = vertexSlot;
        this.vertexPoint = vertexPoint;
        this.vertexA = vertexA;
        this.vertexB = vertexB;
        this.indices = indices;
    }

    /** Concatenates the component meshes of {@code slots} slots. Build time; allocates. */
    static LodMesh concat(Primitive primitive, int slots, int[] slotComponent, ComponentMesh[] meshOfComponent) {
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
        int v0 = 0;
        int i0 = 0;
        for (int s = 0; s < slots; s++) {
            ComponentMesh m = meshOfComponent[slotComponent[s]];
            for (int v = 0; v < m.vertexCount(); v++) {
                vs[v0 + v] = s;
                vp[v0 + v] = m.vertexPoint(v);
                va[v0 + v] = m.vertexA(v);
                vb[v0 + v] = m.vertexB(v);
            }
            for (int i = 0; i < m.indexCount(); i++) {
                idx[i0 + i] = v0 + m.index(i);
            }
            v0 += m.vertexCount();
            i0 += m.indexCount();
        }
        return new LodMesh(primitive, vs, vp, va, vb, idx);
    }

    /** Triangles or lines. */
    public Primitive primitive() {
        return primitive;
    }

    /** Primitives (triangles or line segments) of one plant at this level. */
    public int primitiveCount() {
        return indices.length / (primitive == Primitive.TRIANGLES ? 3 : 2);
    }

    /** Vertices of one plant at this level. */
    public int vertexCount() {
        return vertexPoint.length;
    }

    /** Indices: 3 per triangle, 2 per line. */
    public int indexCount() {
        return indices.length;
    }

    /** Slot (component instance) of vertex {@code v}. */
    public int vertexSlot(int v) {
        return vertexSlot[v];
    }

    /** Pose-table point of vertex {@code v}. */
    public int vertexPoint(int v) {
        return vertexPoint[v];
    }

    /** Side coefficient of vertex {@code v}. */
    public float vertexA(int v) {
        return vertexA[v];
    }

    /** Normal coefficient of vertex {@code v}. */
    public float vertexB(int v) {
        return vertexB[v];
    }

    /** Index {@code i}. */
    public int index(int i) {
        return indices[i];
    }

    /**
     * Writes interleaved vertex attributes for upload, 4 floats per vertex
     * {@code (slot, point, a, b)} (slot and point exact as floats), into {@code dest} from
     * {@code offset}. No allocation.
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

    /** Copies the index list into {@code dest} from {@code offset}. No allocation. */
    public void copyIndices(int[] dest, int offset) {
        System.arraycopy(indices, 0, dest, offset, indices.length);
    }
}
