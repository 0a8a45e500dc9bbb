package org.jecosys.math;

/**
 * Argument checks for API entry points and {@code *Def} constructors. Each failure is an
 * {@link IllegalArgumentException} whose message names the argument and what is allowed.
 * Any thread; allocates only when it throws.
 */
public final class Require {
    private Require() {
    }

    /**
     * A finite value (not NaN, not infinite).
     *
     * @param name the argument's name, for the message
     * @param v    the value to check
     * @return {@code v}
     * @throws IllegalArgumentException when {@code v} is NaN or infinite
     */
    public static double finite(String name, double v) {
        if (!Double.isFinite(v)) {
            throw new IllegalArgumentException(name + " must be a finite number, got " + v);
        }
        return v;
    }

    /**
     * A finite value in [min, max].
     *
     * @param name the argument's name, for the message
     * @param v    the value to check
     * @param min  smallest allowed value (inclusive)
     * @param max  largest allowed value (inclusive)
     * @return {@code v}
     * @throws IllegalArgumentException when {@code v} is not finite or lies outside [min, max]
     */
    public static double range(String name, double v, double min, double max) {
        finite(name, v);
        if (v < min || v > max) {
            throw new IllegalArgumentException(name + " must be in [" + min + ", " + max + "], got " + v);
        }
        return v;
    }

    /**
     * A finite value strictly greater than zero.
     *
     * @param name the argument's name, for the message
     * @param v    the value to check
     * @return {@code v}
     * @throws IllegalArgumentException when {@code v} is not finite or is &le; 0
     */
    public static double positive(String name, double v) {
        finite(name, v);
        if (v <= 0) {
            throw new IllegalArgumentException(name + " must be > 0, got " + v);
        }
        return v;
    }

    /**
     * A finite value greater than or equal to zero.
     *
     * @param name the argument's name, for the message
     * @param v    the value to check
     * @return {@code v}
     * @throws IllegalArgumentException when {@code v} is not finite or is negative
     */
    public static double nonNegative(String name, double v) {
        finite(name, v);
        if (v < 0) {
            throw new IllegalArgumentException(name + " must be >= 0, got " + v);
        }
        return v;
    }

    /**
     * A positive value or {@link Double#POSITIVE_INFINITY} (meaning "unbounded" or "forever").
     *
     * @param name the argument's name, for the message
     * @param v    the value to check
     * @return {@code v}
     * @throws IllegalArgumentException when {@code v} is NaN, negative infinity or &le; 0
     */
    public static double positiveOrInfinite(String name, double v) {
        if (v == Double.POSITIVE_INFINITY) {
            return v;
        }
        return positive(name, v);
    }

    /**
     * A finite value in (min, max]: above {@code min}, at most {@code max} (a scene schema range
     * whose minimum is excluded, e.g. a length that must be positive).
     *
     * @param name the argument's name, for the message
     * @param v    the value to check
     * @param min  the excluded lower bound
     * @param max  largest allowed value (inclusive)
     * @return {@code v}
     * @throws IllegalArgumentException when {@code v} is not finite or lies outside (min, max]
     */
    public static double above(String name, double v, double min, double max) {
        finite(name, v);
        if (!(v > min) || v > max) {
            throw new IllegalArgumentException(name + " must be in (" + min + ", " + max + "], got " + v);
        }
        return v;
    }

    /**
     * A value in (min, max] or {@link Double#POSITIVE_INFINITY} (meaning "unbounded" or "forever").
     *
     * @param name the argument's name, for the message
     * @param v    the value to check
     * @param min  the excluded lower bound
     * @param max  largest finite value allowed (inclusive)
     * @return {@code v}
     * @throws IllegalArgumentException when {@code v} is NaN, negative infinity, or a finite value
     *                                  outside (min, max]
     */
    public static double aboveOrInfinite(String name, double v, double min, double max) {
        if (v == Double.POSITIVE_INFINITY) {
            return v;
        }
        if (!Double.isFinite(v) || !(v > min) || v > max) {
            throw new IllegalArgumentException(name + " must be in (" + min + ", " + max + "] or +Infinity, got " + v);
        }
        return v;
    }

