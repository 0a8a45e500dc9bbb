package org.jecosys.anim;

import java.util.Arrays;
import java.util.List;
import org.jecosys.field.DragLaw;
import org.jecosys.math.Require;
import org.jecosys.plant.ComponentDef;
import org.jecosys.plant.PlantComponent;
import org.jecosys.plant.PoseTable;
import org.jecosys.plant.SpeciesModel;
import org.joml.Vector3f;

/**
 * The constants of every component <em>kind</em> (species x component type x shape variant) and the
 * cached coefficients of one step of the dynamic-constraint spring (paper §4.2.1-4.2.2, eq. 5): each
 * component's deviation D follows a critically damped spring of response time tau toward the rest
 * point F/PC, stiffened smoothly toward the bend limit, integrated exactly for a force linear over the
 * step, with a switch inside a step honoured at the next sub-interval boundary, and with
 * {@link #RESPONSE_VARIANTS} response-time rows per kind. The equations and their derivation are in
 * docs/model.md, "The dynamic-constraint spring".
 *
 * <p>Build time allocates; {@link #prepare} and every accessor allocate nothing. Not thread-safe:
 * the stepping thread calls {@link #prepare} while the workers are idle; workers then only read.
 */
public final class SpringKinds implements KindsView {
    /** Coefficients per kind in {@link #coefficients(int, float[], int)}. */
    public static final int STRIDE = 8;
    /** Response-time variants (coefficient rows) per kind; see the class comment. */
    public static final int RESPONSE_VARIANTS = 9;
    /** The variant whose response time is the kind's own tau. */
    public static final int NOMINAL_VARIANT = 4;
    /** Where the stiffening starts, as a fraction of the bend limit dMax (see the class comment). */
    public static final float KNEE = 0.5f;

    private final int count;
    private final double[] stiffness;
    private final double[] responseTime;
    private final double[] mass;
    private final double[] dragArea;
    private final double[] gain;
    private final double[] responseVariation;
    final float[] leanMag;
    final float[] invLength;
    final float[] poseScale;
    final float[] poseMax;
    final float[] maxBend;
    final float[] length;
    final int[] lodMask;
    /** Per kind, {@code l sin(maxBend)}: the tip offset of the last pose with the length kept, metres. */
    final float[] dMax;
    /** Coefficient rows, {@link #STRIDE} per row, row {@code k * RESPONSE_VARIANTS + v}. */
    final float[] coef;
    private final int[] springClass;
    private final int[] speciesBase;
    private final int[] speciesVariants;
    private double preparedStep = Double.NaN;
    private int preparedSub = -1;
    private int preparedEdge = -1;

    private SpringKinds(Builder b, int[] speciesBase, int[] speciesVariants) {
        count = b.n;
        stiffness = Arrays.copyOf(b.stiffness, count);
        responseTime = Arrays.copyOf(b.responseTime, count);
        mass = Arrays.copyOf(b.mass, count);
        dragArea = Arrays.copyOf(b.dragArea, count);
        gain = new double[count];
        leanMag = new float[count];
        invLength = new float[count];
        poseScale = new float[count];
        poseMax = new float[count];
        maxBend = new float[count];
        length = new float[count];
        lodMask = Arrays.copyOf(b.lodMask, count);
        responseVariation = Arrays.copyOf(b.responseVariation, count);
        dMax = new float[count];
        coef = new float[count * RESPONSE_VARIANTS * STRIDE];
        for (int k = 0; k < count; k++) {
            gain[k] = 0.5 * DragLaw.AIR_DENSITY * dragArea[k] / stiffness[k];
            // a floor on the lean keeps the rest heading defined for an upright component
            leanMag[k] = (float) Math.max(b.lean[k], 1e-4 * b.length[k]);
            invLength[k] = (float) (1 / b.length[k]);
            length[k] = (float) b.length[k];
            maxBend[k] = (float) b.maxBend[k];
            poseMax[k] = b.poses[k] - 1;
            poseScale[k] = (float) ((b.poses[k] - 1) / b.maxBend[k]);
            dMax[k] = (float) (b.length[k] * Math.sin(b.maxBend[k]));
        }
        springClass = new int[count];
        java.util.Map<java.util.List<Double>, Integer> classes = new java.util.HashMap<>();
        for (int k = 0; k < count; k++) {
            Integer prev = classes.putIfAbsent(java.util.List.of(responseTime[k], gain[k], responseVariation[k]), k);
            springClass[k] = prev != null ? prev : k;
        }
        this.speciesBase = speciesBase;
        this.speciesVariants = speciesVariants;
    }

