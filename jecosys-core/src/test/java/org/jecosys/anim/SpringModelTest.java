package org.jecosys.anim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.jecosys.field.DragLaw;
import org.junit.jupiter.api.Test;

/** The dynamic-constraint spring (paper eq. 5 as docs/ARCHITECTURE.md, "The model", resolves it): equilibrium, release, frame rate, stability. */
class SpringModelTest {
    static final double[] STEPS = {1.0 / 30, 1.0 / 60, 1.0 / 144};

    /** One plant with one component of the given spring, the eye at the plant (level 0). */
    static final class One {
        final AnimationState s;
        final double dragArea;
        final float[] wx = new float[1];
        final float[] wz = new float[1];
        final boolean[] vis = {true};
        final AnimationStep step = AnimationStep.of(AnimationMode.CONSTRAINT, wx, wz, vis);
        final int sub;

        One(double pc, double tau, double mass, double dragArea, int sub) {
            this(kinds(pc, tau, mass, dragArea), dragArea, sub);
        }

        /** One plant of one component of kind 0 of {@code kinds}, rest heading 0.3 rad. */
        One(SpringKinds kinds, double dragArea, int sub) {
            s = new AnimationState(kinds, new double[][] {{}}, new int[1], new int[] {0, 1}, new float[1],
                    new float[1], new float[1], new int[1], new float[] {0.3f});
            this.dragArea = dragArea;
            this.sub = sub;
        }

        private static SpringKinds kinds(double pc, double tau, double mass, double dragArea) {
            SpringKinds.Builder b = new SpringKinds.Builder();
            b.add(pc, tau, mass, dragArea, 0.4, 0.05, 1.2, 16, 0xFF);
            return b.build();
        }

        /** Sets the wind so that the drag force is (fx, fz) newtons. */
        void force(double fx, double fz) {
            double f = Math.hypot(fx, fz);
            if (f == 0) {
                wx[0] = 0;
                wz[0] = 0;
                return;
            }
            double speed = Math.sqrt(f / (0.5 * DragLaw.AIR_DENSITY * dragArea));
            wx[0] = (float) (speed * fx / f);
            wz[0] = (float) (speed * fz / f);
        }

        void step(double h) {
            s.kinds().prepare(h, sub);
            assertEquals(1, s.animate(0, 1, step));
        }
    }

    @Test
    void aConstantForceSettlesAtFOverPcWhateverTheStep() {
        for (double h : STEPS) {
            One o = new One(0.2, 0.3, 0.0004, 0.002, 4);
            o.force(0.004, -0.003);
            for (double t = 0; t < 20 * 0.3; t += h) {
                o.step(h);
            }
            assertEquals(0.004 / 0.2, o.s.deviationX(0), 0.01 * 0.004 / 0.2, "h=" + h);
            assertEquals(-0.003 / 0.2, o.s.deviationZ(0), 0.01 * 0.003 / 0.2, "h=" + h);
        }
    }

    @Test
    void aReleasedComponentReturnsWithoutOvershootAndSettlesWithinSixTau() {
        double tau = 0.45;
        for (double h : STEPS) {
            One o = new One(0.8, tau, 0.003, 0.004, 4);
            o.force(0.01, 0);
            for (double t = 0; t < 20 * tau; t += h) {
                o.step(h);
            }
            double peak = o.s.deviationX(0);
            o.force(0, 0);
            double overshoot = 0;
            double t = 0;
            double atSixTau = Double.NaN;
            while (t < 20 * tau) {
                o.step(h);
                t += h;
                overshoot = Math.max(overshoot, -o.s.deviationX(0));
                if (Double.isNaN(atSixTau) && t >= 6 * tau) {
                    atSixTau = o.s.deviationX(0);
                }
            }
            assertTrue(overshoot <= 0.01 * peak, "overshoot " + overshoot + " of peak " + peak + " h=" + h);
            assertTrue(Math.abs(atSixTau) <= 0.02 * peak, "at 6 tau " + atSixTau + " of " + peak + " h=" + h);
        }
    }

