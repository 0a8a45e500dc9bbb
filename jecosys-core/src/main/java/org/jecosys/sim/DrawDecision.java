package org.jecosys.sim;

import java.util.List;
import org.jecosys.field.ForceFieldDef;
import org.jecosys.math.Camera;
import org.jecosys.math.Rng;
import org.jecosys.math.Require;
import org.jecosys.plant.LodDef;
import org.jecosys.plant.SpeciesModel;
import org.joml.FrustumIntersection;
import org.joml.Matrix4f;

/**
 * The one visibility and level-of-detail decision of a frame (paper §3.1.1 and §4.1, Table 3),
 * published with the {@link Frame} for the renderer to draw as it is: a plant is drawn when the force
 * field found it visible (so it was animated this step) and its bounding sphere meets the view
 * frustum; it is drawn at the level its distance to the eye falls in, the same level the animation
 * updated it at (the same distance bands, {@link Simulation#setLodScale}, {@link
 * Simulation#setLodDistances}); and within {@link #transition()} metres before the end of its level
 * it is drawn at the next level too, each level keeping a complementary share of the screen-door
 * dither thresholds ({@link #keep}), so a plant crossing a band fades from one level to the next
 * instead of popping.
 *
 * <h2>Distance thinning</h2>
 * Optionally ({@link #setThinning}; the scene's {@code <field thinStart thinEnd thinMinFraction>}; off
 * by default, when frames are bit for bit those without it) fewer plants are drawn far away, to keep a
 * slow GPU usable: beyond {@link #thinStart()} the kept share {@link #thinKept(double)}
 * {@code k(d) = 1 - (1 - thinMinFraction) smoothstep(thinStart, thinEnd, d)} falls smoothly to
 * {@link #thinMinFraction()} at {@link #thinEnd()}. Each plant has a fixed rank h in [0, 1), a hash of
 * its index (so the same plants stay, whatever the camera and the thread count); with
 * {@code r = (1 + }{@link #THIN_FADE}{@code ) k(d)} a plant is drawn when {@code h < r}, and its dither
 * windows are scaled by {@code min(1, (r - h) / THIN_FADE)}: a plant leaving the kept set fades out over
 * a short distance instead of popping. The share of plants drawn at distance d is {@code min(1, r)}; a
 * renderer may widen far blades by {@code 1 / sqrt(k(d))} to keep the covered area.
 *
 * <p>In a simulation the animation workers make this decision for their own chunks of plants as they
 * animate them; {@code decideAll} makes it for a whole frame on one thread, for tools and tests that
 * build frames without the animation engine. Distances in metres.
 */
public final class DrawDecision {
    /** The transition band a decision starts with, metres (the scene schema's default lodTransition). */
    public static final double DEFAULT_TRANSITION = 1.0;

    static {
        org.jecosys.sim.internal.DecisionWriter.grant(new org.jecosys.sim.internal.DecisionWriter.Access() {
            @Override
            public void setTransition(DrawDecision d, double metres) {
                d.setTransition(metres);
            }

            @Override
            public void setThinning(DrawDecision d, double start, double end, double minFraction) {
                d.setThinning(start, end, minFraction);
            }

            @Override
            public Frame decideAll(DrawDecision d, Camera camera, Frame frame) {
                return d.decideAll(camera, frame);
            }
        });
    }

    /**
     * The width, as a share of the plants, of the rank band over which a plant thinned away fades out
     * (see the class comment).
     */
    public static final double THIN_FADE = 0.1;

    /** Where each species' levels end, metres, with any LOD scale applied. */
    interface Edges {
        /** {@return levels of species s} */
        int levels(int s);

        /** {@return where level l of species s ends, metres} */
        double edge(int s, int l);
    }

