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
}
