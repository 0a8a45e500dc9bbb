package org.jecosys.plant;

import org.jecosys.math.Require;

/**
 * One level of detail of a species (paper §4.1, Table 3): it is used from the previous level's
 * {@code maxDistance} up to its own, and draws with {@code primitive}. Which skeleton points it
 * uses is set per component ({@link ComponentDef#lodSegments()}). Immutable; any thread.
 *
 * @param maxDistance farthest viewer distance of this level, metres, &gt; 0, or +Infinity for the last
 * @param primitive   triangles or lines
 */
public record LodDef(double maxDistance, Primitive primitive) {
    /**
     * Checks the components.
     *
     * @param maxDistance farthest viewer distance, metres, in (0, {@link #MAX_DISTANCE}], or +Infinity
     * @param primitive   triangles or lines, not null
     * @throws IllegalArgumentException when maxDistance is not positive or primitive is null
     */
    public LodDef {
        Require.aboveOrInfinite("maxDistance", maxDistance, 0, MAX_DISTANCE);
        Require.nonNull("primitive", primitive);
    }

    /** Largest finite {@link #maxDistance()}, metres (the scene schema's range and the API's). */
    public static final double MAX_DISTANCE = 1e6;
}