    private final World world;
    private final Edges edges;
    private final float[] radius;
    /** The bands of the step's decision: filled by {@link #prepare} on the stepping thread, read by the workers. */
    private final LevelBands stepBands;
    /** The bands of {@code decideAll}, its caller's own, and its range decision over them. */
    private final LevelBands allBands;
    private final RangeDecision all;
    private volatile double transition = DEFAULT_TRANSITION;
    /** start, end, min fraction: one array, swapped whole, so a decision never sees a mix. */
    private volatile double[] thinning = {ForceFieldDef.DEFAULT_THIN_START, ForceFieldDef.DEFAULT_THIN_END,
            ForceFieldDef.DEFAULT_THIN_MIN_FRACTION};
    private final Matrix4f viewProjection = new Matrix4f();
    private final Matrix4f projection = new Matrix4f();
    private final FrustumIntersection frustum = new FrustumIntersection();

    DrawDecision(World world, Edges edges) {
        this.world = world;
        this.edges = edges;
        List<SpeciesModel> species = world.plants().species();
        radius = new float[species.size()];
        for (int s = 0; s < radius.length; s++) {
            radius[s] = boundingRadius(species.get(s));
        }
        stepBands = new LevelBands(radius.length);
        stepBands.fill(edges, transition);
        allBands = new LevelBands(radius.length);
        all = new RangeDecision(world, allBands, radius);
    }

    /**
     * Takes the LOD edges and the transition band for the decisions of the next step (the workers'
     * {@link #decide}). Stepping thread, before the workers start; no allocation after the first.
     */
    void prepare() {
        stepBands.fill(edges, transition);
    }

    /**
     * A decision over a world with the distance bands of its species' definitions (no LOD scale), for
     * frames built without a simulation. Allocates.
     *
     * @param world the plants
     * @return a new decision with the default transition band ({@link #DEFAULT_TRANSITION})
     */
    public static DrawDecision of(World world) {
        Require.nonNull("world", world);
        List<SpeciesModel> species = world.plants().species();
        double[][] e = new double[species.size()][];
        for (int s = 0; s < e.length; s++) {
            List<LodDef> lods = species.get(s).def().lods();
            e[s] = new double[lods.size() - 1];
            for (int l = 0; l < e[s].length; l++) {
                e[s][l] = lods.get(l).maxDistance();
            }
        }
        return new DrawDecision(world, new Edges() {
            @Override
            public int levels(int s) {
                return e[s].length + 1;
            }

            @Override
            public double edge(int s, int l) {
                return e[s][l];
            }
        });
    }

    /**
     * The radius of a sphere around a plant's base that holds it in every pose: the longest
     * component chain (each component's longest pose-table skeleton plus its width) plus the
     * farthest ground offset of a component, metres.
     *
     * @param m the species
     * @return the radius, metres
     */
    public static float boundingRadius(SpeciesModel m) {
        double r = 0;
        double base = 0;
        for (int s = 0; s < m.slotCount(); s++) {
            base = Math.max(base, Math.hypot(m.slotBaseX(s), m.slotBaseZ(s)));
        }
        for (int c = 0; c < m.componentCount(); c++) {
            double longest = 0;
            for (int v = 0; v < m.component(c).variants(); v++) {
                longest = Math.max(longest, m.component(c).poseTable(v).length());
            }
            r += longest + Math.max(m.component(c).def().baseWidth(), m.component(c).def().tipWidth());
        }
        return (float) (r + base);
    }

    /** {@return the width of the band before each level's end over which two levels are dithered, metres} */
    public double transition() {
        return transition;
    }

    /**
     * Sets the transition band (the scene's {@code <render lodTransition>}); each species uses at
     * most the smallest gap between its own distances ({@link Simulation#setLodTransition} queues it;
     * tests reach it through {@code org.jecosys.sim.internal.DecisionWriter}). Any thread; takes effect
     * at the next decision.
     *
     * @param metres band width, in [0, 10]
     */
    void setTransition(double metres) {
        transition = Require.range("lodTransition", metres, 0, 10);
    }

