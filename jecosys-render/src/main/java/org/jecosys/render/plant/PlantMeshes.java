package org.jecosys.render.plant;

import static org.lwjgl.opengl.GL11C.GL_FLOAT;
import static org.lwjgl.opengl.GL15C.GL_ARRAY_BUFFER;
import static org.lwjgl.opengl.GL15C.GL_ELEMENT_ARRAY_BUFFER;
import static org.lwjgl.opengl.GL15C.GL_STATIC_DRAW;
import static org.lwjgl.opengl.GL20C.glEnableVertexAttribArray;
import static org.lwjgl.opengl.GL20C.glVertexAttribPointer;
import static org.lwjgl.opengl.GL30C.glBindVertexArray;
import static org.lwjgl.opengl.GL31C.GL_TEXTURE_BUFFER;

import java.nio.FloatBuffer;
import java.nio.IntBuffer;
import org.jecosys.anim.BendGeometry;
import java.util.List;
import org.jecosys.math.Rgb;
import org.jecosys.plant.ComponentDef;
import org.jecosys.plant.ComponentMesh;
import org.jecosys.plant.ComponentShape;
import org.jecosys.plant.LodMesh;
import org.jecosys.plant.PoseTable;
import org.jecosys.plant.SpeciesModel;
import org.jecosys.sim.World;
import org.lwjgl.system.MemoryUtil;
import org.jecosys.render.gl.GlBuffer;
import org.jecosys.render.gl.GlTracker;
import org.jecosys.render.gl.GlVertexArray;

/**
 * What {@link PlantRenderer} uploads once, at construction: the pose tables of every species as one
 * buffer (3 RGBA32F texels per skeleton point), a mesh per species and level (per vertex: slot,
 * pose-table point, side and normal coefficients, the component's colour and the fraction along it,
 * the pose stride, and the vertex kind and reach that {@code plant_common.glsl} uses for thin parts
 * and flowers), and the species slots' looks for the resolve pass. Render thread; allocates.
 */
public final class PlantMeshes {
    /**
     * Floats per mesh vertex: slot, point, a, b; r, g, b, along; pose stride; kind, reach, texture layer;
     * for a vertex of a glTF mesh its tangent offset, u, v and 1 (else 0, 0, 0, 0), and its normal in the
     * skeleton's frame (point, a and b are then its fractional point and side and normal offsets in metres).
     */
    public static final int VERTEX_FLOATS = 19;
    /** Vertex kinds of {@code plant_common.glsl}: a blade (leaf), a stem, a petal, a fan head. */
    public static final int BLADE = 0;
    public static final int STEM = 1;
    public static final int PETAL = 2;
    public static final int HEAD = 3;

    private PlantMeshes() {
    }

    private static <T extends AutoCloseable> T own(List<AutoCloseable> owned, T resource) {
        owned.add(resource);
        return resource;
    }

    public static GlBuffer uploadPoses(GlTracker t, List<SpeciesModel> models, long texels) {
        FloatBuffer poses = MemoryUtil.memAllocFloat((int) Math.max(4, texels * 4));
        try {
            for (SpeciesModel m : models) {
                for (int c = 0; c < m.componentCount(); c++) {
                    for (int v = 0; v < m.variants(); v++) {
                        PoseTable pt = m.component(c).poseTable(v);
                        for (int i = 0; i < pt.floatCount(); i += 3) {
                            poses.put(pt.get(i)).put(pt.get(i + 1)).put(pt.get(i + 2)).put(0f);
                        }
                    }
                }
            }
            poses.position(0).limit((int) Math.max(4, texels * 4));
            return GlBuffer.of(t, GL_TEXTURE_BUFFER, poses, GL_STATIC_DRAW);
        } finally {
            MemoryUtil.memFree((java.nio.Buffer) poses);
        }
    }

