package org.jecosys.sim;

import java.util.List;
import org.jecosys.math.CameraDef;
import org.jecosys.math.ViewCamera;
import org.jecosys.math.Waypoint;
import org.jecosys.terrain.Heightfield;

/**
 * The viewer of a headless run: the scene camera's start pose, walking its path (if it has two or
 * more waypoints) at {@code pathSpeed} m/s, looping if the path loops, else stopping at its end.
 * While walking it looks along the current segment (yaw from the direction of travel, the start
 * pitch); its eye is a waypoint's height above the terrain, interpolated along the segment, or the
 * start height where a waypoint's y is 0 (unset). The paper's tests walked the viewer through each
 * scene this way (section 5.2). One owner thread; no allocation per call.
 */
public final class CameraWalk {
    private final CameraDef def;
    private final org.jecosys.math.HeightFunction ground;
    private final List<Waypoint> path;
    private final double[] cumulative;
    private final ViewCamera camera;

    /**
     * A walk of {@code def}'s path over {@code ground}. Allocates.
     *
     * @param def    the scene camera: start pose, lens, path, walking speed (m/s) and loop flag
     * @param ground the ground the eye heights are measured from: a terrain (0 outside it) or an
     *               unbounded height function (an open world's hills)
     * @param aspect viewport width over height
     */
    public CameraWalk(CameraDef def, org.jecosys.math.HeightFunction ground, double aspect) {
        this.def = def;
        this.ground = ground;
        this.path = def.path();
        camera = ViewCamera.of(def, height(def.x(), def.z()), aspect);
        cumulative = new double[path.size()];
        for (int i = 1; i < path.size(); i++) {
            Waypoint a = path.get(i - 1);
            Waypoint b = path.get(i);
            cumulative[i] = cumulative[i - 1] + Math.hypot(b.x() - a.x(), b.z() - a.z());
        }
    }

    private double height(double x, double z) {
        return !(ground instanceof Heightfield h) || h.contains(x, z) ? ground.height(x, z) : 0;
    }

    /**
     * The camera at a time of the walk. No allocation.
     *
     * @param time seconds after the start, &gt;= 0
     * @return the walk's one camera, updated (the same instance every call)
     */
    public ViewCamera at(double time) {
        int n = path.size();
        double total = n < 2 ? 0 : cumulative[n - 1];
        if (total <= 0) {
            return camera;
        }
        double s = def.pathSpeed() * time;
        s = def.pathLoop() ? s % total : Math.min(s, total);
        int i = 1;
        while (i < n - 1 && cumulative[i] < s) {
            i++;
        }
        Waypoint a = path.get(i - 1);
        Waypoint b = path.get(i);
        double len = cumulative[i] - cumulative[i - 1];
        double f = len > 0 ? (s - cumulative[i - 1]) / len : 0;
        double x = a.x() + (b.x() - a.x()) * f;
        double z = a.z() + (b.z() - a.z()) * f;
        double ha = a.y() > 0 ? a.y() : def.y();
        double hb = b.y() > 0 ? b.y() : def.y();
        camera.setPosition(x, height(x, z) + ha + (hb - ha) * f, z);
        if (len > 0) {
            camera.setOrientation(Math.atan2(b.x() - a.x(), -(b.z() - a.z())), def.pitch());
        }
        return camera;
    }
}
