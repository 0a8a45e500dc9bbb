package org.jecosys.plant;

import de.javagl.jgltf.model.AccessorByteData;
import de.javagl.jgltf.model.AccessorData;
import de.javagl.jgltf.model.AccessorFloatData;
import de.javagl.jgltf.model.AccessorIntData;
import de.javagl.jgltf.model.AccessorModel;
import de.javagl.jgltf.model.AccessorShortData;
import de.javagl.jgltf.model.GltfModel;
import de.javagl.jgltf.model.GltfModels;
import de.javagl.jgltf.model.MeshModel;
import de.javagl.jgltf.model.MeshPrimitiveModel;
import de.javagl.jgltf.model.NodeModel;
import de.javagl.jgltf.model.io.GltfAsset;
import de.javagl.jgltf.model.io.GltfAssetReader;
import de.javagl.jgltf.model.io.GltfReference;
import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.net.URLDecoder;
import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Base64;
import java.util.List;

/**
 * Reads the triangles of a glTF 2.0 file ({@code .gltf} with its buffers, or binary {@code .glb}) for a
 * mesh component. The format is parsed by javagl's JglTF ({@code de.javagl:jgltf-model}): a pure-Java
 * reader, so the core stays free of native code (LWJGL's Assimp binding would bring a native library
 * to every platform for one format), maintained, and one that hands external buffers to the caller to
 * fetch: here through the scene's image source, so a buffer obeys the same folder confinement as the
 * scene's images and comes from a game's asset manager when the scene does.
 *
 * <p>What is read: every mesh of the file's first scene, each node's transform applied (or every mesh
 * as it is when the file has no scene); per primitive POSITION (required), NORMAL and TEXCOORD_0 (used
 * when every primitive has them) and the indices (or the vertices in order). Only triangle lists (mode
 * 4) are accepted. Materials, images, skins and animations are ignored: the component's
 * {@code texture} and {@code colour} give its look. Every refusal is an {@link IOException} whose
 * message names the file and says what is allowed. Build time, any one thread; allocates.
 */
public final class GltfMeshes {
    private static final int TRIANGLES = 4;

    private GltfMeshes() {
    }

    /**
     * Reads a mesh.
     *
     * @param path  the file as the scene writes it; its buffers are read relative to its folder
     * @param files where the file and its buffers come from
     * @return the triangles
     * @throws IOException naming the file: missing or unreadable (the source's message), not glTF 2.0,
     *                     a buffer that cannot be read or leads out of the scene's folder, no
     *                     triangles, no POSITION, a mode other than triangles, too many vertices
     */
    public static MeshGeometry read(String path, PlantTextures.Files files) throws IOException {
        String what = "mesh '" + path + "'";
        byte[] bytes = files.read(path);
        GltfAsset asset;
        List<String> jsonErrors = new ArrayList<>();
        try {
            GltfAssetReader reader = new GltfAssetReader();
            reader.setJsonErrorConsumer(e -> jsonErrors.add(e.getJsonPathString() + ": " + e.getMessage()));
            asset = reader.readWithoutReferences(new ByteArrayInputStream(bytes));
        } catch (IOException | RuntimeException e) {
            throw new IOException(what + ": not a glTF 2.0 file (.gltf JSON or binary .glb): " + reason(e));
        }
        if (asset == null || !jsonErrors.isEmpty()) {
            throw new IOException(what + ": not a valid glTF 2.0 file: "
                    + (jsonErrors.isEmpty() ? "nothing read" : jsonErrors.get(0)));
        }
        if (!(asset.getGltf() instanceof de.javagl.jgltf.impl.v2.GlTF)) {
            throw new IOException(what + ": a glTF 1.0 file; only glTF 2.0 is read");
        }
        String folder = path.replace('\\', '/').contains("/")
                ? path.replace('\\', '/').substring(0, path.replace('\\', '/').lastIndexOf('/') + 1) : "";
        for (GltfReference ref : asset.getReferences()) {
            if (!ref.getName().toLowerCase(java.util.Locale.ROOT).startsWith("buffer")) {
                continue; // images: the component's texture gives its look
            }
            byte[] data = buffer(what, folder, ref.getUri(), files);
            ByteBuffer direct = ByteBuffer.allocateDirect(data.length).order(java.nio.ByteOrder.LITTLE_ENDIAN);
            direct.put(data).flip();
            ref.getTarget().accept(direct);
        }
        GltfModel model;
        try {
            model = GltfModels.create(asset);
        } catch (RuntimeException e) {
            throw new IOException(what + ": its buffers, views or accessors do not fit together: " + reason(e));
        }
        List<float[]> transforms = new ArrayList<>();
        List<MeshModel> meshes = new ArrayList<>();
        if (!model.getSceneModels().isEmpty()) {
            for (NodeModel n : model.getSceneModels().get(0).getNodeModels()) {
                collect(n, meshes, transforms, 0);
            }
        } else {
            for (MeshModel m : model.getMeshModels()) {
                meshes.add(m);
                transforms.add(null);
            }
        }
        try {
            return geometry(what, meshes, transforms);
        } catch (RuntimeException e) {
            throw new IOException(what + ": " + reason(e));
        }
    }

