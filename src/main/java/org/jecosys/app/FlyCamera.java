package org.jecosys.app;

import java.util.List;
import org.jecosys.math.CameraDef;
import org.jecosys.math.ViewCamera;
import org.jecosys.math.Waypoint;
import org.jecosys.terrain.Heightfield;

/**
 * The viewer's first-person camera: WASD moves in the view's heading, Q/E down/up, Shift four times
 * faster, mouse look; and playback of the scene's camera path (paper §5.2: the tests walked a path)
 * at its walking speed, eye at each waypoint's height above the terrain. Render thread; no allocation.
 */
final class FlyCamera {
    static final double SPEED = 3.0;
    static final double LOOK = 0.0025;

    private final ViewCamera camera;
    private final Heightfield ground;
    private final List<Waypoint> path;
    private final double pathSpeed;
    private final boolean loop;
    private boolean playing;
    private double travelled;

    FlyCamera(ViewCamera camera, CameraDef def, Heightfield ground) {
        this.camera = camera;
        this.ground = ground;
        this.path = def.path();
        this.pathSpeed = def.pathSpeed();
        this.loop = def.pathLoop();
    }

    ViewCamera camera() {
        return camera;
    }

    boolean playing() {
        return playing;
    }

    /** Starts or stops the path (P); a no-op without a path. */
    void togglePath() {
        playing = !playing && path.size() >= 2;
        travelled = 0;
    }

    /** Mouse look by a cursor delta in pixels. */
    void look(double dx, double dy) {
        double pitch = Math.max(-1.55, Math.min(1.55, camera.pitch() - dy * LOOK));
        camera.setOrientation(camera.yaw() + dx * LOOK, pitch);
    }

    /**
     * Moves by the keys held: forward/right/up in [-1, 1] each.
     *
     * @param dt seconds
     */
    void move(double dt, double forward, double right, double up, boolean fast) {
        if (playing) {
            followPath(dt);
            return;
        }
        double v = SPEED * (fast ? 4 : 1) * dt;
        double sy = Math.sin(camera.yaw());
        double cy = Math.cos(camera.yaw());
        double x = camera.x() + v * (forward * sy + right * cy);
        double z = camera.z() + v * (-forward * cy + right * sy);
        double y = camera.y() + v * up;
        y = Math.max(y, ground.height(x, z) + 0.2);
        camera.setPosition(x, y, z);
    }

    private void followPath(double dt) {
        travelled += pathSpeed * dt;
        double total = 0;
        for (int i = 0; i + 1 < path.size(); i++) {
            total += segment(i);
        }
        if (travelled >= total) {
            if (!loop) {
                playing = false;
                return;
            }
            travelled -= total;
        }
        double d = travelled;
        int i = 0;
        while (i + 2 < path.size() && d > segment(i)) {
            d -= segment(i);
            i++;
        }
        Waypoint a = path.get(i);
        Waypoint b = path.get(i + 1);
        double t = segment(i) > 0 ? Math.min(1, d / segment(i)) : 1;
        double x = a.x() + (b.x() - a.x()) * t;
        double z = a.z() + (b.z() - a.z()) * t;
        double h = a.y() + (b.y() - a.y()) * t;
        camera.setPosition(x, ground.height(x, z) + h, z);
        double yaw = Math.atan2(b.x() - a.x(), -(b.z() - a.z()));
        camera.setOrientation(yaw, camera.pitch());
    }

    private double segment(int i) {
        Waypoint a = path.get(i);
        Waypoint b = path.get(i + 1);
        return Math.hypot(b.x() - a.x(), b.z() - a.z());
    }
}
