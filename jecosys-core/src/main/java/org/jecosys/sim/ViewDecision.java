package org.jecosys.sim;

import java.util.Arrays;
import org.jecosys.math.Camera;
import org.jecosys.math.Require;
import org.jecosys.math.ViewLod;
import org.joml.FrustumIntersection;
import org.joml.Matrix4f;

/**
 * The visibility and level-of-detail decision of one frame for any camera (paper §3.1.1 and §4.1):
 * what {@link DrawDecision} decides for the camera a step followed, made here for another view (a
 * second player, a minimap, a shadow map's light, the first frame after a camera cut), with the
 * edges, transition band, distance thinning and LOD lens the frame recorded, levels picked by
 * projected size ({@link ViewLod}). Every plant in the view's frustum is drawn, animated in that step
 * or not: the frame holds every plant's last state ({@link Frame#renderStates()}).
 *
 * <p>Culling is hierarchical: the plants, in the world's Morton order, are cut into blocks of
 * {@link #BLOCK} neighbours with a bounding box each; a block outside the frustum is skipped whole,
 * a block inside it needs no test per plant. One object per renderer; the caller's thread (the render
 * thread), one call at a time. Construction allocates; {@link #decide} allocates nothing.
 */
public final class ViewDecision {
    /** Plants per culling block. */
    public static final int BLOCK = 64;

    private final World world;
    private final float[] radius;
    private final byte[] level;
    private final int[] keep;
    private final float[] box; // per block: minX, minY, minZ, maxX, maxY, maxZ
    private final int blocks;
    private final Matrix4f viewProjection = new Matrix4f();
    private final Matrix4f projection = new Matrix4f();
    private final FrustumIntersection frustum = new FrustumIntersection();
    private final double[] metric = new double[2];
    private final FrameEdges edges = new FrameEdges();
    private final LevelBands bands;
    private final RangeDecision range;
    private int drawn;
    private int unanimated;

    /** The edges a frame recorded, read through {@link DrawDecision.Edges}. */
    private static final class FrameEdges implements DrawDecision.Edges {
        Frame frame;

        @Override
        public int levels(int s) {
            return frame.lodEdgeCount(s) + 1;
        }

        @Override
        public double edge(int s, int l) {
            return frame.lodEdge(s, l);
        }
    }

    /**
     * A decision over a world's plants. Build time; allocates a level and a window per plant.
     *
     * @param world the plants
     */
    public ViewDecision(World world) {
        this.world = Require.nonNull("world", world);
        java.util.List<org.jecosys.plant.SpeciesModel> species = world.plants().species();
        radius = new float[species.size()];
        for (int s = 0; s < radius.length; s++) {
            radius[s] = DrawDecision.boundingRadius(species.get(s));
        }
        bands = new LevelBands(radius.length);
        range = new RangeDecision(world, bands, radius);
        int plants = world.plantCount();
        level = new byte[plants];
        keep = new int[plants];
        blocks = (plants + BLOCK - 1) / BLOCK;
        box = new float[6 * blocks];
        for (int b = 0; b < blocks; b++) {
            float[] bb = {Float.MAX_VALUE, Float.MAX_VALUE, Float.MAX_VALUE, -Float.MAX_VALUE, -Float.MAX_VALUE,
                -Float.MAX_VALUE};
            for (int p = b * BLOCK, e = Math.min(plants, p + BLOCK); p < e; p++) {
                float r = radius[world.plantSpecies(p)];
                bb[0] = Math.min(bb[0], world.plantX(p) - r);
                bb[1] = Math.min(bb[1], world.plantY(p) - r);
                bb[2] = Math.min(bb[2], world.plantZ(p) - r);
                bb[3] = Math.max(bb[3], world.plantX(p) + r);
                bb[4] = Math.max(bb[4], world.plantY(p) + r);
                bb[5] = Math.max(bb[5], world.plantZ(p) + r);
            }
            System.arraycopy(bb, 0, box, 6 * b, 6);
        }
    }

    /**
     * Decides every plant of the world for {@code camera}, with what {@code frame} recorded (its LOD
     * edges, transition band, thinning and lens), into this object's {@link #levels()} and
     * {@link #keeps()}. No allocation.
     *
     * @param frame  a frame of this world, published by a simulation (or decided by
     *               {@code DrawDecision.decideAll})
     * @param camera the view
     * @throws IllegalArgumentException when the frame is of another world's size
     */
    public void decide(Frame frame, Camera camera) {
        if (frame.plantCount() != world.plantCount()) {
            throw new IllegalArgumentException("frame has " + frame.plantCount() + " plants, the world "
                    + world.plantCount());
        }
        edges.frame = frame;
        frustum.set(camera.viewProjection(viewProjection), true);
        ViewLod.metric(camera, frame.lodReference(), projection, metric);
        range.setEye(camera.x(), camera.y(), camera.z(), metric[0], metric[1]);
        range.setThinning(frame.thinStart(), frame.thinEnd(), frame.thinMinFraction());
        bands.fill(edges, frame.lodTransition());
        int plants = world.plantCount();
        int n = 0;
        int still = 0;
        boolean[] animated = frame.plantVisible;
        for (int b = 0; b < blocks; b++) {
            int p0 = b * BLOCK;
            int p1 = Math.min(plants, p0 + BLOCK);
            int o = 6 * b;
            int res = frustum.intersectAab(box[o], box[o + 1], box[o + 2], box[o + 3], box[o + 4], box[o + 5]);
            if (res != FrustumIntersection.INSIDE && res != FrustumIntersection.INTERSECT) {
                Arrays.fill(level, p0, p1, (byte) -1);
                Arrays.fill(keep, p0, p1, 0);
                continue;
            }
            range.setFrustum(frustum, res == FrustumIntersection.INTERSECT);
            range.decide(p0, p1, level, keep);
            for (int p = p0; p < p1; p++) {
                if (level[p] >= 0) {
                    n++;
                    still += animated[p] ? 0 : 1;
                }
            }
        }
        drawn = n;
        unanimated = still;
        edges.frame = null;
    }

    /**
     * {@return per plant, the level of detail the last {@link #decide} draws it at, or -1: this
     * object's own array, read it, do not change it}
     */
    public byte[] levels() {
        return level;
    }

    /**
     * {@return per plant, the packed dither windows of the last {@link #decide} (as
     * {@link Frame#drawKeep}): this object's own array, read it, do not change it}
     */
    public int[] keeps() {
        return keep;
    }

    /** {@return the plants the last {@link #decide} draws} */
    public int drawn() {
        return drawn;
    }

    /**
     * {@return the plants the last {@link #decide} draws that the frame's step did not animate (on no
     * visible force-field node of any view it followed, {@link Frame#plantVisible}): they stand still
     * until the camera is registered with {@code Simulation.addView}}
     */
    public int unanimated() {
        return unanimated;
    }
}