    /**
     * An angle given in radians whose allowed range is stated in degrees (as in scene files):
     * {@code v} must be finite and in [toRadians(minDegrees), toRadians(maxDegrees)]. The message
     * gives both units, e.g. "maxBend must be in [0.1, 90] degrees, got 120 degrees (2.0943951023931953 radians)".
     *
     * @param name       the argument's name, for the message
     * @param v          the value to check, radians
     * @param minDegrees smallest allowed value, degrees (inclusive)
     * @param maxDegrees largest allowed value, degrees (inclusive)
     * @return {@code v}
     * @throws IllegalArgumentException when {@code v} is not finite or lies outside the range
     */
    public static double degrees(String name, double v, double minDegrees, double maxDegrees) {
        if (!Double.isFinite(v) || v < Math.toRadians(minDegrees) || v > Math.toRadians(maxDegrees)) {
            throw new IllegalArgumentException(name + " must be in [" + number(minDegrees) + ", " + number(maxDegrees)
                    + "] degrees, got " + (Double.isFinite(v) ? number(Math.toDegrees(v)) + " degrees ("
                    + v + " radians)" : v));
        }
        return v;
    }

    /** A short decimal form: at most 6 significant digits, no trailing zeros, e.g. 0.1, 90, 401.07. */
    private static String number(double v) {
        if (v == Math.rint(v) && Math.abs(v) < 1e15) {
            return String.valueOf((long) v);
        }
        return new java.math.BigDecimal(v).round(new java.math.MathContext(6)).stripTrailingZeros().toPlainString();
    }

    /**
     * An int in [min, max].
     *
     * @param name the argument's name, for the message
     * @param v    the value to check
     * @param min  smallest allowed value (inclusive)
     * @param max  largest allowed value (inclusive)
     * @return {@code v}
     * @throws IllegalArgumentException when {@code v} lies outside [min, max]
     */
    public static int range(String name, int v, int min, int max) {
        if (v < min || v > max) {
            throw new IllegalArgumentException(name + " must be in [" + min + ", " + max + "], got " + v);
        }
        return v;
    }

    /**
     * A non-null reference.
     *
     * @param <T>  the reference's type
     * @param name the argument's name, for the message
     * @param v    the reference to check
     * @return {@code v}
     * @throws IllegalArgumentException when {@code v} is null (not NullPointerException, like the
     *                                  other checks)
     */
    public static <T> T nonNull(String name, T v) {
        if (v == null) {
            throw new IllegalArgumentException(name + " must not be null");
        }
        return v;
    }

    /**
     * An int element {@code array[index]} in [min, max]: like {@link #range(String, int, int, int)}, for a
     * check in a loop over an array, whose element name is built only when it throws (a loop over a
     * tile's components allocates nothing).
     *
     * @param array the array's name, for the message
     * @param index the element's index, for the message
     * @param v     the element's value
     * @param min   smallest allowed value (inclusive)
     * @param max   largest allowed value (inclusive)
     * @return {@code v}
     * @throws IllegalArgumentException when {@code v} lies outside [min, max], naming {@code array[index]}
     */
    public static int elementRange(String array, int index, int v, int min, int max) {
        return v < min || v > max ? range(array + "[" + index + "]", v, min, max) : v;
    }

    /**
     * A finite double element {@code array[index]} in [min, max]: like
     * {@link #range(String, double, double, double)}, its name built only when it throws.
     *
     * @param array the array's name, for the message
     * @param index the element's index, for the message
     * @param v     the element's value
     * @param min   smallest allowed value (inclusive)
     * @param max   largest allowed value (inclusive)
     * @return {@code v}
     * @throws IllegalArgumentException when {@code v} is not finite or lies outside [min, max], naming
     *                                  {@code array[index]}
     */
    public static double elementRange(String array, int index, double v, double min, double max) {
        return v >= min && v <= max && Double.isFinite(v) ? v : range(array + "[" + index + "]", v, min, max);
    }

    /**
     * A finite double element {@code array[index]} in (min, max]: like
     * {@link #above(String, double, double, double)}, its name built only when it throws.
     *
     * @param array the array's name, for the message
     * @param index the element's index, for the message
     * @param v     the element's value
     * @param min   the exclusive lower bound
     * @param max   largest allowed value (inclusive)
     * @return {@code v}
     * @throws IllegalArgumentException when {@code v} is not finite, &le; min or &gt; max, naming
     *                                  {@code array[index]}
     */
    public static double elementAbove(String array, int index, double v, double min, double max) {
        return v > min && v <= max && Double.isFinite(v) ? v : above(array + "[" + index + "]", v, min, max);
    }

    /**
     * A non-null element {@code array[index]}: like {@link #nonNull(String, Object)}, its name built only
     * when it throws.
     *
     * @param <T>   the element's type
     * @param array the array's (or list's) name, for the message
     * @param index the element's index, for the message
     * @param v     the element
     * @return {@code v}
     * @throws IllegalArgumentException when {@code v} is null, naming {@code array[index]}
     */
    public static <T> T elementNonNull(String array, int index, T v) {
        return v != null ? v : nonNull(array + "[" + index + "]", v);
    }
}