    /** A copy of {@code o}: its per-kind constants shared (they never change), its coefficients copied. */
    private SpringKinds(SpringKinds o) {
        count = o.count;
        stiffness = o.stiffness;
        responseTime = o.responseTime;
        mass = o.mass;
        dragArea = o.dragArea;
        gain = o.gain;
        responseVariation = o.responseVariation;
        leanMag = o.leanMag;
        invLength = o.invLength;
        poseScale = o.poseScale;
        poseMax = o.poseMax;
        maxBend = o.maxBend;
        length = o.length;
        lodMask = o.lodMask;
        dMax = o.dMax;
        coef = o.coef.clone();
        springClass = o.springClass;
        speciesBase = o.speciesBase;
        speciesVariants = o.speciesVariants;
        preparedStep = o.preparedStep;
        preparedSub = o.preparedSub;
        preparedEdge = o.preparedEdge;
    }

    /**
     * The same kinds with their own coefficients and preparation (copied as this one is prepared
     * now), sharing the per-kind constants, which never change: what {@link #of} and {@link #prepare}
     * would give again for the same species, without rebuilding or recomputing them. Many simulations
     * of one species list (an open world's tiles) each take a copy of one prepared instance. Any
     * thread while no thread prepares this one; allocates the coefficient rows
     * ({@code count() * RESPONSE_VARIANTS * STRIDE} floats).
     *
     * @return the copy
     */
    public SpringKinds copy() {
        return new SpringKinds(this);
    }

    /**
     * The kinds of a scene's species: kind {@link #kindOf}{@code (s, c, v)} for species s, component
     * type c and shape variant v. The rest lean of a kind is the horizontal tip offset of its pose 0
     * (the gravity-bent rest shape, local +X). Build time; allocates.
     *
     * @param species the scene's built species, in scene order
     * @return the kinds, species by species, component type by component type, variant by variant
     */
    public static SpringKinds of(List<SpeciesModel> species) {
        Require.nonNull("species", species);
        Builder b = new Builder();
        int[] base = new int[species.size()];
        int[] variants = new int[species.size()];
        Vector3f tip = new Vector3f();
        for (int s = 0; s < species.size(); s++) {
            SpeciesModel sm = species.get(s);
            base[s] = b.n;
            variants[s] = sm.variants();
            for (int c = 0; c < sm.componentCount(); c++) {
                PlantComponent cm = sm.component(c);
                ComponentDef d = cm.def();
                int mask = 0;
                for (int l = 0; l < d.lodSegments().size(); l++) {
                    mask |= d.lodSegments().get(l) > 0 ? 1 << l : 0;
                }
                for (int v = 0; v < sm.variants(); v++) {
                    PoseTable t = cm.poseTable(v);
                    t.position(0, t.points() - 1, tip);
                    b.add(cm.stiffness(), cm.responseTime(), cm.mass(v), cm.dragArea(), cm.length(v),
                            Math.abs(tip.x), t.maxBend(), t.poses(), mask, sm.def().variation().responseTime());
                }
            }
        }
        return new SpringKinds(b, base, variants);
    }

    // the accessors of KindsView, documented there (units, ranges, the coefficients' order)

    @Override
    public int kindOf(int species, int component, int variant) {
        return speciesBase[species] + component * speciesVariants[species] + variant;
    }

    @Override
    public int count() {
        return count;
    }

    @Override
    public double stiffness(int k) {
        return stiffness[k];
    }

    @Override
    public double responseTime(int k) {
        return responseTime[k];
    }

    @Override
    public double mass(int k) {
        return mass[k];
    }

    @Override
    public double dragArea(int k) {
        return dragArea[k];
    }

    @Override
    public double gain(int k) {
        return gain[k];
    }

    @Override
    public float restLean(int k) {
        return leanMag[k];
    }

    @Override
    public float length(int k) {
        return length[k];
    }

    @Override
    public float maxBend(int k) {
        return maxBend[k];
    }

    @Override
    public float poseMax(int k) {
        return poseMax[k];
    }

    @Override
    public int springClass(int k) {
        return springClass[k];
    }

    @Override
    public int lodMask(int k) {
        return lodMask[k];
    }

    @Override
    public float bendLimit(int k) {
        return dMax[k];
    }

    @Override
    public double responseVariation(int k) {
        return responseVariation[k];
    }

    @Override
    public double responseTime(int k, int v) {
        return responseTime[k] * (1 + responseVariation[k] * (v - NOMINAL_VARIANT) / NOMINAL_VARIANT);
    }

    @Override
    public double preparedStep() {
        return preparedStep;
    }

    @Override
    public float[] coefficients(int k, float[] dest, int offset) {
        Require.range("k", k, 0, count - 1);
        Require.nonNull("dest", dest);
        if (offset < 0 || dest.length - offset < STRIDE) {
            throw new IllegalArgumentException("dest must hold " + STRIDE + " values from offset " + offset
                    + ", its length is " + dest.length);
        }
        System.arraycopy(coef, row(k, NOMINAL_VARIANT) * STRIDE, dest, offset, STRIDE);
        return dest;
    }