    /**
     * One VAO (owning its vertex and index buffers) for a species' level: slot, point, a, b; colour,
     * along; pose stride (3 x points of the slot's pose table, the same for every variant); kind, reach
     * and the texture layer of the vertex's component (-1: none; {@code layers[c]} for component c).
     */
    public static GlVertexArray uploadMesh(GlTracker t, SpeciesModel m, LodMesh mesh, int[] layers,
                                           List<AutoCloseable> owned) {
        int n = mesh.vertexCount();
        FloatBuffer fv = MemoryUtil.memAllocFloat(Math.max(VERTEX_FLOATS, VERTEX_FLOATS * n));
        IntBuffer iv = MemoryUtil.memAllocInt(Math.max(1, mesh.indexCount()));
        try {
            float[] reach = new float[m.slotCount()];
            float[] halfWidth = new float[m.slotCount()];
            for (int slot = 0; slot < reach.length; slot++) {
                reach[slot] = reach(m.slotPoseTable(slot, 0));
                halfWidth[slot] = m.slotWidestHalfWidth(slot);
            }
            for (int v = 0; v < n; v++) {
                int slot = mesh.vertexSlot(v);
                int component = m.slotComponent(mesh.vertexLookSlot(v)); // a head riding its stalk: its own look
                ComponentDef def = m.component(component).def();
                Rgb rgb = def.colour();
                int points = m.slotPoseTable(slot, 0).points();
                float point = mesh.meshValue(v, ComponentMesh.MESH_POINT);
                fv.put(slot).put(point).put(mesh.vertexA(v)).put(mesh.vertexB(v))
                        .put(rgb.r()).put(rgb.g()).put(rgb.b()).put(point / (float) Math.max(1, points - 1))
                        .put(3 * points).put(kind(def)).put(reach[slot]).put(layers[component])
                        // a glTF vertex's offset along the skeleton; any other: the slot's widest half width
                        .put(mesh.vertexFromFile(v) ? mesh.meshValue(v, ComponentMesh.MESH_C) : halfWidth[slot])
                        .put(mesh.meshValue(v, ComponentMesh.MESH_U))
                        .put(mesh.meshValue(v, ComponentMesh.MESH_V)).put(mesh.vertexFromFile(v) ? 1f : 0f)
                        .put(mesh.meshValue(v, ComponentMesh.MESH_NORMAL))
                        .put(mesh.meshValue(v, ComponentMesh.MESH_NORMAL + 1))
                        .put(mesh.meshValue(v, ComponentMesh.MESH_NORMAL + 2));
            }
            for (int i = 0; i < mesh.indexCount(); i++) {
                iv.put(mesh.index(i));
            }
            fv.position(0).limit(Math.max(VERTEX_FLOATS, VERTEX_FLOATS * n));
            iv.position(0).limit(Math.max(1, mesh.indexCount()));
            GlVertexArray vao = own(owned, new GlVertexArray(t));
            vao.bind();
            own(owned, GlBuffer.of(t, GL_ARRAY_BUFFER, fv, GL_STATIC_DRAW));
            glEnableVertexAttribArray(0);
            glVertexAttribPointer(0, 4, GL_FLOAT, false, 4 * VERTEX_FLOATS, 0);
            glEnableVertexAttribArray(1);
            glVertexAttribPointer(1, 4, GL_FLOAT, false, 4 * VERTEX_FLOATS, 16);
            glEnableVertexAttribArray(2);
            glVertexAttribPointer(2, 1, GL_FLOAT, false, 4 * VERTEX_FLOATS, 32);
            glEnableVertexAttribArray(3);
            glVertexAttribPointer(3, 3, GL_FLOAT, false, 4 * VERTEX_FLOATS, 36);
            glEnableVertexAttribArray(4);
            glVertexAttribPointer(4, 4, GL_FLOAT, false, 4 * VERTEX_FLOATS, 48);
            glEnableVertexAttribArray(5);
            glVertexAttribPointer(5, 3, GL_FLOAT, false, 4 * VERTEX_FLOATS, 64);
            own(owned, GlBuffer.of(t, GL_ELEMENT_ARRAY_BUFFER, iv, GL_STATIC_DRAW));
            glBindVertexArray(0);
            return vao;
        } finally {
            MemoryUtil.memFree((java.nio.Buffer) fv);
            MemoryUtil.memFree((java.nio.Buffer) iv);
        }
    }

