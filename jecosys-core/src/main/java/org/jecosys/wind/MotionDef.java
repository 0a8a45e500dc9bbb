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

    public MotionDef {
        Require.nonNull("kind", kind);
        waypoints = List.copyOf(Require.nonNull("waypoints", waypoints));
        Require.positive("speed", speed);
        if (kind == Kind.PATH && waypoints.size() < 2) {
            throw new IllegalArgumentException("a path needs at least 2 waypoints, got " + waypoints.size());
        }
    }

    /** A centre that does not move. */
    public static final MotionDef FIXED = new MotionDef(Kind.FIXED, List.of(), 1, false);
}