    /**
     * Sets the distance thinning (the scene's {@code <field thinStart thinEnd thinMinFraction>}; see the
     * class comment; {@link Simulation#setThinning} queues it; tests reach it through
     * {@code DecisionWriter}). Any thread; takes effect at the next decision; allocates a small array.
     *
     * @param start       where thinning starts, metres, in [0, 1e6]
     * @param end         where the kept share reaches {@code minFraction}, metres, in [start, 1e6]
     * @param minFraction share of plants kept at and beyond {@code end}, in [0, 1]; 1 for no thinning
     * @throws IllegalArgumentException when out of range
     */
    void setThinning(double start, double end, double minFraction) {
        checkThinning(start, end, minFraction);
        thinning = new double[] {start, end, minFraction};
    }

    static void checkThinning(double start, double end, double minFraction) {
        Require.range("thinStart", start, 0, ForceFieldDef.MAX_LOD_DISTANCE);
        Require.range("thinEnd", end, start, ForceFieldDef.MAX_LOD_DISTANCE);
        Require.range("thinMinFraction", minFraction, 0, 1);
    }

    /** {@return where distance thinning starts, metres} Any thread. */
    public double thinStart() {
        return thinning[0];
    }

    /** {@return where the kept share reaches {@link #thinMinFraction()}, metres} Any thread. */
    public double thinEnd() {
        return thinning[1];
    }

    /** {@return the share of plants kept at and beyond {@link #thinEnd()}; 1 when thinning is off} Any thread. */
    public double thinMinFraction() {
        return thinning[2];
    }

    /**
     * The share of plants kept at distance {@code d}, in [thinMinFraction, 1]: 1 up to thinStart, falling
     * smoothly (smoothstep) to thinMinFraction at thinEnd. A renderer may widen the kept plants' thin
     * parts by {@code 1 / sqrt(thinKept(d))}. Any thread; no allocation.
     *
     * @param d distance to the eye, metres
     * @return the kept share
     */
    public double thinKept(double d) {
        double[] t = thinning;
        return kept(d, t[0], t[1], t[2]);
    }

    /** The kept share at distance d for a thinning from start to end down to min (see {@link #thinKept}). */
    static double kept(double d, double start, double end, double min) {
        if (min >= 1 || d <= start) {
            return 1;
        }
        double u = end > start ? Math.min(1, (d - start) / (end - start)) : 1;
        return 1 - (1 - min) * u * u * (3 - 2 * u);
    }

    /**
     * {@return plant p's fixed thinning rank, in [0, 1): a hash of its index} Any thread; no allocation.
     *
     * @param p plant index
     */
    public static double thinRank(int p) {
        return (Rng.mix(0x7A1E5EEDL ^ Rng.mix(p + 1L)) >>> 11) * 0x1.0p-53;
    }

    /**
     * {@return the bounding radius of a species' plants, metres (see {@link #boundingRadius})}
     *
     * @param species species index
     */
    public float radius(int species) {
        return radius[species];
    }

    /**
     * A range decision over this decision's world with the bands of the step ({@link #prepare}): a
     * worker's own, for {@link #decide}. Build time; allocates.
     */
    RangeDecision range() {
        return new RangeDecision(world, stepBands, radius);
    }

