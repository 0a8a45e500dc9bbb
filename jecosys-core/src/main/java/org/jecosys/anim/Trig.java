package org.jecosys.anim;

/**
 * Fast, deterministic arc tangents for the bend outputs (Java's {@code Math.atan2} is not
 * an intrinsic on JDK 17 and costs tens of nanoseconds). An odd polynomial of degree 17 on [-1, 1]
 * (Abramowitz and Stegun 4.4.49), absolute error below 2e-7 rad in float arithmetic. Plain float
 * arithmetic, hence bit-identical on every thread and JVM (strict IEEE semantics since Java 17).
 *
 * <p>{@link #poseAngle} and {@link #azimuth} are the forms the bend outputs use: they need only
 * add, multiply, divide, abs, min and max (no branches, no sign-bit tricks), so C2's superword pass
 * can vectorise a loop made of them. Any thread; no allocation.
 */
final class Trig {
    private static final float B3 = -0.3333314528f;
    private static final float B5 = 0.1999355085f;
    private static final float B7 = -0.1420889944f;
    private static final float B9 = 0.1065626393f;
    private static final float B11 = -0.0752896400f;
    private static final float B13 = 0.0429096138f;
    private static final float B15 = -0.0161657367f;
    private static final float B17 = 0.0028662257f;
    static final float PI = (float) Math.PI;
    static final float HALF_PI = (float) (Math.PI / 2);
    /** atanUnit(1): pi/4 to 1 ulp, chosen so that {@code QUARTER + atanUnit(-1)} is exactly 0. */
    static final float QUARTER = atanUnit(1f);
    private static final float HALF = 2 * QUARTER;
    private static final float HUGE = 0x1p100f;

    private Trig() {
    }

    /** atan(x) for x in [-1, 1]. */
    static float atanUnit(float x) {
        float z = x * x;
        return x * (1f + z * (B3 + z * (B5 + z * (B7 + z * (B9 + z * (B11 + z * (B13 + z * (B15 + z * B17))))))));
    }

    /** atan(x) for x &gt;= 0 (any magnitude, +Infinity included). */
    static float atanPositive(float x) {
        return x <= 1f ? atanUnit(x) : HALF_PI - atanUnit(1f / x);
    }

    /**
     * atan2(y, x) in [-pi, pi]; 0 for (0, 0). Branch-free (octant selection by sign bits, min/max
     * and copySign). Tests and build time; the outputs use {@link #azimuth}.
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

    /**
     * The argument of {@link #poseAngle(float)} for atan(num / den), num &gt;= 0 and den &gt; 0:
     * {@code (num - den) / (num + den)} in [-1, 1], exactly -1 for num = 0.
     */
    static float poseArgument(float num, float den) {
        return (num - den) / (num + den);
    }

    /**
     * atan(num / den) in [0, pi/2] from {@code u = poseArgument(num, den)}, as {@code pi/4 + atan(u)}:
     * no branch, exactly 0 for num = 0.
     */
    static float poseAngle(float u) {
        return QUARTER + atanUnit(u);
    }

    /**
     * The argument of {@link #azimuth(float, float)} for atan2(y, x) given {@code r = sqrt(x^2 + y^2)}:
     * {@code -x / (|y| + r)} in [-1, 1] (the tangent of a half angle about the y axis, without
     * cancellation); 0 for the undefined (0, 0).
     */
    static float azimuthArgument(float y, float x, float r) {
        return -x / Math.max(Math.abs(y) + r, 1e-30f);
    }

    /**
     * atan2(y, x) in [-pi, pi] from {@code u = azimuthArgument(y, x, r)}, as
     * {@code sign(y) (pi/2 + 2 atan(u))}. The sign is +1 for y = +-0 (so (0, x &lt; 0) gives pi);
     * exactly 0 for y = 0, x &gt; 0; pi/2 for the undefined (0, 0). No branch. Error below 5e-7 rad.
     */
    static float azimuth(float y, float u) {
        float s = Math.min(1f, Math.max(-1f, y * HUGE * HUGE + 1f));
        return s * (HALF + 2 * atanUnit(u));
    }
}