    private static String reason(Throwable e) {
        String m = e.getMessage();
        return m == null || m.isBlank() ? e.getClass().getSimpleName() : m;
    }

    private static void collect(NodeModel n, List<MeshModel> meshes, List<float[]> transforms, int depth)
            throws IOException {
        if (depth > 64) {
            throw new IOException("nodes nested more than 64 deep");
        }
        for (MeshModel m : n.getMeshModels()) {
            meshes.add(m);
            transforms.add(n.computeGlobalTransform(null));
        }
        for (NodeModel c : n.getChildren()) {
            collect(c, meshes, transforms, depth + 1);
        }
    }

    /** A buffer's bytes: a base64 data URI, or a file relative to the glTF file's folder, read through files. */
    private static byte[] buffer(String what, String folder, String uri, PlantTextures.Files files) throws IOException {
        if (uri == null) {
            throw new IOException(what + ": a buffer without a uri (only a .glb's first buffer may have none)");
        }
        if (uri.startsWith("data:")) {
            int comma = uri.indexOf(',');
            if (comma < 0 || !uri.substring(0, comma).endsWith(";base64")) {
                throw new IOException(what + ": a data URI buffer must be base64 ('data:...;base64,...')");
            }
            try {
                return Base64.getDecoder().decode(uri.substring(comma + 1));
            } catch (IllegalArgumentException e) {
                throw new IOException(what + ": a data URI buffer is not valid base64");
            }
        }
        int colon = uri.indexOf(':');
        int slash = uri.indexOf('/');
        if (colon > 1 && (slash < 0 || colon < slash)) {
            throw new IOException(what + ": buffer '" + uri + "' is a URL; a buffer is a file next to the mesh "
                    + "(a relative path) or a data URI");
        }
        String file = URLDecoder.decode(uri.replace("+", "%2B"), StandardCharsets.UTF_8);
        if (file.startsWith("/") || file.startsWith("\\") || (file.length() > 1 && file.charAt(1) == ':')) {
            throw new IOException(what + ": buffer '" + uri + "' is an absolute path; a buffer is a file relative "
                    + "to the mesh, inside the scene's folder");
        }
        String joined = folder + file;
        if (leavesFolder(joined)) {
            throw new IOException(what + ": buffer '" + uri + "' leads out of the scene's folder");
        }
        try {
            return files.read(joined);
        } catch (IOException e) {
            throw new IOException(what + ": buffer '" + uri + "': " + e.getMessage());
        }
    }

    private static boolean leavesFolder(String path) {
        int depth = 0;
        for (String part : path.replace('\\', '/').split("/")) {
            if (part.equals("..")) {
                if (--depth < 0) {
                    return true;
                }
            } else if (!part.isEmpty() && !part.equals(".")) {
                depth++;
            }
        }
        return false;
    }

