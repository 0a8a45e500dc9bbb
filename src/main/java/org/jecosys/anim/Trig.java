package org.jecosys.anim;

/**
 * Fast, deterministic arc tangents for the per-component hot loop (Java's {@code Math.atan2} is not
 * an intrinsic on JDK 17 and costs tens of nanoseconds). An odd minimax polynomial on [0, 1] with
 * octant reduction; absolute error below 1e-5 rad. Plain float arithmetic, hence bit-identical on
 * every thread and JVM (strict IEEE semantics since Java 17). Any thread; no allocation.
 */
final class Trig {
    private static final float A1 = 0.99997726f;
    private static final float A3 = -0.33262347f;
    private static final float A5 = 0.19354346f;
    private static final float A7 = -0.11643287f;
    private static final float A9 = 0.05265332f;
    private static final float A11 = -0.01172120f;
    static final float PI = (float) Math.PI;
    static final float HALF_PI = (float) (Math.PI / 2);

    private Trig() {
    }

    /** atan(x) for x in [-1, 1]. */
    static float atanUnit(float x) {
        float x2 = x * x;
        return x * (A1 + x2 * (A3 + x2 * (A5 + x2 * (A7 + x2 * (A9 + x2 * A11)))));
    }

    /** atan(x) for x &gt;= 0 (any magnitude, +Infinity included). */
    static float atanPositive(float x) {
        return x <= 1f ? atanUnit(x) : HALF_PI - atanUnit(1f / x);
    }

    /**
     * atan2(y, x) in [-pi, pi]; 0 for (0, 0). Branch-free (octant selection by sign bits, min/max
     * and copySign), so random headings cost no branch mispredictions.
     */
    static float atan2(float y, float x) {
        float ax = Math.abs(x);
        float ay = Math.abs(y);
        float lo = Math.min(ax, ay);
        float hi = Math.max(Math.max(ax, ay), 1e-30f);
        float a = atanUnit(lo / hi);
        float swap = (float) (Float.floatToRawIntBits(ax - ay) >>> 31); // 1 when ay > ax
        a += swap * (HALF_PI - 2 * a);
        float neg = (float) (Float.floatToRawIntBits(x) >>> 31); // 1 when x < 0 (or -0)
        a += neg * (PI - 2 * a);
        return Math.copySign(a, y);
    }
}