    /**
     * The look of every species slot for the resolve pass, 4 floats each (colour r, g, b, vertex
     * kind), species after species; a textured component's colour is tinted by its texture's mean (the
     * far levels drawn as lines stand for the textured part). Construction time; allocates.
     */
    public static float[] slotLooks(List<SpeciesModel> models, org.jecosys.plant.PlantTextures textures) {
        int n = 0;
        for (SpeciesModel m : models) {
            n += m.slotCount();
        }
        float[] looks = new float[4 * Math.max(1, n)];
        int o = 0;
        float[] mean = {1, 1, 1};
        for (int s = 0; s < models.size(); s++) {
            SpeciesModel m = models.get(s);
            for (int slot = 0; slot < m.slotCount(); slot++) {
                int c = m.slotComponent(slot);
                ComponentDef def = m.component(c).def();
                int layer = textures.layer(s, c);
                if (layer >= 0) {
                    textures.meanColour(layer, mean);
                } else {
                    mean[0] = 1;
                    mean[1] = 1;
                    mean[2] = 1;
                }
                looks[o++] = (float) def.colour().r() * mean[0];
                looks[o++] = (float) def.colour().g() * mean[1];
                looks[o++] = (float) def.colour().b() * mean[2];
                looks[o++] = kind(def);
            }
        }
        return looks;
    }

    /**
     * The texture layer of each component of species {@code s} (-1: none). Construction time; allocates.
     *
     * @param textures the world's textures
     * @param s        the species' index
     * @param m        the species
     * @return per component, its layer
     */
    public static int[] layers(org.jecosys.plant.PlantTextures textures, int s, SpeciesModel m) {
        int[] out = new int[m.componentCount()];
        for (int c = 0; c < out.length; c++) {
            out[c] = textures.layer(s, c);
        }
        return out;
    }

    /** {@return per species of {@code models}, in order, whether it has flower parts ({@link #hasFlowerParts})} */
    static boolean[] flowerParts(List<SpeciesModel> models) {
        boolean[] flowers = new boolean[models.size()];
        for (int s = 0; s < flowers.length; s++) {
            flowers[s] = hasFlowerParts(models.get(s));
        }
        return flowers;
    }

    /** {@return whether any component of the species is a flower part (a petal or a head)} */
    public static boolean hasFlowerParts(SpeciesModel m) {
        for (int slot = 0; slot < m.slotCount(); slot++) {
            if (kind(m.component(m.slotComponent(slot)).def()) >= PETAL) {
                return true;
            }
        }
        return false;
    }

    /** The vertex kind of a component for {@code plant_common.glsl}. */
    public static int kind(ComponentDef def) {
        return switch (def.type()) {
            case STALK -> STEM;
            case PETAL -> PETAL;
            case HEAD -> def.shape() == ComponentShape.FAN ? HEAD : PETAL;
            default -> BLADE;
        };
    }

    /** The farthest a point of pose 0 reaches from the component's base, width included, metres. */
    public static float reach(PoseTable table) {
        double most = 1e-4;
        for (int j = 0; j < table.points(); j++) {
            int o = j * PoseTable.STRIDE;
            double p = Math.sqrt(sq(table.get(o)) + sq(table.get(o + 1)) + sq(table.get(o + 2)));
            double w = Math.sqrt(sq(table.get(o + 3)) + sq(table.get(o + 4)) + sq(table.get(o + 5)));
            most = Math.max(most, p + w);
        }
        return (float) most;
    }

    private static double sq(double x) {
        return x * x;
    }

    /**
     * The pose buffer's layout: species after species, component type after type, variant after
     * variant, 3 texels (12 floats) per point of each pose. Fills {@code first[s][c][v]} with the
     * first texel of that pose table and returns the texels in all. Construction time; allocates.
     */
    public static long poseTexelLayout(List<SpeciesModel> models, int[][][] first) {
        long texels = 0;
        for (int s = 0; s < models.size(); s++) {
            SpeciesModel m = models.get(s);
            first[s] = new int[m.componentCount()][m.variants()];
            for (int c = 0; c < m.componentCount(); c++) {
                for (int v = 0; v < m.variants(); v++) {
                    first[s][c][v] = (int) Math.min(texels, Integer.MAX_VALUE);
                    PoseTable pt = m.component(c).poseTable(v);
                    texels += 3L * pt.poses() * pt.points();
                }
            }
        }
        return texels;
    }

    /** A float buffer for a buffer texture, uploaded once. Construction time; allocates. */
    public static GlBuffer uploadFloats(GlTracker t, float[] values) {
        FloatBuffer b = MemoryUtil.memAllocFloat(values.length);
        try {
            b.put(values).flip();
            return GlBuffer.of(t, GL_TEXTURE_BUFFER, b, GL_STATIC_DRAW);
        } finally {
            MemoryUtil.memFree((java.nio.Buffer) b);
        }
    }

