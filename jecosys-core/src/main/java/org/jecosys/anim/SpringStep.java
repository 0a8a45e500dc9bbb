package org.jecosys.anim;

/**
 * The exact one-step map of {@link SpringKinds}' critically damped spring (paper §4.2.1-4.2.2, eq. 5,
 * integrated exactly rather than by the paper's one-step balance; see the class comment there): over a
 * step of h seconds with response time tau, the rest point moving linearly from T0 at the start of the
 * step to T1 at its end or, when the flows switch inside the step, T0 held until the switch and T1
 * after it (two exact constant-force maps composed). Its eight coefficients, in the order of a
 * {@link SpringKinds#STRIDE}-float row: {@code D' = aDD D + aDv v + bD T0 + cD T1} and
 * {@code v' = aVD D + aVv v + bV T0 + cV T1}. The incomplete gamma functions are summed as series below
 * x = 1, where their closed forms cancel. Stateless; any thread; no allocation.
 */
final class SpringStep {
    private SpringStep() {
    }

    /**
     * Writes the step's coefficient row into {@code coef} at {@code o}.
     *
     * @param tau   response time, seconds, &gt; 0
     * @param h     step length, seconds, &gt; 0
     * @param sub   sub-intervals of the step, in [1, 64]
     * @param edge  the sub-interval boundary where the force switches, in [0, sub], or -1 for none
     * @param coef  the rows
     * @param o     where this row starts
     */
    static void coefficients(double tau, double h, int sub, int edge, float[] coef, int o) {
        double aDD;
        double aDv;
        double bD;
        double cD;
        double aVD;
        double aVv;
        double bV;
        double cV;
        if (edge < 0) {
            double x = h / tau;
            double e = StrictMath.exp(-x);
            double g2 = gamma2(x, e);
            double g3 = gamma3(x, e);
            aDD = e * (1 + x);
            aDv = e * h;
            aVD = -e * x / tau;
            aVv = e * (1 - x);
            bD = g3 / x;
            cD = g2 - bD;
            cV = g2 / (x * tau);
            bV = x * e / tau - cV;
        } else {
            // the force T0 over [0, a], then T1 over [a, h]: two exact constant-force maps composed
            double a = h * edge / sub;
            double x1 = a / tau;
            double x2 = (h - a) / tau;
            double e1 = StrictMath.exp(-x1);
            double e2 = StrictMath.exp(-x2);
            double p1 = e1 * (1 + x1);
            double q1 = e1 * a;
            double r1 = -e1 * x1 / tau;
            double w1 = e1 * (1 - x1);
            double g1 = gamma2(x1, e1);
            double p2 = e2 * (1 + x2);
            double q2 = e2 * (h - a);
            double r2 = -e2 * x2 / tau;
            double w2 = e2 * (1 - x2);
            aDD = p2 * p1 + q2 * r1;
            aDv = p2 * q1 + q2 * w1;
            bD = p2 * g1 - q2 * r1;
            cD = gamma2(x2, e2);
            aVD = r2 * p1 + w2 * r1;
            aVv = r2 * q1 + w2 * w1;
            bV = r2 * g1 - w2 * r1;
            cV = -r2;
        }
        coef[o] = (float) aDD;
        coef[o + 1] = (float) aDv;
        coef[o + 2] = (float) bD;
        coef[o + 3] = (float) cD;
        coef[o + 4] = (float) aVD;
        coef[o + 5] = (float) aVv;
        coef[o + 6] = (float) bV;
        coef[o + 7] = (float) cV;
    }

    /** {@code 1 - e^-x (1 + x)}, the lower incomplete gamma function of order 2, for x &gt;= 0 and e = e^-x. */
    static double gamma2(double x, double e) {
        return x < 1 ? lowerGammaSeries(2, x, e) : 1 - e * (1 + x);
    }

    /** {@code 2 - e^-x (x^2 + 2x + 2)}, the lower incomplete gamma function of order 3, for x &gt;= 0. */
    static double gamma3(double x, double e) {
        return x < 1 ? lowerGammaSeries(3, x, e) : 2 - e * (x * x + 2 * x + 2);
    }

    /** {@code x^n e^-x sum_k x^k / (n (n+1) ... (n+k))} for x in [0, 1): no cancellation. */
    private static double lowerGammaSeries(int n, double x, double e) {
        double term = 1.0 / n;
        double sum = term;
        for (int k = 1; k < 30; k++) {
            term *= x / (n + k);
            sum += term;
        }
        double xn = n == 2 ? x * x : x * x * x;
        return xn * e * sum;
    }
}
