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
 * cached step coefficients of the dynamic-constraint spring (paper §4.2.1-4.2.2, eq. 5, resolved as
 * "The model" below states; see also docs/ARCHITECTURE.md, "The model").
 *
 * <h2>The model</h2>
 * Each component's deviation D (metres, 2D in the ground plane, the centre of mass's offset from its
 * rest position) obeys Barzel-Barr's constraint dynamics (eq. 1 with no torque) toward the elastic
 * equilibrium of eq. 4:
 * <pre>
 *   D'' + (2/tau) D' + (1/tau^2) (D - F/PC) = 0        i.e.  m D'' = F_c,
 *   F_c = -(2m/tau) v - (m/tau^2) (D - F/PC)            (eq. 3 with the constraint point moved to F/PC)
 * </pre>
 * a critically damped spring of natural frequency {@code omega = 1/tau} whose rest point is the
 * deviation {@code F/PC} at which the elastic force {@code PC D} of eq. 4 balances the external force
 * F. Hence:
 * <ul>
 * <li>{@code PC} (N/m, the component's stiffness) sets the equilibrium: a constant force F settles
 * at exactly {@code F/PC}, whatever the step;</li>
 * <li>{@code tau} (s, the component's response time, a species property, not the frame interval)
 * sets the speed: after release the deviation decays as {@code (1 + t/tau) e^(-t/tau)}, without
 * overshoot, within 2% of its start after 5.8 tau;</li>
 * <li>the mass m scales the constraint force {@code F_c = m D''} but cancels from the motion (as in
 * Barzel-Barr, whose constraint dynamics are mass-normalised); it shapes the rest pose through
 * gravity (§4.1) and is kept here for reports.</li>
 * </ul>
 * The force is the drag law of the field ({@link DragLaw}): {@code F = 0.5 rho dragArea |u| u}, so
 * the equilibrium deviation is {@code gain |u| u} with {@code gain = 0.5 rho dragArea / PC}.
 *
 * <h2>Closed form, sub-intervals and cached constants</h2>
 * A step of length h is split into S sub-intervals ({@link AnimationDef#subIntervals()}, §4.2.1).
 * Over a sub-interval of length s with the force held at its value at the sub-interval's middle
 * (linearly interpolated between the force at the start and at the end of the step), the exact
 * solution with {@code x = s/tau}, {@code E = e^-x} and {@code e = D - F/PC} is
 * <pre>
 *   e' = E (1 + x) e + E s v          v' = -E x/tau e + E (1 - x) v
 * </pre>
 * exact for any s, so the update is stable for every step and independent of frame rate up to the
 * O(s^2) error of interpolating the force. The map is linear, so the S sub-intervals compose into
 * one affine map per kind, computed once when the step length changes ({@link #prepare}):
 * <pre>
 *   D' = aDD D + aDv v + bD P0 + cD P1        v' = aVD D + aVv v + bV P0 + cV P1
 * </pre>
 * where P0 and P1 are the plant's {@code |u| u} at the start and end of the step. These eight
 * numbers are what eq. 5's cached constants {@code 1/mu} (the force gain, here bD + cD = 1 - aDD
 * times gain) and {@code 2m/(tau mu)} (the velocity gain, here aDv) become when the constraint
 * equation is integrated exactly rather than by the paper's one-step balance, whose equilibrium
 * {@code F/(PC + m/tau^2)} moved with the frame interval.
 *
 * <p>Build time allocates; {@link #prepare} and every accessor allocate nothing. Not thread-safe:
 * the stepping thread calls {@link #prepare} while the workers are idle; workers then only read.
 */
public final class SpringKinds {
    /** Coefficients per kind in {@link #coefficients(int, float[], int)}. */
    public static final int STRIDE = 8;

    private final int count;
    private final double[] stiffness;
    private final double[] responseTime;
    private final double[] mass;
    private final double[] dragArea;
    private final double[] gain;
    final float[] leanMag;
    final float[] invLength;
    final float[] poseScale;
    final float[] poseMax;
    final float[] maxBend;
    final float[] length;
    final int[] lodMask;
    final float[] coef;
    private final int[] springClass;
    private final int[] speciesBase;
    private final int[] speciesVariants;
    private double preparedStep = Double.NaN;
    private int preparedSub = -1;

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
        coef = new float[count * STRIDE];
        for (int k = 0; k < count; k++) {
            gain[k] = 0.5 * DragLaw.AIR_DENSITY * dragArea[k] / stiffness[k];
            // a floor on the lean keeps the rest heading defined for an upright component
            leanMag[k] = (float) Math.max(b.lean[k], 1e-4 * b.length[k]);
            invLength[k] = (float) (1 / b.length[k]);
            length[k] = (float) b.length[k];
            maxBend[k] = (float) b.maxBend[k];
            poseMax[k] = b.poses[k] - 1;
            poseScale[k] = (float) ((b.poses[k] - 1) / b.maxBend[k]);
        }
        springClass = new int[count];
        java.util.Map<java.util.List<Double>, Integer> classes = new java.util.HashMap<>();
        for (int k = 0; k < count; k++) {
            Integer prev = classes.putIfAbsent(java.util.List.of(responseTime[k], gain[k]), k);
            springClass[k] = prev != null ? prev : k;
        }
        this.speciesBase = speciesBase;
        this.speciesVariants = speciesVariants;
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
                            Math.abs(tip.x), t.maxBend(), t.poses(), mask);
                }
            }
        }
        return new SpringKinds(b, base, variants);
    }

    /**
     * {@return the kind of a species' component type in a shape variant (for kinds made by {@link #of})}
     *
     * @param species   species index, in the list given to {@link #of}
     * @param component component type index within the species
     * @param variant   shape variant, in [0, the species' variants)
     */
    public int kindOf(int species, int component, int variant) {
        return speciesBase[species] + component * speciesVariants[species] + variant;
    }

    /** {@return the number of kinds} */
    public int count() {
        return count;
    }

    /**
     * {@return the spring constant PC of kind k, N/m}
     *
     * @param k kind, in [0, count())
     */
    public double stiffness(int k) {
        return stiffness[k];
    }

    /**
     * {@return the response time tau of kind k, seconds}
     *
     * @param k kind, in [0, count())
     */
    public double responseTime(int k) {
        return responseTime[k];
    }

    /**
     * {@return the mass of kind k, kg (does not enter the motion; see the class comment)}
     *
     * @param k kind, in [0, count())
     */
    public double mass(int k) {
        return mass[k];
    }

    /**
     * {@return the drag coefficient times area of kind k, m^2}
     *
     * @param k kind, in [0, count())
     */
    public double dragArea(int k) {
        return dragArea[k];
    }

    /**
     * {@return the equilibrium deviation per unit {@code |u| u}: {@code 0.5 rho dragArea / PC}, m per (m/s)^2}
     *
     * @param k kind, in [0, count())
     */
    public double gain(int k) {
        return gain[k];
    }

    /**
     * {@return the rest lean of kind k: horizontal tip offset of the rest pose, metres (at least 1e-4 length)}
     *
     * @param k kind, in [0, count())
     */
    public float restLean(int k) {
        return leanMag[k];
    }

    /**
     * {@return the skeleton length of kind k, metres}
     *
     * @param k kind, in [0, count())
     */
    public float length(int k) {
        return length[k];
    }

    /**
     * {@return the bend of the last pose of kind k, radians}
     *
     * @param k kind, in [0, count())
     */
    public float maxBend(int k) {
        return maxBend[k];
    }

    /**
     * {@return the last pose coordinate (K - 1) of kind k}
     *
     * @param k kind, in [0, count())
     */
    public float poseMax(int k) {
        return poseMax[k];
    }

    /**
     * The spring class of kind k: the first kind with the same response time and gain (the only
     * constants the step coefficients depend on), so kinds of one class always have bit-identical
     * coefficients. The shape variants of one component type share their class.
     *
     * @param k kind, in [0, count())
     * @return the class's first kind, in [0, k]
     */
    public int springClass(int k) {
        return springClass[k];
    }

    /**
     * {@return a mask with bit l set when kind k is drawn (lodSegments &gt; 0) at level of detail l}
     *
     * @param k kind, in [0, count())
     */
    public int lodMask(int k) {
        return lodMask[k];
    }

    /** {@return the step length the coefficients were last prepared for, seconds (NaN before the first)} */
    public double preparedStep() {
        return preparedStep;
    }

    /**
     * Copies the cached coefficients of kind k, {@link #STRIDE} of them in the order aDD, aDv, bD, cD,
     * aVD, aVv, bV, cV (see the class comment), into {@code dest} from {@code offset}. Any thread
     * while no {@link #prepare} runs; no allocation.
     *
     * @param k      kind, in [0, count())
     * @param dest   where to write, at least {@code offset + STRIDE} long
     * @param offset first index written
     * @return {@code dest}
     * @throws IllegalArgumentException when k is out of range or dest is too short
     */
    public float[] coefficients(int k, float[] dest, int offset) {
        Require.range("k", k, 0, count - 1);
        Require.nonNull("dest", dest);
        if (offset < 0 || dest.length - offset < STRIDE) {
            throw new IllegalArgumentException("dest must hold " + STRIDE + " values from offset " + offset
                    + ", its length is " + dest.length);
        }
        System.arraycopy(coef, k * STRIDE, dest, offset, STRIDE);
        return dest;
    }

    /**
     * One cached coefficient of kind k (see {@link #coefficients(int, float[], int)}). No allocation.
     *
     * @param k kind, in [0, count())
     * @param i which, in [0, STRIDE): aDD, aDv, bD, cD, aVD, aVv, bV, cV
     * @return the coefficient (NaN-free after {@link #prepare}; 0 before)
     */
    public float coefficient(int k, int i) {
        Require.range("k", k, 0, count - 1);
        Require.range("i", i, 0, STRIDE - 1);
        return coef[k * STRIDE + i];
    }

    /**
     * Computes the step coefficients of every kind for steps of {@code step} seconds split into
     * {@code subIntervals}; does nothing when both are unchanged. Stepping thread, workers idle.
     * No allocation.
     *
     * @param step         seconds, in [1e-6, 10]
     * @param subIntervals in [1, 64]
     */
    public void prepare(double step, int subIntervals) {
        Require.range("step", step, 1e-6, 10);
        Require.range("subIntervals", subIntervals, 1, 64);
        if (step == preparedStep && subIntervals == preparedSub) {
            return;
        }
        for (int k = 0; k < count; k++) {
            compose(k, step, subIntervals);
        }
        preparedStep = step;
        preparedSub = subIntervals;
    }

    private void compose(int k, double h, int sub) {
        double tau = responseTime[k];
        double s = h / sub;
        double x = s / tau;
        double e = StrictMath.exp(-x);
        double p = e * (1 + x);
        double q = e * s;
        double r = -e * x / tau;
        double w = e * (1 - x);
        double uD = (1 - p) * gain[k];
        double uV = -r * gain[k];
        double m11 = 1;
        double m12 = 0;
        double m21 = 0;
        double m22 = 1;
        double bD = 0;
        double bV = 0;
        double cD = 0;
        double cV = 0;
        for (int i = 0; i < sub; i++) {
            double lambda = (i + 0.5) / sub;
            double n11 = p * m11 + q * m21;
            double n12 = p * m12 + q * m22;
            double n21 = r * m11 + w * m21;
            double n22 = r * m12 + w * m22;
            m11 = n11;
            m12 = n12;
            m21 = n21;
            m22 = n22;
            double nbD = p * bD + q * bV + uD * (1 - lambda);
            double nbV = r * bD + w * bV + uV * (1 - lambda);
            bD = nbD;
            bV = nbV;
            double ncD = p * cD + q * cV + uD * lambda;
            double ncV = r * cD + w * cV + uV * lambda;
            cD = ncD;
            cV = ncV;
        }
        int o = k * STRIDE;
        coef[o] = (float) m11;
        coef[o + 1] = (float) m12;
        coef[o + 2] = (float) bD;
        coef[o + 3] = (float) cD;
        coef[o + 4] = (float) m21;
        coef[o + 5] = (float) m22;
        coef[o + 6] = (float) bV;
        coef[o + 7] = (float) cV;
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
            Require.range("stiffness", stiffness, 1e-9, 1e6);
            Require.range("responseTime", responseTime, 1e-3, 10);
            Require.range("mass", mass, 1e-9, 10);
            Require.range("dragArea", dragArea, 0, 10);
            Require.range("length", length, 1e-6, 10);
            Require.range("restLean", restLean, 0, 10);
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
            return n++;
        }

        /** {@return the kinds added so far (kindOf is not available on these)} Allocates. */
        public SpringKinds build() {
            return new SpringKinds(this, new int[0], new int[0]);
        }
    }
}