    /**
     * Decides plants {@code [p0, p1)} into {@code frame}: {@link Frame#drawLevel} and
     * {@link Frame#drawKeep}, with this step's thinning. Worker threads, each on its own range and
     * {@code range}; no allocation.
     *
     * @param range  the range's inputs, from {@link #range()}: the field's visibility, the camera's eye
     *               and LOD metric ({@link org.jecosys.math.ViewLod}), its frustum and whether to test
     *               each plant's bounding sphere against it (no test when the plants' bases all lie
     *               inside it, {@link #baseBoxes}, where every sphere passes)
     * @param box    the boxes of {@link #baseBoxes}; the range's is the six floats at {@code box[o]}
     * @param o      offset of the range's box
     * @param levels scratch of the range's own, one byte per species from {@code levels[u]}
     * @param u      offset of the range's scratch
     */
    void decide(RangeDecision range, int p0, int p1, float[] box, int o, byte[] levels, int u, Frame frame) {
        double[] thin = thinning;
        range.setThinning(thin[0], thin[1], thin[2]);
        if (range.plainLevels(box, o, levels, u)) {
            // the whole range in view and, for each species, within one level's plain window: the levels
            // and windows the per-plant arithmetic gives, without a distance per plant
            boolean[] visible = range.visible();
            byte[] levelOut = frame.drawLevel;
            int[] keepOut = frame.drawKeep;
            for (int p = p0; p < p1; p++) {
                boolean v = visible[p];
                levelOut[p] = v ? levels[u + world.plantSpecies(p)] : -1;
                keepOut[p] = v ? 255 : 0;
            }
            return;
        }
        range.decide(p0, p1, frame.drawLevel, frame.drawKeep);
    }

    /** {@return the number of species the decision knows} */
    int species() {
        return radius.length;
    }

    /**
     * The boxes round the bases of the plants of each range {@code [first[i], first[i + 1])}: six floats
     * per range (minimum X, Y, Z, then maximum), metres. When a frustum holds a range's box whole
     * ({@link FrustumIntersection#INSIDE}), every base in it is inside each plane, so every bounding sphere
     * (radius &gt; 0) passes the sphere test. Build time; allocates the array.
     *
     * @param first per range its first plant, plus the end of the last
     * @return the boxes
     */
    float[] baseBoxes(int[] first) {
        int n = first.length - 1;
        float[] box = new float[6 * n];
        for (int i = 0; i < n; i++) {
            float x0 = Float.POSITIVE_INFINITY;
            float y0 = Float.POSITIVE_INFINITY;
            float z0 = Float.POSITIVE_INFINITY;
            float x1 = Float.NEGATIVE_INFINITY;
            float y1 = Float.NEGATIVE_INFINITY;
            float z1 = Float.NEGATIVE_INFINITY;
            for (int p = first[i]; p < first[i + 1]; p++) {
                x0 = Math.min(x0, world.plantX(p));
                y0 = Math.min(y0, world.plantY(p));
                z0 = Math.min(z0, world.plantZ(p));
                x1 = Math.max(x1, world.plantX(p));
                y1 = Math.max(y1, world.plantY(p));
                z1 = Math.max(z1, world.plantZ(p));
            }
            int o = 6 * i;
            box[o] = x0;
            box[o + 1] = y0;
            box[o + 2] = z0;
            box[o + 3] = x1;
            box[o + 4] = y1;
            box[o + 5] = z1;
        }
        return box;
    }

    /**
     * Decides every plant of {@code frame} for {@code camera}, all taken as visible to the field:
     * for frames built without the animation engine (a renderer preview, tests). The caller's thread;
     * uses this object's own matrices, so one call at a time; no allocation.
     *
     * @param camera the viewer
     * @param frame  a frame of this decision's world
     * @return {@code frame}
     */
    Frame decideAll(Camera camera, Frame frame) {
        Require.nonNull("camera", camera);
        if (frame.plantCount() != world.plantCount()) {
            throw new IllegalArgumentException("frame has " + frame.plantCount() + " plants, the world "
                    + world.plantCount());
        }
        frustum.set(camera.viewProjection(viewProjection), true); // normalised planes for testSphere
        java.util.Arrays.fill(frame.plantVisible, true);
        double[] thin = thinning;
        allBands.fill(edges, transition);
        all.setVisible(frame.plantVisible);
        all.setEye(camera.x(), camera.y(), camera.z(), 1, -1);
        all.setFrustum(frustum, true);
        all.setThinning(thin[0], thin[1], thin[2]);
        all.decide(0, world.plantCount(), frame.drawLevel, frame.drawKeep);
        frame.setThinning(thinStart(), thinEnd(), thinMinFraction());
        // the distances are taken as meant for this camera's own lens: another camera drawing the
        // frame decides the same way relative to it
        double p11 = Math.abs(camera.projection(projection).m11());
        boolean perspective = projection.m23() != 0;
        frame.recordDecision(viewProjection, camera.x(), camera.y(), camera.z(), this, perspective && p11 > 0
                ? p11 : org.jecosys.math.ViewLod.referenceScale(ForceFieldDef.DEFAULT_LOD_FOV_Y));
        return frame;
    }

