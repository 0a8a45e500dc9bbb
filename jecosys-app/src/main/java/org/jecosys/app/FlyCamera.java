package org.jecosys.app;

import org.jecosys.math.CameraDef;
import org.jecosys.math.ViewCamera;
import org.jecosys.sim.CameraWalk;
import org.jecosys.terrain.Heightfield;

/**
 * The viewer's first-person camera: WASD moves in the view's heading, Q/E down/up, Shift four times
 * faster, mouse look; and playback of the scene's camera path (paper §5.2: the tests walked a path)
 * through {@link CameraWalk}, the same walk {@code jecosys simulate} and the benchmarks use, so the
 * viewer and those runs see the path identically (time since P was pressed, the walk's pose copied
 * into this camera; at the end of a path that does not loop the camera stays there until P is
 * pressed again). Render thread; no allocation.
 */
final class FlyCamera {
    static final double SPEED = 3.0;
    static final double LOOK = 0.0025;

    private final ViewCamera camera;
    private final Heightfield ground;
    private final CameraWalk walk;
    private final boolean hasPath;
    private boolean playing;
    private double pathTime;

    FlyCamera(ViewCamera camera, CameraDef def, Heightfield ground) {
        this.camera = camera;
        this.ground = ground;
        this.walk = new CameraWalk(def, ground, camera.aspect());
        this.hasPath = def.path().size() >= 2;
    }

    ViewCamera camera() {
        return camera;
    }

    boolean playing() {
        return playing;
    }

    /** Starts (from the path's start) or stops the path (P); a no-op without a path. */
    void togglePath() {
        playing = !playing && hasPath;
        pathTime = 0;
        if (playing) {
            follow(walk.at(0));
        }
    }

    /** Mouse look by a cursor delta in pixels. */
    void look(double dx, double dy) {
        double pitch = Math.max(-1.55, Math.min(1.55, camera.pitch() - dy * LOOK));
        camera.setOrientation(camera.yaw() + dx * LOOK, pitch);
    }

    /**
     * Moves by the keys held: forward/right/up in [-1, 1] each; while the path plays, advances it
     * instead.
     *
     * @param dt seconds
     */
    void move(double dt, double forward, double right, double up, boolean fast) {
        if (playing) {
            pathTime += dt;
            follow(walk.at(pathTime));
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

    private void follow(ViewCamera walked) {
        camera.setPosition(walked.x(), walked.y(), walked.z());
        camera.setOrientation(walked.yaw(), walked.pitch());
    }
}