    /** One wind history (m/s) sampled at the end of each step, as the simulation feeds it. */
    static double windX(double t) {
        return 3 + 2 * Math.sin(2 * Math.PI * 0.5 * t);
    }

    static double windZ(double t) {
        return 1.5 * Math.cos(2 * Math.PI * 0.3 * t) + (t > 4 ? 2 : 0);
    }

    @Test
    void oneWindHistoryGivesTheSameTrajectoryAt30And60And144Hz() {
        double duration = 10;
        int samples = 60; // every 1/6 s
        double[][][] traj = new double[STEPS.length][samples][2];
        double maxDev = 0;
        for (int r = 0; r < STEPS.length; r++) {
            double h = STEPS[r];
            int perSample = (int) Math.round((duration / samples) / h);
            One o = new One(0.2, 0.3, 0.0004, 0.002, 4);
            o.wx[0] = (float) windX(0);
            o.wz[0] = (float) windZ(0);
            o.s.settle(0, 1, o.step); // as the simulation does with its sample at t = 0
            int k = 0;
            for (int i = 0; i < samples; i++) {
                for (int j = 0; j < perSample; j++) {
                    k++;
                    o.wx[0] = (float) windX(k * h);
                    o.wz[0] = (float) windZ(k * h);
                    o.step(h);
                }
                traj[r][i][0] = o.s.deviationX(0);
                traj[r][i][1] = o.s.deviationZ(0);
                maxDev = Math.max(maxDev, Math.hypot(traj[r][i][0], traj[r][i][1]));
            }
        }
        for (int r = 1; r < STEPS.length; r++) {
            for (int i = 0; i < samples; i++) {
                double d = Math.hypot(traj[r][i][0] - traj[0][i][0], traj[r][i][1] - traj[0][i][1]);
                assertTrue(d <= 0.02 * maxDev, "sample " + i + " differs by " + d + " of " + maxDev + " at "
                        + STEPS[r]);
            }
        }
    }

    @Test
    void everyStepForceMassAndStiffnessGivesFiniteBoundedValues() {
        double[] steps = {1e-5, 1e-4, 1e-3, 1.0 / 60, 0.1, 1};
        double[] forces = {0, 1e-3, 1, 1e3, 1e6};
        double[] stiffness = {1e-9, 1e-3, 1, 1e6};
        double[] taus = {1e-3, 0.1, 10};
        double[] masses = {1e-9, 10};
        for (double h : steps) {
            for (double f : forces) {
                for (double pc : stiffness) {
                    for (double tau : taus) {
                        for (double m : masses) {
                            One o = new One(pc, tau, m, 1e-3, 4);
                            double bound = f / pc;
                            for (int i = 0; i < 40; i++) {
                                double sign = (i / 7) % 2 == 0 ? 1 : -1;
                                o.force(sign * f * 0.6, f * 0.8);
                                o.step(h);
                                float x = o.s.deviationX(0);
                                float z = o.s.deviationZ(0);
                                float vx = o.s.velocityX(0);
                                float vz = o.s.velocityZ(0);
                                String what = "h=" + h + " F=" + f + " PC=" + pc + " tau=" + tau + " m=" + m;
                                assertTrue(Float.isFinite(x) && Float.isFinite(z) && Float.isFinite(vx)
                                        && Float.isFinite(vz), what);
                                assertTrue(Math.hypot(x, z) <= 1.01 * bound + 1e-30, what + " |D|=" + Math.hypot(x, z));
                                assertTrue(Math.hypot(vx, vz) <= 1.01 * bound / tau + 1e-30, what);
                                float pose = o.s.poseCoordinate(0);
                                assertTrue(pose >= 0 && pose <= 15, what + " pose " + pose);
                                assertTrue(Math.abs(o.s.azimuth(0)) <= Math.PI + 1e-6, what);
                            }
                        }
                    }
                }
            }
        }
    }
}