    @Override
    public float coefficient(int k, int i) {
        return coefficient(k, NOMINAL_VARIANT, i);
    }

    @Override
    public float coefficient(int k, int v, int i) {
        Require.range("k", k, 0, count - 1);
        Require.range("v", v, 0, RESPONSE_VARIANTS - 1);
        Require.range("i", i, 0, STRIDE - 1);
        return coef[row(k, v) * STRIDE + i];
    }

    /** The coefficient row of kind k in response variant v. */
    static int row(int k, int v) {
        return k * RESPONSE_VARIANTS + v;
    }

    /**
     * Computes the step coefficients of every kind for steps of {@code step} seconds with a force
     * linear over the step (no switch inside it); does nothing when nothing changed. Stepping thread,
     * workers idle. No allocation.
     *
     * @param step         seconds, in [1e-6, 10]
     * @param subIntervals in [1, 64]
     */
    public void prepare(double step, int subIntervals) {
        prepare(step, subIntervals, -1);
    }

    /**
     * Computes the step coefficients of every kind and response variant for steps of {@code step}
     * seconds split into {@code subIntervals}, with a switch of the force at sub-interval boundary
     * {@code edge} (the force is the start's before it and the end's from it), or none for -1 (the
     * force linear over the step); see the class comment. Does nothing when all three are unchanged.
     * Stepping thread, workers idle. No allocation.
     *
     * @param step         seconds, in [1e-6, 10]
     * @param subIntervals in [1, 64]
     * @param edge         -1, or the boundary of the switch, in [0, subIntervals]
     * @throws IllegalArgumentException when a value is out of range
     */
    public void prepare(double step, int subIntervals, int edge) {
        Require.range("step", step, 1e-6, 10);
        Require.range("subIntervals", subIntervals, 1, 64);
        Require.range("edge", edge, -1, subIntervals);
        if (step == preparedStep && subIntervals == preparedSub && edge == preparedEdge) {
            return;
        }
        for (int k = 0; k < count; k++) {
            for (int v = 0; v < RESPONSE_VARIANTS; v++) {
                compose(k, v, step, subIntervals, edge);
            }
        }
        preparedStep = step;
        preparedSub = subIntervals;
        preparedEdge = edge;
    }

    /**
     * The sub-interval boundary at which a switch at wind time {@code edgeTime} takes effect in the
     * step that ends at {@code stepEnd}: the first boundary at or after it, allowing for rounding of
     * the accumulated time (a millionth of a sub-interval), clamped to [0, subIntervals]; -1 when
     * {@code edgeTime} is NaN (no switch). Any thread; no allocation.
     *
     * @param edgeTime     seconds, or NaN
     * @param stepEnd      seconds, the time at the end of the step
     * @param step         the step length, seconds, &gt; 0
     * @param subIntervals in [1, 64]
     * @return -1 or the boundary, in [0, subIntervals]
     */
    public static int edgeBoundary(double edgeTime, double stepEnd, double step, int subIntervals) {
        if (Double.isNaN(edgeTime)) {
            return -1;
        }
        double s = step / subIntervals;
        double i = Math.ceil((edgeTime - (stepEnd - step)) / s - 1e-6);
        return (int) Math.max(0, Math.min(subIntervals, i));
    }

    private void compose(int k, int v, double h, int sub, int edge) {
        SpringStep.coefficients(responseTime(k, v), h, sub, edge, coef, row(k, v) * STRIDE);
    }

    /** Collects kinds one by one (tests, games with their own components). Build time; allocates. */
    public static final class Builder {
        private int n;
        private double[] stiffness = new double[8];
        private double[] responseTime = new double[8];
        private double[] mass = new double[8];
        private double[] dragArea = new double[8];
        private double[] length = new double[8];
        private double[] lean = new double[8];
        private double[] maxBend = new double[8];
        private int[] poses = new int[8];
        private int[] lodMask = new int[8];
        private double[] responseVariation = new double[8];

        /** An empty builder, room for 8 kinds before it grows (doubling). Allocates. */
        public Builder() {
        }

        /**
         * Adds a kind; returns its index.
         *
         * @param stiffness    PC, N/m, in [1e-9, 1e6]
         * @param responseTime tau, seconds, in [1e-3, 10]
         * @param mass         kg, in [1e-9, 10]
         * @param dragArea     m^2, in [0, 10]
         * @param length       skeleton length, metres, in [1e-6, 10]
         * @param restLean     horizontal tip offset of the rest pose, metres, in [0, 10]
         * @param maxBend      bend of the last pose, radians, in [1e-3, pi/2]
         * @param poses        pose count K, in [2, 64]
         * @param lodMask      bit l set when drawn at level l
         * @return the new kind's index
         * @throws IllegalArgumentException when a value is out of range or there are already
         *                                  {@code Short.MAX_VALUE} kinds
         */
        public int add(double stiffness, double responseTime, double mass, double dragArea, double length,
                       double restLean, double maxBend, int poses, int lodMask) {
            return add(stiffness, responseTime, mass, dragArea, length, restLean, maxBend, poses, lodMask, 0);
        }

