package org.jecosys.plant;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.util.Locale;

/**
 * Writes a {@link MeshGeometry} as a binary glTF 2.0 file ({@code .glb}): one mesh of one
 * triangle-list primitive with POSITION, NORMAL and, where the geometry has them, TEXCOORD_0, and
 * unsigned int indices, in one buffer inside the file. What {@link GltfMeshes#read} reads back,
 * vertex for vertex; for tools that make a scene's meshes (the shipped scenes' generator) and for
 * tests. Any thread; allocates.
 */
public final class GltfWriter {
    private static final int MAGIC = 0x46546C67; // "glTF"
    private static final int JSON = 0x4E4F534A;
    private static final int BIN = 0x004E4942;

    private GltfWriter() {
    }

    /**
     * The .glb file's bytes.
     *
     * @param g the mesh
     * @return the file, little-endian, chunks padded to 4 bytes
     */
    public static byte[] glb(MeshGeometry g) {
        int n = g.vertexCount();
        int floats = n * (6 + (g.hasUvs() ? 2 : 0));
        ByteBuffer bin = ByteBuffer.allocate(4 * floats + 4 * 3 * g.triangleCount()).order(ByteOrder.LITTLE_ENDIAN);
        float[] lo = {Float.MAX_VALUE, Float.MAX_VALUE, Float.MAX_VALUE};
        float[] hi = {-Float.MAX_VALUE, -Float.MAX_VALUE, -Float.MAX_VALUE};
        for (int v = 0; v < n; v++) {
            for (int a = 0; a < 3; a++) {
                bin.putFloat(g.position(v, a));
                lo[a] = Math.min(lo[a], g.position(v, a));
                hi[a] = Math.max(hi[a], g.position(v, a));
            }
        }
        for (int v = 0; v < n; v++) {
            for (int a = 0; a < 3; a++) {
                bin.putFloat(g.normal(v, a));
            }
        }
        if (g.hasUvs()) {
            for (int v = 0; v < n; v++) {
                bin.putFloat(g.uv(v, 0)).putFloat(g.uv(v, 1));
            }
        }
        for (int i = 0; i < 3 * g.triangleCount(); i++) {
            bin.putInt(g.index(i));
        }
        int posBytes = 12 * n;
        int uvBytes = g.hasUvs() ? 8 * n : 0;
        int idxBytes = 12 * g.triangleCount();
        StringBuilder j = new StringBuilder();
        j.append("{\"asset\":{\"version\":\"2.0\",\"generator\":\"JEcoSys GltfWriter\"},\"scene\":0,")
                .append("\"scenes\":[{\"nodes\":[0]}],\"nodes\":[{\"mesh\":0}],\"meshes\":[{\"primitives\":[{")
                .append("\"attributes\":{\"POSITION\":0,\"NORMAL\":1").append(g.hasUvs() ? ",\"TEXCOORD_0\":3" : "")
                .append("},\"indices\":2,\"mode\":4}]}],")
                .append("\"buffers\":[{\"byteLength\":").append(bin.capacity()).append("}],\"bufferViews\":[")
                .append(view(0, posBytes, ",\"target\":34962")).append(',')
                .append(view(posBytes, posBytes, ",\"target\":34962")).append(',')
                .append(view(2 * posBytes + uvBytes, idxBytes, ",\"target\":34963"));
        if (g.hasUvs()) {
            j.append(',').append(view(2 * posBytes, uvBytes, ",\"target\":34962"));
        }
        j.append("],\"accessors\":[").append(String.format(Locale.ROOT, "{\"bufferView\":0,\"componentType\":5126,"
                + "\"count\":%d,\"type\":\"VEC3\",\"min\":[%s,%s,%s],\"max\":[%s,%s,%s]}", n, lo[0], lo[1], lo[2], hi[0],
                hi[1], hi[2]))
                .append(",{\"bufferView\":1,\"componentType\":5126,\"count\":").append(n).append(",\"type\":\"VEC3\"}")
                .append(",{\"bufferView\":2,\"componentType\":5125,\"count\":").append(3 * g.triangleCount())
                .append(",\"type\":\"SCALAR\"}");
        if (g.hasUvs()) {
            j.append(",{\"bufferView\":3,\"componentType\":5126,\"count\":").append(n).append(",\"type\":\"VEC2\"}");
        }
        j.append("]}");
        byte[] json = j.toString().getBytes(StandardCharsets.UTF_8);
        int jl = (json.length + 3) & ~3;
        int bl = (bin.capacity() + 3) & ~3;
        ByteBuffer out = ByteBuffer.allocate(12 + 8 + jl + 8 + bl).order(ByteOrder.LITTLE_ENDIAN);
        out.putInt(MAGIC).putInt(2).putInt(out.capacity());
        out.putInt(jl).putInt(JSON).put(json);
        for (int i = json.length; i < jl; i++) {
            out.put((byte) ' ');
        }
        out.putInt(bl).putInt(BIN).put(bin.array());
        return out.array();
    }

    private static String view(int offset, int length, String target) {
        return "{\"buffer\":0,\"byteOffset\":" + offset + ",\"byteLength\":" + length + target + "}";
    }
}
