package org.jecosys.plant;

import java.util.Arrays;
import org.jecosys.math.Require;

/**
 * Triangles of a mesh component as read from a glTF file ({@link GltfMeshes}), in the file's
 * coordinates (metres, +Y up): per vertex a position, a unit normal and, where the file has them,
 * texture coordinates (glTF's: u to the right, v down the image). Immutable (the arrays are copied
 * in and never handed out); any thread; accessors do not allocate.
 */
public final class MeshGeometry {
    /** Most vertices of one component's mesh (each is drawn once per component of every plant). */
    public static final int MAX_VERTICES = 4096;
    /** Most triangles of one component's mesh. */
    public static final int MAX_TRIANGLES = 8192;

    private final float[] positions;
    private final float[] normals;
    private final float[] uvs;
    private final int[] indices;

    /**
     * A mesh. Build time; copies the arrays.
     *
     * @param positions x, y, z per vertex, finite; at least 3 vertices, at most {@link #MAX_VERTICES}
     * @param normals   x, y, z per vertex, unit length (or null: each vertex gets the mean of its
     *                  triangles' normals, weighted by their areas)
     * @param uvs       u, v per vertex, or null when the file has none
     * @param indices   3 per triangle, each a vertex; at least 1, at most {@link #MAX_TRIANGLES}
     * @throws IllegalArgumentException when an array is missing, of the wrong length or out of range
     */
    public MeshGeometry(float[] positions, float[] normals, float[] uvs, int[] indices) {
        Require.nonNull("positions", positions);
        Require.nonNull("indices", indices);
        int n = positions.length / 3;
        if (positions.length % 3 != 0) {
            throw new IllegalArgumentException("positions: 3 floats per vertex, got " + positions.length);
        }
        Require.range("vertices", n, 3, MAX_VERTICES);
        if (indices.length % 3 != 0) {
            throw new IllegalArgumentException("indices: 3 per triangle, got " + indices.length);
        }
        Require.range("triangles", indices.length / 3, 1, MAX_TRIANGLES);
        for (float p : positions) {
            Require.finite("position", p);
        }
        for (int i : indices) {
            Require.range("index", i, 0, n - 1);
        }
        if (normals != null && normals.length != 3 * n) {
            throw new IllegalArgumentException("normals: 3 floats per vertex, got " + normals.length + " for " + n);
        }
        if (uvs != null && uvs.length != 2 * n) {
            throw new IllegalArgumentException("uvs: 2 floats per vertex, got " + uvs.length + " for " + n);
        }
        this.positions = positions.clone();
        this.indices = indices.clone();
        this.uvs = uvs == null ? null : uvs.clone();
        this.normals = normals == null ? smoothNormals(this.positions, this.indices) : unit(normals.clone());
    }

    private static float[] unit(float[] n) {
        for (int v = 0; v < n.length; v += 3) {
            double l = Math.sqrt(n[v] * n[v] + n[v + 1] * n[v + 1] + n[v + 2] * n[v + 2]);
            if (!(l > 1e-12) || !Double.isFinite(l)) {
                n[v] = 0;
                n[v + 1] = 0;
                n[v + 2] = 1;
            } else {
                n[v] /= l;
                n[v + 1] /= l;
                n[v + 2] /= l;
            }
        }
        return n;
    }

    private static float[] smoothNormals(float[] p, int[] idx) {
        float[] n = new float[p.length];
        for (int t = 0; t < idx.length; t += 3) {
            int a = 3 * idx[t];
            int b = 3 * idx[t + 1];
            int c = 3 * idx[t + 2];
            float ux = p[b] - p[a];
            float uy = p[b + 1] - p[a + 1];
            float uz = p[b + 2] - p[a + 2];
            float vx = p[c] - p[a];
            float vy = p[c + 1] - p[a + 1];
            float vz = p[c + 2] - p[a + 2];
            float nx = uy * vz - uz * vy;
            float ny = uz * vx - ux * vz;
            float nz = ux * vy - uy * vx;
            for (int k : new int[] {a, b, c}) {
                n[k] += nx;
                n[k + 1] += ny;
                n[k + 2] += nz;
            }
        }
        return unit(n);
    }

    /** {@return the number of vertices} */
    public int vertexCount() {
        return positions.length / 3;
    }

    /** {@return the number of triangles} */
    public int triangleCount() {
        return indices.length / 3;
    }

    /**
     * {@return coordinate {@code axis} (0 x, 1 y, 2 z) of vertex {@code v}'s position, metres}
     *
     * @param v    vertex, in [0, vertexCount())
     * @param axis 0, 1 or 2
     */
    public float position(int v, int axis) {
        return positions[3 * v + axis];
    }

    /**
     * {@return coordinate {@code axis} of vertex {@code v}'s unit normal}
     *
     * @param v    vertex, in [0, vertexCount())
     * @param axis 0, 1 or 2
     */
    public float normal(int v, int axis) {
        return normals[3 * v + axis];
    }

    /** {@return whether the file gave texture coordinates (TEXCOORD_0)} */
    public boolean hasUvs() {
        return uvs != null;
    }

    /**
     * {@return texture coordinate {@code axis} (0 u, 1 v, glTF's: v down the image) of vertex {@code v}}
     *
     * @param v    vertex, in [0, vertexCount())
     * @param axis 0 or 1
     * @throws IllegalStateException when the mesh has no texture coordinates
     */
    public float uv(int v, int axis) {
        if (uvs == null) {
            throw new IllegalStateException("the mesh has no texture coordinates");
        }
        return uvs[2 * v + axis];
    }

    /**
     * {@return index {@code i}: a vertex of a triangle, 3 per triangle}
     *
     * @param i in [0, 3 triangleCount())
     */
    public int index(int i) {
        return indices[i];
    }

    /**
     * {@return the least or greatest coordinate along an axis over the vertices, metres}
     *
     * @param axis 0 x, 1 y, 2 z
     * @param max  true for the greatest
     */
    public float bound(int axis, boolean max) {
        float b = positions[axis];
        for (int v = axis; v < positions.length; v += 3) {
            b = max ? Math.max(b, positions[v]) : Math.min(b, positions[v]);
        }
        return b;
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof MeshGeometry m && Arrays.equals(positions, m.positions) && Arrays.equals(normals, m.normals)
                && Arrays.equals(uvs, m.uvs) && Arrays.equals(indices, m.indices);
    }

    @Override
    public int hashCode() {
        return 31 * Arrays.hashCode(positions) + Arrays.hashCode(indices);
    }

    @Override
    public String toString() {
        return "MeshGeometry[" + vertexCount() + " vertices, " + triangleCount() + " triangles]";
    }
}
