package org.jecosys.sim;

import org.joml.FrustumIntersection;

/**
 * The draw decision of a range of plants (paper §3.1.1 and §4.1, Table 3): the per-plant loop behind
 * {@link DrawDecision} (the workers' chunks, {@code decideAll}) and {@link ViewDecision}, with the
 * inputs of a call held here rather than passed one by one: the eye and the camera's level-of-detail
 * metric, the frustum and whether each plant is tested against it, the field's visibility and the
 * distance thinning. The world, the distance bands and the bounding radii are set at construction.
 * Each caller owns its own (one per chunk of the workers, one per view) and refills it before each
 * {@link #decide}; one thread at a time. Construction allocates; nothing after. Distances in metres.
 */
final class RangeDecision {
    private final World world;
    private final LevelBands bands;
    private final float[] radius;
    private boolean[] visible;
    private double ex;
    private double ey;
    private double ez;
    private double scale2 = 1;
    private double fixed2 = -1;
    private FrustumIntersection frustum;
    private boolean test;
    private double thinStart;
    private double thinEnd;
    private double thinMin = 1;

    /**
     * A decision over {@code world}'s plants with these bands (read at each decision, filled by their
     * owner) and per-species bounding radii ({@link DrawDecision#boundingRadius}). Build time.
     */
    RangeDecision(World world, LevelBands bands, float[] radius) {
        this.world = world;
        this.bands = bands;
        this.radius = radius;
    }

    /**
     * Sets the eye and the camera's level-of-detail metric ({@link org.jecosys.math.ViewLod}): 1 and
     * -1 for distances as they are. No allocation.
     *
     * @param x      eye X, metres
     * @param y      eye Y, metres
     * @param z      eye Z, metres
     * @param scale2 the metric's scale
     * @param fixed2 its fixed part, &lt; 0 for a perspective camera
     */
    void setEye(double x, double y, double z, double scale2, double fixed2) {
        ex = x;
        ey = y;
        ez = z;
        this.scale2 = scale2;
        this.fixed2 = fixed2;
    }

    /**
     * Sets the frustum the plants' bounding spheres are tested against when {@code test}; without the
     * test every sphere passes (the range's bases all lie inside the frustum). Kept, not copied.
     */
    void setFrustum(FrustumIntersection frustum, boolean test) {
        this.frustum = frustum;
        this.test = test;
    }

    /** Sets per plant whether the field found it visible (kept, not copied); null: every plant is. */
    void setVisible(boolean[] visible) {
        this.visible = visible;
    }

    /** Sets the distance thinning: start and end, metres, and the share kept from the end on (1: none). */
    void setThinning(double start, double end, double minFraction) {
        thinStart = start;
        thinEnd = end;
        thinMin = minFraction;
    }

    /** {@return per plant whether the field found it visible, as set; null for every plant} */
    boolean[] visible() {
        return visible;
    }

    /**
     * Whether, without the frustum test, every plant whose base lies in the box at {@code box[o]} (min
     * X, Y, Z, max X, Y, Z, metres) is, for its species, within the plain window of one level and
     * nearer than the thinning: then writes that level per species into {@code levels[u + s]}. The
     * box's nearest and farthest squared distances from the eye, widened by
     * {@link LevelBands#PLAIN_MARGIN}, bound every base's. No allocation.
     */
    boolean plainLevels(float[] box, int o, byte[] levels, int u) {
        if (test || !(box[o] <= box[o + 3])) {
            return false; // spheres to test, or no plant
        }
        double near2 = org.jecosys.math.Boxes.near2(box, o, ex, ey, ez) * (1 - LevelBands.PLAIN_MARGIN);
        double far2 = org.jecosys.math.Boxes.far2(box, o, ex, ey, ez) * (1 + LevelBands.PLAIN_MARGIN);
        if (!(far2 < unthinned2())) {
            return false;
        }
        double q2near = org.jecosys.math.ViewLod.equivalent2(near2, scale2, fixed2);
        double q2far = org.jecosys.math.ViewLod.equivalent2(far2, scale2, fixed2);
        for (int s = 0; s < bands.levels.length; s++) {
            double[] edge = bands.edges[s];
            int l = 0;
            while (l < bands.levels[s] - 1 && !(q2near < edge[l] * edge[l])) {
                l++;
            }
            double[] w = bands.plain[s];
            if (!(q2near >= w[2 * l] && q2far <= w[2 * l + 1])) {
                return false;
            }
            levels[u + s] = (byte) l;
        }
        return true;
    }

    /** The squared distance below which no plant is thinned (the thinning needs the distance itself). */
    private double unthinned2() {
        return thinMin < 1 ? LevelBands.below2(thinStart) : Double.POSITIVE_INFINITY;
    }

    /**
     * Decides plants {@code [p0, p1)} into {@code levelOut} and {@code keepOut}. A plant not visible
     * (when a visibility is set) or whose bounding sphere misses the frustum (when tested) is not drawn
     * (level -1, window 0); otherwise its level is where its equivalent distance
     * ({@link org.jecosys.math.ViewLod}) falls among the edges, with the next level too in a transition
     * band ({@link DrawDecision#keep(double[], int, int, double, double)}), and distance thinning by
     * its real distance. No allocation.
     */
    void decide(int p0, int p1, byte[] levelOut, int[] keepOut) {
        boolean thinned = thinMin < 1;
        double unthinned2 = unthinned2();
        for (int p = p0; p < p1; p++) {
            int s = world.plantSpecies(p);
            float x = world.plantX(p);
            float y = world.plantY(p);
            float z = world.plantZ(p);
            if ((visible != null && !visible[p]) || (test && !frustum.testSphere(x, y, z, radius[s]))) {
                levelOut[p] = -1;
                keepOut[p] = 0;
                continue;
            }
            double dx = x - ex;
            double dy = y - ey;
            double dz = z - ez;
            double d2 = dx * dx + dy * dy + dz * dz;
            double q2 = org.jecosys.math.ViewLod.equivalent2(d2, scale2, fixed2);
            int levels = bands.levels[s];
            double[] edge = bands.edges[s];
            int l = 0;
            while (l < levels - 1) {
                double e = edge[l];
                if (q2 < e * e) {
                    break;
                }
                l++;
            }
            double[] plain = bands.plain[s];
            if (q2 >= plain[2 * l] && q2 <= plain[2 * l + 1] && d2 < unthinned2) {
                // level l whole and alone, unthinned: what the window's arithmetic below gives there
                levelOut[p] = (byte) l;
                keepOut[p] = 255;
                continue;
            }
            double q = Math.sqrt(q2);
            double b = bands.band[s];
            int keep = DrawDecision.keep(edge, l, levels, q, b);
            if (l < levels - 1 && b > 0 && q > edge[l] - b) {
                keep |= DrawDecision.keep(edge, l + 1, levels, q, b) << 16;
            }
            if (thinned) {
                double d = q2 == d2 ? q : Math.sqrt(d2);
                if (d > thinStart) {
                    double r = (1 + DrawDecision.THIN_FADE) * DrawDecision.kept(d, thinStart, thinEnd, thinMin);
                    double a = (r - DrawDecision.thinRank(p)) / DrawDecision.THIN_FADE;
                    if (a < 1) {
                        keep = a * 255 < 0.5 ? 0 : DrawDecision.scaleKeep(keep, a);
                        if (keep == 0) {
                            levelOut[p] = -1;
                            keepOut[p] = 0;
                            continue;
                        }
                    }
                }
            }
            levelOut[p] = (byte) l;
            keepOut[p] = keep;
        }
    }
}
