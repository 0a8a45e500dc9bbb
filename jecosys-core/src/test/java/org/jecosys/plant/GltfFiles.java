package org.jecosys.plant;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.util.Base64;
import java.util.Locale;

/** glTF 2.0 files written for tests: one mesh of one triangle-list primitive, float positions, optional normals and uvs. */
public final class GltfFiles {
    private GltfFiles() {
    }

    /** The buffer: positions, then normals (when given), then uvs (when given), then unsigned int indices. */
    public static byte[] buffer(float[] positions, float[] normals, float[] uvs, int[] indices) {
        int n = 4 * (positions.length + (normals == null ? 0 : normals.length) + (uvs == null ? 0 : uvs.length)
                + indices.length);
        ByteBuffer b = ByteBuffer.allocate(n).order(ByteOrder.LITTLE_ENDIAN);
        for (float f : positions) {
            b.putFloat(f);
        }
        if (normals != null) {
            for (float f : normals) {
                b.putFloat(f);
            }
        }
        if (uvs != null) {
            for (float f : uvs) {
                b.putFloat(f);
            }
        }
        for (int i : indices) {
            b.putInt(i);
        }
        return b.array();
    }

    /**
     * The JSON of a .gltf whose one buffer is {@code uri} (null: a base64 data URI of the buffer);
     * {@code mode} the primitive's (4: triangles); {@code position} false leaves POSITION out.
     */
    public static String json(float[] positions, float[] normals, float[] uvs, int[] indices, String uri, int mode,
                       boolean position) {
        byte[] buf = buffer(positions, normals, uvs, indices);
        int vc = positions.length / 3;
        StringBuilder views = new StringBuilder();
        StringBuilder accessors = new StringBuilder();
        StringBuilder attributes = new StringBuilder();
        int offset = 0;
        int view = 0;
        float[][] arrays = {positions, normals, uvs};
        String[] names = {"POSITION", "NORMAL", "TEXCOORD_0"};
        String[] types = {"VEC3", "VEC3", "VEC2"};
        for (int a = 0; a < 3; a++) {
            if (arrays[a] == null) {
                continue;
            }
            int len = 4 * arrays[a].length;
            views.append(String.format(Locale.ROOT, "{\"buffer\":0,\"byteOffset\":%d,\"byteLength\":%d},", offset, len));
            String minMax = "";
            if (a == 0) {
                float[] lo = {Float.MAX_VALUE, Float.MAX_VALUE, Float.MAX_VALUE};
                float[] hi = {-Float.MAX_VALUE, -Float.MAX_VALUE, -Float.MAX_VALUE};
                for (int i = 0; i < positions.length; i++) {
                    lo[i % 3] = Math.min(lo[i % 3], positions[i]);
                    hi[i % 3] = Math.max(hi[i % 3], positions[i]);
                }
                minMax = String.format(Locale.ROOT, ",\"min\":[%s,%s,%s],\"max\":[%s,%s,%s]", lo[0], lo[1], lo[2],
                        hi[0], hi[1], hi[2]);
            }
            accessors.append(String.format(Locale.ROOT, "{\"bufferView\":%d,\"componentType\":5126,\"count\":%d,"
                    + "\"type\":\"%s\"%s},", view, vc, types[a], minMax));
            if (a > 0 || position) {
                attributes.append(String.format(Locale.ROOT, "\"%s\":%d,", names[a], view));
            }
            offset += len;
            view++;
        }
        views.append(String.format(Locale.ROOT, "{\"buffer\":0,\"byteOffset\":%d,\"byteLength\":%d}", offset,
                4 * indices.length));
        accessors.append(String.format(Locale.ROOT, "{\"bufferView\":%d,\"componentType\":5125,\"count\":%d,"
                + "\"type\":\"SCALAR\"}", view, indices.length));
        String attrs = attributes.length() == 0 ? "" : attributes.substring(0, attributes.length() - 1);
        String bufferUri = uri != null ? uri
                : "data:application/octet-stream;base64," + Base64.getEncoder().encodeToString(buf);
        return "{\"asset\":{\"version\":\"2.0\"},\"scene\":0,\"scenes\":[{\"nodes\":[0]}],\"nodes\":[{\"mesh\":0}],"
                + "\"meshes\":[{\"primitives\":[{\"attributes\":{" + attrs + "},\"indices\":" + view + ",\"mode\":" + mode
                + "}]}],\"buffers\":[{\"byteLength\":" + buf.length + (uri != null && uri.isEmpty() ? "" : ",\"uri\":\"" + bufferUri + "\"") + "}],"
                + "\"bufferViews\":[" + views + "],\"accessors\":[" + accessors + "]}";
    }

    public static byte[] utf8(String s) {
        return s.getBytes(StandardCharsets.UTF_8);
    }
}
