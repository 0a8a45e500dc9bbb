package org.jecosys.wind;

import java.util.List;
import org.jecosys.math.Require;
import org.jecosys.math.Waypoint;

/**
 * How a flow's centre moves (paper §3.2: "each source can also be under the action of other
 * flows, moving under their action or not"). Immutable; any thread.
 *
 * @param kind      fixed, along a scripted path, or advected by the other active flows
 * @param waypoints the path's points (kind PATH: at least 2; otherwise empty); y is ignored
 * @param speed     speed along the path, m/s, &gt; 0 (PATH only; otherwise ignored)
 * @param loop      PATH only: start again at the first waypoint after the last; otherwise stop there
 */
public record MotionDef(Kind kind, List<Waypoint> waypoints, double speed, boolean loop) {
    /** The motion kinds. */
    public enum Kind {
        /** The centre stays where it was declared. */
        FIXED,
        /** The centre walks the waypoints at constant speed. */
        PATH,
        /** The centre moves with the velocity of the other active flows at its position. */
        ADVECTED
    }

    /**
     * Checks the components and copies the waypoints.
     *
     * @param kind      not null
     * @param waypoints not null; at least 2 for PATH
     * @param speed     m/s, in [{@link org.jecosys.math.CameraDef#MIN_PATH_SPEED},
     *                  {@link org.jecosys.math.CameraDef#MAX_PATH_SPEED}] (even when unused)
     * @param loop      PATH only: whether the path repeats
     * @throws IllegalArgumentException when a component is null or out of range, or a path has fewer
     *                                  than 2 waypoints
     */
    public MotionDef {
        Require.nonNull("kind", kind);
        waypoints = List.copyOf(Require.nonNull("waypoints", waypoints));
        Require.range("speed", speed, org.jecosys.math.CameraDef.MIN_PATH_SPEED,
                org.jecosys.math.CameraDef.MAX_PATH_SPEED);
        if (kind == Kind.PATH && waypoints.size() < 2) {
            throw new IllegalArgumentException("a path needs at least 2 waypoints, got " + waypoints.size());
        }
    }

    /** A centre that does not move. */
    public static final MotionDef FIXED = new MotionDef(Kind.FIXED, List.of(), 1, false);

    /** Default speed along a flow's path, m/s (the scene schema's default too). */
    public static final double DEFAULT_PATH_SPEED = 1;
    /** Default of {@link #loop()} for a flow's path: stop at the last waypoint. */
    public static final boolean DEFAULT_PATH_LOOP = false;

    /** A centre that moves with the other active flows (speed and loop unused). */
    public static final MotionDef ADVECTED = new MotionDef(Kind.ADVECTED, List.of(), 1, false);

    /**
     * A path walked at {@link #DEFAULT_PATH_SPEED}, not looping (the scene schema's defaults).
     * Allocates.
     *
     * @param waypoints at least 2; y is ignored
     * @return the motion
     * @throws IllegalArgumentException when there are fewer than 2 waypoints
     */
    public static MotionDef path(List<Waypoint> waypoints) {
        return new MotionDef(Kind.PATH, waypoints, DEFAULT_PATH_SPEED, DEFAULT_PATH_LOOP);
    }
}
