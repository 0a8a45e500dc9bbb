package org.jecosys.plant;

import org.jecosys.math.Require;

/**
 * The rest shape of a component bent by gravity (paper §4.1: "stalk width and mass define the
 * deformation"): the skeleton is a chain of rigid segments joined by rotational springs of flexural
 * constant {@code E I / l} (a ribbon's or a round stalk's second moment of area, from the width at the
 * joint, Young's modulus {@link #MODULUS} and thickness {@link #THICKNESS}), loaded by the weight of
 * its segments and its tip mass; the equilibrium minimises the elastic plus gravitational potential
 * with every angle in [-pi/2, pi/2]. The model and the solver are in docs/model.md, "Rest shapes bent
 * by gravity".
 *
 * <p>Build time only; allocates small scratch arrays per call; any thread.
 */
public final class GravityBend {
    /** Young's modulus of plant tissue used for every component, Pa (order of fresh grass blades). */
    public static final double MODULUS = 1.0e9;
    /** Effective flexural thickness of flat parts (leaves, petals, heads), metres. */
    public static final double THICKNESS = 1.2e-3;
    /** Standard gravity, m/s^2: the default of the build step. */
    public static final double EARTH_GRAVITY = 9.81;

    private static final int MAX_ITERATIONS = 200;
    private static final double TOLERANCE = 1e-12;

    private GravityBend() {
    }

    /**
     * Flexural constant of a joint, N m / rad.
     *
     * @param type      component type: {@link ComponentType#STALK} is round, the rest flat
     * @param width     width at the joint, metres, &gt; 0
     * @param segLength segment length, metres, &gt; 0
     * @return {@code MODULUS * I / segLength}, N m / rad
     */
    public static double jointStiffness(ComponentType type, double width, double segLength) {
        double inertia = type == ComponentType.STALK
                ? Math.PI * width * width * width * width / 64.0
                : width * THICKNESS * THICKNESS * THICKNESS / 12.0;
        return MODULUS * inertia / segLength;
    }

    /**
     * Solves the gravity-bent rest angles of one component.
     *
     * @param type      component type (section shape of the stiffness law)
     * @param segments  segment count, in [1, 32]
     * @param length    total length, metres, &gt; 0
     * @param baseWidth width at the base, metres, &gt; 0
     * @param tipWidth  width at the tip, metres, &gt;= 0 (joints never sit at the tip)
     * @param tilt      base lean from vertical, radians
     * @param curvature rest curvature over the length, radians
     * @param mass      component mass, kg, &gt;= 0
     * @param tipMass   mass hanging at the tip (attached components), kg, &gt;= 0
     * @param gravity   gravitational acceleration, m/s^2, &gt;= 0
     * @param dest      receives {@code segments} angles, radians, each in [-pi/2, pi/2]
     */
    public static void solve(ComponentType type, int segments, double length, double baseWidth, double tipWidth,
                             double tilt, double curvature, double mass, double tipMass, double gravity,
                             double[] dest) {
        Require.nonNull("type", type);
        Require.range("segments", segments, 1, 32);
        Require.positive("length", length);
        Require.positive("baseWidth", baseWidth);
        Require.nonNegative("tipWidth", tipWidth);
        Require.nonNegative("mass", mass);
        Require.nonNegative("tipMass", tipMass);
        Require.nonNegative("gravity", gravity);
        Require.nonNull("dest", dest);
        Require.range("dest.length", dest.length, segments, Integer.MAX_VALUE);
        int n = segments;
        double l = length / n;
        double segMass = mass / n;
        double[] restAlpha = new double[n];
        double[] k = new double[n];
        double[] effMass = new double[n];
        double[] restTheta = new double[n];
        Skeleton.restAngles(n, tilt, curvature, restTheta);
        for (int j = 0; j < n; j++) {
            restAlpha[j] = restTheta[j] - (j == 0 ? 0 : restTheta[j - 1]);
            k[j] = jointStiffness(type, Skeleton.width(baseWidth, tipWidth, j, n), l);
            // weight moment arm factor of theta_j: own half segment plus everything beyond
            effMass[j] = segMass * (n - 1 - j) + 0.5 * segMass + tipMass;
        }
        System.arraycopy(restTheta, 0, dest, 0, n);
        if (gravity == 0 || (mass == 0 && tipMass == 0)) {
            return;
        }
        double[] xy = new double[2 * (n + 1)];
        double[] trial = new double[n];
        double[] step = new double[n];
        double energy = energy(dest, n, l, restAlpha, k, effMass, gravity);
        for (int it = 0; it < MAX_ITERATIONS; it++) {
            Skeleton.points(dest, n, l, xy);
            // tau_j: moment of the weights beyond joint j about joint j (positive bends toward +x)
            double stepMax = 0;
            double cumulative = 0;
            for (int j = 0; j < n; j++) {
                double xj = xy[2 * j];
                double tau = tipMass * (xy[2 * n] - xj);
                for (int i = j; i < n; i++) {
                    double xc = 0.5 * (xy[2 * i] + xy[2 * i + 2]);
                    tau += segMass * (xc - xj);
                }
                tau *= gravity;
                double alpha = dest[j] - (j == 0 ? 0 : dest[j - 1]);
                cumulative += restAlpha[j] + tau / k[j] - alpha;
                step[j] = cumulative;
                stepMax = Math.max(stepMax, Math.abs(cumulative));
            }
            if (stepMax < TOLERANCE) {
                return;
            }
            double omega = 1;
            boolean improved = false;
            while (omega > 1e-9) {
                for (int j = 0; j < n; j++) {
                    trial[j] = Skeleton.clampAngle(dest[j] + omega * step[j]);
                }
                double e = energy(trial, n, l, restAlpha, k, effMass, gravity);
                if (e < energy) {
                    energy = e;
                    System.arraycopy(trial, 0, dest, 0, n);
                    improved = true;
                    break;
                }
                omega *= 0.5;
            }
            if (!improved || omega * stepMax < TOLERANCE) {
                return;
            }
        }
    }

    private static double energy(double[] theta, int n, double l, double[] restAlpha, double[] k,
                                 double[] effMass, double gravity) {
        double e = 0;
        for (int j = 0; j < n; j++) {
            double d = theta[j] - (j == 0 ? 0 : theta[j - 1]) - restAlpha[j];
            e += 0.5 * k[j] * d * d + gravity * l * effMass[j] * Math.cos(theta[j]);
        }
        return e;
    }
}