    /**
     * The packed dither window of level {@code l} for a plant at distance {@code d} (the core of
     * {@link RangeDecision#decide}): level l keeps
     * the bayer thresholds in {@code [handOver, received)} (both /255), where handOver is the share
     * already given to level l + 1 and received the share taken over from level l - 1; packed as
     * {@code 256 handOver + received}. The windows of neighbouring levels tile [0, 255] at every
     * distance. No allocation.
     *
     * @param s      species index
     * @param l      level
     * @param levels levels of the species
     * @param d      distance to the eye, metres
     * @param band   transition band of the species, metres
     * @return the packed window, in [0, 65535]
     */
    static int keep(double[] edge, int l, int levels, double d, double band) {
        double handOver = l < levels - 1 ? fade(d, edge[l], band) : 0;
        double received = l > 0 ? (d >= edge[l - 1] ? 1 : fade(d, edge[l - 1], band)) : 1;
        return 256 * (int) Math.round(handOver * 255) + (int) Math.round(received * 255);
    }

    /**
     * {@return the packed dither window of level l of species s at distance d, with this decision's
     * band (see {@link #keep(double[], int, int, double, double)})}
     *
     * @param s species index
     * @param l level
     * @param d distance to the eye, metres
     */
    public int keep(int s, int l, double d) {
        int levels = edges.levels(s);
        double band = Math.min(transition, LevelBands.minGap(edges, s, levels));
        double handOver = l < levels - 1 ? fade(d, edges.edge(s, l), band) : 0;
        double received = l > 0 ? (d >= edges.edge(s, l - 1) ? 1 : fade(d, edges.edge(s, l - 1), band)) : 1;
        return 256 * (int) Math.round(handOver * 255) + (int) Math.round(received * 255);
    }

    /**
     * Both packed dither windows of {@code keep} with their bounds scaled by {@code a}: the windows keep
     * tiling, now {@code [0, 255 a)}, so the plant keeps about a share {@code a} of its fragments; 0 when
     * nothing is left. No allocation.
     */
    static int scaleKeep(int keep, double a) {
        int lo = (int) Math.round(((keep >>> 8) & 0xFF) * a);
        int hi = (int) Math.round((keep & 0xFF) * a);
        int next = keep >>> 16;
        int out = lo < hi ? 256 * lo + hi : 0;
        if (next != 0) {
            int nlo = (int) Math.round(((next >>> 8) & 0xFF) * a);
            int nhi = (int) Math.round((next & 0xFF) * a);
            if (nlo < nhi) {
                out |= (256 * nlo + nhi) << 16;
            }
        }
        return out;
    }

    /** Fade across the band ending at {@code edge}: 0 before it, 1 at and beyond the edge. */
    static double fade(double d, double edge, double band) {
        if (band <= 0) {
            return d >= edge ? 1 : 0;
        }
        return Math.max(0, Math.min(1, (d - (edge - band)) / band));
    }

    /** {@return the number of species} */
    public int speciesCount() {
        return radius.length;
    }

    /**
     * {@return levels of species s}
     *
     * @param s species index
     */
    public int levels(int s) {
        return edges.levels(s);
    }

    /**
     * {@return where level l of species s ends, metres, with the LOD scale applied}
     *
     * @param s species index
     * @param l level, below the species' last
     */
    public double edge(int s, int l) {
        return edges.edge(s, l);
    }
}