        /** Smallest scale of a variant's length (1 - the largest variation), with a margin for rounding. */
        private static final double VARIANT_MIN = (1 - org.jecosys.plant.VariationDef.MAX_FRACTION) * (1 - 1e-9);
        /** Largest scale of a variant's length (1 + the largest variation), with a margin for rounding. */
        private static final double VARIANT_MAX = (1 + org.jecosys.plant.VariationDef.MAX_FRACTION) * (1 + 1e-9);

        /**
         * Adds a kind whose response time varies from plant to plant (see the class comment); returns
         * its index.
         *
         * @param stiffness         PC, N/m, in [1e-9, 1e6]
         * @param responseTime      tau, seconds, in [1e-3, 10]
         * @param mass              kg, the def's range widened by the variation: [1e-11, 36.1]
         * @param dragArea          m^2, in [0, 10]
         * @param length            skeleton length, metres, the def's range widened by the variation:
         *                          [1e-7, 19]
         * @param restLean          horizontal tip offset of the rest pose, metres, in [0, 19]
         * @param maxBend           bend of the last pose, radians, in [1e-3, pi/2]
         * @param poses             pose count K, in [2, 64]
         * @param lodMask           bit l set when drawn at level l
         * @param responseVariation relative response-time variation between plants, in [0, 0.9]
         * @return the new kind's index
         * @throws IllegalArgumentException when a value is out of range or there are already
         *                                  {@code Short.MAX_VALUE} kinds
         */
        public int add(double stiffness, double responseTime, double mass, double dragArea, double length,
                       double restLean, double maxBend, int poses, int lodMask, double responseVariation) {
            Require.range("responseVariation", responseVariation, 0, 0.9);
            Require.range("stiffness", stiffness, 1e-9, 1e6);
            Require.range("responseTime", responseTime, 1e-3, 10);
            // a kind is one shape variant: its length is the def's times up to 1 +- the largest variation
            // (org.jecosys.plant.VariationDef), its mass that squared
            Require.range("mass", mass, VARIANT_MIN * VARIANT_MIN * org.jecosys.plant.ComponentDef.MIN_MASS,
                    VARIANT_MAX * VARIANT_MAX * org.jecosys.plant.ComponentDef.MAX_MASS);
            Require.range("dragArea", dragArea, 0, 10);
            Require.range("length", length, VARIANT_MIN * org.jecosys.plant.ComponentDef.MIN_LENGTH,
                    VARIANT_MAX * org.jecosys.plant.ComponentDef.MAX_LENGTH);
            Require.range("restLean", restLean, 0, VARIANT_MAX * org.jecosys.plant.ComponentDef.MAX_LENGTH);
            Require.range("maxBend", maxBend, 1e-3, Math.PI / 2);
            Require.range("poses", poses, 2, 64);
            if (n == Short.MAX_VALUE) {
                throw new IllegalArgumentException("at most " + Short.MAX_VALUE + " component kinds");
            }
            if (n == this.stiffness.length) {
                int c = n * 2;
                this.stiffness = Arrays.copyOf(this.stiffness, c);
                this.responseTime = Arrays.copyOf(this.responseTime, c);
                this.mass = Arrays.copyOf(this.mass, c);
                this.dragArea = Arrays.copyOf(this.dragArea, c);
                this.length = Arrays.copyOf(this.length, c);
                this.lean = Arrays.copyOf(this.lean, c);
                this.maxBend = Arrays.copyOf(this.maxBend, c);
                this.poses = Arrays.copyOf(this.poses, c);
                this.lodMask = Arrays.copyOf(this.lodMask, c);
                this.responseVariation = Arrays.copyOf(this.responseVariation, c);
            }
            this.stiffness[n] = stiffness;
            this.responseTime[n] = responseTime;
            this.mass[n] = mass;
            this.dragArea[n] = dragArea;
            this.length[n] = length;
            this.lean[n] = restLean;
            this.maxBend[n] = maxBend;
            this.poses[n] = poses;
            this.lodMask[n] = lodMask;
            this.responseVariation[n] = responseVariation;
            return n++;
        }

        /** {@return the kinds added so far (kindOf is not available on these)} Allocates. */
        public SpringKinds build() {
            return new SpringKinds(this, new int[0], new int[0]);
        }
    }
}