    private static MeshGeometry geometry(String what, List<MeshModel> meshes, List<float[]> transforms)
            throws IOException {
        int vertices = 0;
        int indices = 0;
        boolean normals = true;
        boolean uvs = true;
        List<MeshPrimitiveModel> prims = new ArrayList<>();
        List<float[]> primTransforms = new ArrayList<>();
        for (int m = 0; m < meshes.size(); m++) {
            for (MeshPrimitiveModel p : meshes.get(m).getMeshPrimitiveModels()) {
                if (p.getMode() != TRIANGLES) {
                    throw new IOException(what + ": a primitive of mode " + p.getMode() + " ("
                            + modeName(p.getMode()) + "); only triangle lists (mode 4) are read");
                }
                AccessorModel pos = p.getAttributes().get("POSITION");
                if (pos == null) {
                    throw new IOException(what + ": a primitive without the POSITION attribute");
                }
                if (pos.getElementType().getNumComponents() != 3 || !(pos.getAccessorData() instanceof AccessorFloatData)) {
                    throw new IOException(what + ": POSITION must be VEC3 of floats");
                }
                vertices += pos.getCount();
                indices += p.getIndices() == null ? pos.getCount() : p.getIndices().getCount();
                normals &= p.getAttributes().get("NORMAL") != null;
                uvs &= p.getAttributes().get("TEXCOORD_0") != null;
                prims.add(p);
                primTransforms.add(transforms.get(m));
            }
        }
        if (prims.isEmpty()) {
            throw new IOException(what + ": no mesh with triangles in the file");
        }
        if (vertices > MeshGeometry.MAX_VERTICES) {
            throw new IOException(what + ": " + vertices + " vertices; a component's mesh has at most "
                    + MeshGeometry.MAX_VERTICES + " (it is drawn once per component of every plant)");
        }
        if (indices / 3 > MeshGeometry.MAX_TRIANGLES || indices % 3 != 0) {
            throw new IOException(what + ": " + (indices % 3 != 0 ? "an index count that is not a multiple of 3"
                    : indices / 3 + " triangles; a component's mesh has at most " + MeshGeometry.MAX_TRIANGLES));
        }
        if (vertices < 3) {
            throw new IOException(what + ": fewer than 3 vertices");
        }
        float[] pos = new float[3 * vertices];
        float[] nrm = normals ? new float[3 * vertices] : null;
        float[] uv = uvs ? new float[2 * vertices] : null;
        int[] idx = new int[indices];
        int v0 = 0;
        int i0 = 0;
        for (int k = 0; k < prims.size(); k++) {
            MeshPrimitiveModel p = prims.get(k);
            float[] m = primTransforms.get(k);
            AccessorFloatData pd = (AccessorFloatData) p.getAttributes().get("POSITION").getAccessorData();
            int n = pd.getNumElements();
            for (int v = 0; v < n; v++) {
                transform(m, pd.get(v, 0), pd.get(v, 1), pd.get(v, 2), 1, pos, 3 * (v0 + v));
            }
            if (nrm != null) {
                AccessorData nd = p.getAttributes().get("NORMAL").getAccessorData();
                if (!(nd instanceof AccessorFloatData f) || nd.getNumComponentsPerElement() != 3 || nd.getNumElements() != n) {
                    throw new IOException(what + ": NORMAL must be VEC3 of floats, one per vertex");
                }
                for (int v = 0; v < n; v++) {
                    transform(m, f.get(v, 0), f.get(v, 1), f.get(v, 2), 0, nrm, 3 * (v0 + v));
                }
            }
            if (uv != null) {
                AccessorData td = p.getAttributes().get("TEXCOORD_0").getAccessorData();
                if (td.getNumComponentsPerElement() != 2 || td.getNumElements() != n) {
                    throw new IOException(what + ": TEXCOORD_0 must be VEC2, one per vertex");
                }
                for (int v = 0; v < n; v++) {
                    uv[2 * (v0 + v)] = component(td, v, 0);
                    uv[2 * (v0 + v) + 1] = component(td, v, 1);
                }
            }
            AccessorModel im = p.getIndices();
            if (im == null) {
                if (n % 3 != 0) {
                    throw new IOException(what + ": a primitive without indices whose vertex count is not a multiple of 3");
                }
                for (int v = 0; v < n; v++) {
                    idx[i0++] = v0 + v;
                }
            } else {
                AccessorData id = im.getAccessorData();
                for (int i = 0; i < id.getNumElements(); i++) {
                    long x = index(id, i);
                    if (x < 0 || x >= n) {
                        throw new IOException(what + ": index " + x + " outside its primitive's " + n + " vertices");
                    }
                    idx[i0++] = v0 + (int) x;
                }
            }
            v0 += n;
        }
        return new MeshGeometry(pos, nrm, uv, idx);
    }

    private static String modeName(int mode) {
        return switch (mode) {
            case 0 -> "points";
            case 1 -> "lines";
            case 2 -> "line loop";
            case 3 -> "line strip";
            case 5 -> "triangle strip";
            case 6 -> "triangle fan";
            default -> "unknown";
        };
    }

    /** A texture coordinate: floats, or normalised unsigned bytes or shorts as glTF allows. */
    private static float component(AccessorData d, int v, int c) {
        if (d instanceof AccessorFloatData f) {
            return f.get(v, c);
        }
        if (d instanceof AccessorByteData b) {
            return b.getInt(v, c) / 255f;
        }
        if (d instanceof AccessorShortData s) {
            return s.getInt(v, c) / 65535f;
        }
        throw new IllegalArgumentException("TEXCOORD_0 of an unsupported component type");
    }

    private static long index(AccessorData d, int i) {
        if (d instanceof AccessorByteData b) {
            return b.getInt(i);
        }
        if (d instanceof AccessorShortData s) {
            return s.getInt(i);
        }
        if (d instanceof AccessorIntData n) {
            return n.getLong(i);
        }
        throw new IllegalArgumentException("indices must be unsigned bytes, shorts or ints");
    }

    /** Column-major 4x4 m (null: identity) applied to (x, y, z, w), written at out[o..o+2]. */
    private static void transform(float[] m, float x, float y, float z, float w, float[] out, int o) {
        if (m == null) {
            out[o] = x;
            out[o + 1] = y;
            out[o + 2] = z;
            return;
        }
        out[o] = m[0] * x + m[4] * y + m[8] * z + m[12] * w;
        out[o + 1] = m[1] * x + m[5] * y + m[9] * z + m[13] * w;
        out[o + 2] = m[2] * x + m[6] * y + m[10] * z + m[14] * w;
    }
}
