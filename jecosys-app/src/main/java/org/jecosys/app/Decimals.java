package org.jecosys.app;

import java.math.BigDecimal;
import java.math.RoundingMode;

/**
 * Numbers the user sets in the viewer, kept as the decimal the user chose so that a saved scene reads
 * {@code maxDistance="43.146"}, not the float's widened binary value {@code 43.145999908447266}.
 * ImGui's sliders hold floats rounded to their display format; {@link #ofFloat} turns such a float
 * into the double of its shortest decimal form ({@link Float#toString} semantics), which the scene
 * writer then prints as that decimal. Pure; any thread; allocates a little.
 */
final class Decimals {
    private Decimals() {
    }

    /**
     * The double whose shortest decimal form is the float's: {@code ofFloat(43.146f) == 43.146}.
     *
     * @param v any float; infinities and NaN are kept
     * @return the double nearest to the float's shortest decimal
     */
    static double ofFloat(float v) {
        if (Float.isNaN(v) || Float.isInfinite(v)) {
            return v;
        }
        return Double.parseDouble(Float.toString(v));
    }

    /**
     * {@code v} rounded half-up to {@code digits} decimals: the position of a flow placed with the
     * mouse is saved to the centimetre ({@code round(3.47283, 2) == 3.47}).
     *
     * @param v      a finite value
     * @param digits decimals kept, &ge; 0
     * @return the double nearest to the rounded decimal
     */
    static double round(double v, int digits) {
        if (!Double.isFinite(v)) {
            return v;
        }
        return new BigDecimal(Double.toString(v)).setScale(digits, RoundingMode.HALF_UP).doubleValue();
    }

    /**
     * {@code v} rounded to {@code digits} significant digits: strengths scaled to a scene read
     * {@code 12} or {@code 0.37}, not {@code 12.345678}.
     *
     * @param v      a finite value
     * @param digits significant digits, &ge; 1
     * @return the double nearest to the rounded decimal
     */
    static double significant(double v, int digits) {
        if (!Double.isFinite(v) || v == 0) {
            return v;
        }
        return new BigDecimal(Double.toString(v)).round(new java.math.MathContext(digits, RoundingMode.HALF_UP))
                .doubleValue();
    }
}
