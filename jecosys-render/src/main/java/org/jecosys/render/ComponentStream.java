package org.jecosys.render;

import java.nio.FloatBuffer;
import java.util.List;
import org.jecosys.plant.PoseTable;
import org.jecosys.plant.SpeciesModel;
import org.jecosys.sim.Frame;
import org.jecosys.sim.World;
import org.joml.Vector3f;

/**
 * The GL-free per-frame component pass of plant rendering: once per drawn component (not once per
 * vertex, as the vertex shader used to) it resolves everything the vertex shader needs into two
 * RGBA32F texels, so the shader does 2 + 6 texel fetches per vertex and no
 * trigonometry, instead of walking the attachment chain (up to 4 parents, each with slot, bend and
 * two pose fetches) for every vertex. The texel stride between poses (3 x points) is per slot and
 * is baked into the mesh vertices instead.
 *
 * <p>Record of one component, 8 floats, in {@link PlantBatches#componentOffset} order (list after
 * list, plant after plant, slot after slot):
 * <ol>
 * <li>x, y, z: world position of the component's base, metres: the plant's base plus its rotated
 * ground offset, or the animated tip of its parent (which follows its own parent, ...), blended
 * between poses k and k + 1 and rotated by the parent's bend azimuth, exactly as before in the
 * shader;</li>
 * <li>cos of the component's bend azimuth (so the vertex shader evaluates no trigonometry);</li>
 * <li>the pose-buffer texel of (pose k, point 0) of its pose table, an integer held exactly in a
 * float (checked &lt; 2^24 at construction);</li>
 * <li>the blend weight w toward pose k + 1;</li>
 * <li>sin of the component's bend azimuth;</li>
 * <li>the dither window of this level, packed {@code 256 lo + hi} with lo, hi in 0..255 (/255):
 * the shader keeps fragments with {@code lo <= bayer < hi} (see {@code plant.frag}).</li>
 * </ol>
 *
 * <p>Render thread (or any single thread); {@link #write} allocates nothing. Pure function of the
 * world, the frame, the batches and the eye.
 */
public final class ComponentStream {
    /** Floats per component record. */
    public static final int FLOATS = 8;
    /** Largest texel index a float holds exactly. */
    static final int MAX_EXACT = 1 << 24;
    private static final int CHAIN = 4;

    private final World world;
    private final List<SpeciesModel> models;
    private final int[][][] poseTexel;
    private final Vector3f tip = new Vector3f();

    /**
     * @param world     the plants
     * @param poseTexel per species, component type and component variant: the first texel of that
     *                  pose table in the pose buffer (3 texels per point)
     */
    public ComponentStream(World world, int[][][] poseTexel) {
        this.world = world;
        this.models = world.plants().species();
        this.poseTexel = poseTexel;
    }

    /**
     * Writes the records of every listed plant's components for the last {@link PlantBatches#update}
     * into {@code dest} from 0, and flips it. No allocation.
     *
     * @param b     the batches, after their last {@link PlantBatches#update}
     * @param frame the animation frame the batches were updated with
     * @param ex    eye X, metres
     * @param ey    eye Y, metres
     * @param ez    eye Z, metres
     * @param dest  receives {@link #FLOATS} floats per listed component; cleared, then flipped
     */
    public void write(PlantBatches b, Frame frame, double ex, double ey, double ez, FloatBuffer dest) {
        dest.clear();
        for (int s = 0; s < b.speciesCount(); s++) {
            SpeciesModel m = models.get(s);
            int levels = b.levels(s);
            for (int l = 0; l < levels; l++) {
                int li = b.list(s, l);
                for (int i = 0, n = b.count(li); i < n; i++) {
                    int p = b.plant(li, i);
                    float px = world.plantX(p);
                    float py = world.plantY(p);
                    float pz = world.plantZ(p);
                    double dx = px - ex;
                    double dy = py - ey;
                    double dz = pz - ez;
                    float keep = keep(b, s, l, levels, Math.sqrt(dx * dx + dy * dy + dz * dz));
                    writePlant(m, s, p, px, py, pz, keep, frame, dest);
                }
            }
        }
        dest.flip();
    }

    private void writePlant(SpeciesModel m, int s, int p, float px, float py, float pz, float keep, Frame frame,
                            FloatBuffer dest) {
        int v = world.plantVariant(p);
        double rest = world.plantRestAzimuth(p);
        double rc = Math.cos(rest);
        double rs = Math.sin(rest);
        int first = world.firstComponent(p);
        for (int slot = 0, slots = m.slotCount(); slot < slots; slot++) {
            // base: walk up the attachment chain (at most CHAIN deep, as the shader did)
            float bx = 0;
            float by = 0;
            float bz = 0;
            int at = slot;
            for (int depth = 0; depth < CHAIN; depth++) {
                int parent = m.slotParent(at);
                if (parent < 0) {
                    double ox = m.slotBaseX(at);
                    double oz = m.slotBaseZ(at);
                    bx += (float) (ox * rc - oz * rs);
                    bz += (float) (ox * rs + oz * rc);
                    break;
                }
                PoseTable pt = m.slotPoseTable(parent, v);
                int pc = first + parent;
                pt.blendedPosition(frame.poseCoord(pc), pt.points() - 1, tip);
                float a = frame.bendAzimuth(pc);
                float c = (float) Math.cos(a);
                float sn = (float) Math.sin(a);
                bx += tip.x * c - tip.z * sn;
                by += tip.y;
                bz += tip.x * sn + tip.z * c;
                at = parent;
            }
            int comp = first + slot;
            PoseTable pt = m.slotPoseTable(slot, v);
            int poses = pt.poses();
            float coord = Math.max(0f, Math.min(poses - 1, frame.poseCoord(comp)));
            int k = Math.min((int) coord, poses - 2);
            int stride = 3 * pt.points();
            int texel = poseTexel[s][m.slotComponent(slot)][m.slotVariant(slot, v)] + k * stride;
            float a = frame.bendAzimuth(comp);
            dest.put(px + bx).put(py + by).put(pz + bz).put((float) Math.cos(a))
                    .put(texel).put(coord - k).put((float) Math.sin(a)).put(keep);
        }
    }

    /**
     * The packed dither window of level {@code l} for a plant at distance {@code d}: level l keeps
     * {@code [handOver, received)} of the bayer thresholds, where handOver is the share already given
     * to level l + 1 and received the share taken over from level l - 1.
     */
    static float keep(PlantBatches b, int s, int l, int levels, double d) {
        double band = b.bandWidth(s);
        double handOver = l < levels - 1 ? fade(d, b.edge(s, l), band) : 0;
        double received = l > 0 ? (d >= b.edge(s, l - 1) ? 1 : fade(d, b.edge(s, l - 1), band)) : 1;
        return 256 * Math.round(handOver * 255) + Math.round(received * 255);
    }

    /** Fade across the band ending at {@code edge}: 0 before it, 1 at and beyond the edge. */
    static double fade(double d, double edge, double band) {
        if (band <= 0) {
            return d >= edge ? 1 : 0;
        }
        return Math.max(0, Math.min(1, (d - (edge - band)) / band));
    }
}