    /**
     * Static per-component data for the resolve pass, one RGBA32F texel per component: the world
     * position of a root component's base (its plant's base plus the slot's ground offset rotated by
     * the plant's rest azimuth; 0 for attached components) and the texel of pose 0, point 0 of its
     * pose table.
     */
    public static GlBuffer uploadStatic(GlTracker t, World world, int[][][] poseTexel) {
        int n = Math.max(1, world.componentCount());
        FloatBuffer b = MemoryUtil.memAllocFloat(4 * n);
        try {
            for (int p = 0; p < world.plantCount(); p++) {
                SpeciesModel m = world.plants().species().get(world.plantSpecies(p));
                int v = world.plantVariant(p);
                int s = world.plantSpecies(p);
                double rest = world.plantRestAzimuth(p);
                double rc = Math.cos(rest);
                double rs = Math.sin(rest);
                for (int slot = 0; slot < m.slotCount(); slot++) {
                    int o = 4 * (world.firstComponent(p) + slot);
                    if (m.slotParent(slot) < 0) {
                        double ox = m.slotBaseX(slot);
                        double oz = m.slotBaseZ(slot);
                        b.put(o, world.plantX(p) + (float) (ox * rc - oz * rs));
                        b.put(o + 1, world.plantY(p));
                        b.put(o + 2, world.plantZ(p) + (float) (ox * rs + oz * rc));
                    } else {
                        b.put(o, 0f).put(o + 1, 0f).put(o + 2, 0f);
                    }
                    b.put(o + 3, poseTexel[s][m.slotComponent(slot)][m.slotVariant(slot, v)]);
                }
            }
            b.position(0).limit(4 * n);
            return GlBuffer.of(t, GL_TEXTURE_BUFFER, b, GL_STATIC_DRAW);
        } finally {
            MemoryUtil.memFree((java.nio.Buffer) b);
        }
    }

    /**
     * The bend geometry for the resolve pass, one RGBA32F texel per component: its rest lean (world X,
     * Z, metres), its length (metres) and its pose scale ({@link BendGeometry}), with which the pass
     * turns the frame's deviations into pose coordinates and azimuths.
     */
    public static GlBuffer uploadBend(GlTracker t, BendGeometry g) {
        int n = Math.max(1, g.componentCount());
        FloatBuffer b = MemoryUtil.memAllocFloat(4 * n);
        try {
            for (int c = 0; c < g.componentCount(); c++) {
                b.put(4 * c, g.leanX(c)).put(4 * c + 1, g.leanZ(c)).put(4 * c + 2, g.length(c))
                        .put(4 * c + 3, g.poseScale(c));
            }
            b.position(0).limit(4 * n);
            return GlBuffer.of(t, GL_TEXTURE_BUFFER, b, GL_STATIC_DRAW);
        } finally {
            MemoryUtil.memFree((java.nio.Buffer) b);
        }
    }

    /**
     * Static links for the resolve pass, one RGBA32I texel per component: its parent component (-1
     * for a root), the texels between two poses of its table (3 per point), the texel offset within a
     * pose of its parent's point it sits on ({@link SpeciesModel#slotAttachPoint}; a root's own tip),
     * and its pose count.
     */
    public static GlBuffer uploadLinks(GlTracker t, World world) {
        int n = Math.max(1, world.componentCount());
        IntBuffer b = MemoryUtil.memAllocInt(4 * n);
        try {
            for (int p = 0; p < world.plantCount(); p++) {
                SpeciesModel m = world.plants().species().get(world.plantSpecies(p));
                int v = world.plantVariant(p);
                int first = world.firstComponent(p);
                for (int slot = 0; slot < m.slotCount(); slot++) {
                    PoseTable pt = m.slotPoseTable(slot, v);
                    int o = 4 * (first + slot);
                    int parent = m.slotParent(slot);
                    b.put(o, parent < 0 ? -1 : first + parent);
                    b.put(o + 1, 3 * pt.points());
                    // where it sits on its parent (texel offset within a parent pose); a ground slot's own tip
                    b.put(o + 2, 3 * (parent < 0 ? pt.points() - 1 : m.slotAttachPoint(slot)));
                    b.put(o + 3, pt.poses());
                }
            }
            b.position(0).limit(4 * n);
            return GlBuffer.of(t, GL_TEXTURE_BUFFER, b, GL_STATIC_DRAW);
        } finally {
            MemoryUtil.memFree((java.nio.Buffer) b);
        }
    }
}
