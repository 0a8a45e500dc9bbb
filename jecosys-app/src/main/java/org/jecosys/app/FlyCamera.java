package org.jecosys.app;

import org.jecosys.math.CameraDef;
import org.jecosys.math.HeightFunction;
import org.jecosys.math.ViewCamera;
import org.jecosys.sim.CameraWalk;
import org.jecosys.terrain.Heightfield;

/**
 * The viewer's first-person camera: WASD moves in the view's heading, Q/E down/up, at a walking
 * speed scaled to the terrain ({@link #walkSpeed}: 3.2 m/s on the 80 m meadow, 0.2 m/s on the 4 m
 * rose), Shift four times faster, Ctrl four times slower, the mouse wheel scales it; mouse look; the
 * camera stays over the terrain and above the ground ({@link #clamp}); {@link #frameScene} frames the
 * whole terrain; and playback of the scene's camera path (paper §5.2: the tests walked a path)
 * through {@link CameraWalk}, the same walk {@code jecosys simulate} and the benchmarks use, so the
 * viewer and those runs see the path identically (time since P was pressed, the walk's pose copied
 * into this camera; at the end of a path that does not loop the camera stays there until P is
 * pressed again). Render thread; no allocation.
 *
 * <p>Over an open world ({@link #unbounded}) the ground has no edge: the camera walks anywhere over the
 * world's hills, at most {@link #OPEN_CEILING} metres above their highest point, and H returns to the
 * scene's camera instead of framing a square.
 */
final class FlyCamera {
    static final double LOOK = 0.0025;
    /** Speed factor while Shift is held. */
    static final double FAST = 4;
    /** Speed factor while Ctrl is held. */
    static final double SLOW = 0.25;
    /** Largest and smallest walking speed the terrain's size gives, m/s. */
    static final double MAX_WALK = 4;
    static final double MIN_WALK = 0.2;
    /** Angle below the horizon at which the top of the view meets the far edge in {@link #frameScene}, radians. */
    static final double FRAME_TOP = Math.toRadians(8);

    /** Over an open world: the highest the eye may go above the hills' highest point, metres. */
    static final double OPEN_CEILING = 300;
    /** Over an open world: the walking speed without Shift, Ctrl or the wheel, m/s (a brisk walk). */
    static final double OPEN_WALK = 4;

    private final ViewCamera camera;
    private final HeightFunction ground;
    private final CameraWalk walk;
    private final boolean hasPath;
    private final double clearance;
    private final double margin;
    /** The ground's extent (infinite over an open world), its highest point and the speed scale. */
    private final double minX;
    private final double maxX;
    private final double minZ;
    private final double maxZ;
    private final double maxHeight;
    private final double ceiling;
    private final double baseSpeed;
    private final boolean bounded;
    /** The scene camera's pose, where H returns over an open world. */
    private final double homeX;
    private final double homeY;
    private final double homeZ;
    private final double homeYaw;
    private final double homePitch;
    private double speed;
    private boolean playing;
    private double pathTime;

    FlyCamera(ViewCamera camera, CameraDef def, Heightfield ground) {
        this(camera, def, ground, true, ground.minX(), ground.maxX(), ground.minZ(), ground.maxZ(),
                ground.maxHeight(), Math.max(ground.sizeX(), ground.sizeZ()), walkSpeed(ground),
                Math.min(ground.sizeX(), ground.sizeZ()));
    }

    private FlyCamera(ViewCamera camera, CameraDef def, HeightFunction ground, boolean bounded, double minX,
                      double maxX, double minZ, double maxZ, double maxHeight, double ceiling, double baseSpeed,
                      double small) {
        this.camera = camera;
        this.ground = ground;
        this.bounded = bounded;
        this.minX = minX;
        this.maxX = maxX;
        this.minZ = minZ;
        this.maxZ = maxZ;
        this.maxHeight = maxHeight;
        this.ceiling = ceiling;
        this.baseSpeed = baseSpeed;
        this.walk = new CameraWalk(def, ground, camera.aspect());
        this.hasPath = def.path().size() >= 2;
        this.speed = baseSpeed;
        this.clearance = Math.max(0.05, Math.min(0.3, 0.02 * small));
        this.margin = bounded ? 0.01 * small : 0;
        this.homeX = camera.x();
        this.homeY = camera.y();
        this.homeZ = camera.z();
        this.homeYaw = camera.yaw();
        this.homePitch = camera.pitch();
    }

    /**
     * A camera over ground without an edge (an open world's hills): it walks anywhere, at most
     * {@link #OPEN_CEILING} metres above {@code maxHeight}, at {@link #OPEN_WALK} m/s; H returns it to
     * where it starts.
     *
     * @param camera    the camera, at its starting pose (the scene's camera over the hills)
     * @param def       the scene's camera (its path is played with P)
     * @param ground    the hills
     * @param maxHeight the hills' highest point, metres
     * @return the camera
     */
    static FlyCamera unbounded(ViewCamera camera, CameraDef def, HeightFunction ground, double maxHeight) {
        return new FlyCamera(camera, def, ground, false, Double.NEGATIVE_INFINITY, Double.POSITIVE_INFINITY,
                Double.NEGATIVE_INFINITY, Double.POSITIVE_INFINITY, maxHeight, OPEN_CEILING, OPEN_WALK, 100);
    }

    /**
     * The walking speed for a terrain: 4% of its larger side per second, in [{@link #MIN_WALK},
     * {@link #MAX_WALK}] m/s, so crossing a terrain takes about 25 s whatever its size.
     *
     * @param ground the terrain
     * @return m/s
     */
    static double walkSpeed(Heightfield ground) {
        return Math.max(MIN_WALK, Math.min(MAX_WALK, 0.04 * Math.max(ground.sizeX(), ground.sizeZ())));
    }

    /** {@return the walking speed without Shift or Ctrl, m/s} */
    double speed() {
        return speed;
    }

    /** Scales the walking speed by 1.25 per mouse-wheel step (up: faster), within [1/16, 16] times the terrain's. */
    void scaleSpeed(double steps) {
        double base = baseSpeed;
        speed = Math.max(base / 16, Math.min(base * 16, speed * Math.pow(1.25, steps)));
    }

    /** {@return the lowest the eye may be above the ground, metres} */
    double clearance() {
        return clearance;
    }

    /**
     * Keeps the eye over the terrain (X and Z within its bounds, less a margin of 1% of its smaller
     * side), at least {@link #clearance()} above the ground and at most the terrain's larger side
     * above its highest point (over an open world: anywhere in X and Z, at most {@link #OPEN_CEILING}
     * above the hills). No allocation.
     */
    void clamp() {
        double x = Math.max(minX + margin, Math.min(maxX - margin, camera.x()));
        double z = Math.max(minZ + margin, Math.min(maxZ - margin, camera.z()));
        double top = maxHeight + ceiling;
        double y = Math.max(ground.height(x, z) + clearance, Math.min(top, camera.y()));
        if (x != camera.x() || y != camera.y() || z != camera.z()) {
            camera.setPosition(x, y, z);
        }
    }

    /**
     * Frames the whole terrain (the "frame the scene" key): stops the path, puts the eye over the
     * middle of the terrain's south edge, looking north (-Z) and down so that the far edge is just
     * below the top of the view, high enough to see over every hill. Over an open world, which has no
     * edge to frame, returns to the pose the camera started at. No allocation.
     */
    void frameScene() {
        playing = false;
        if (!bounded) {
            camera.setOrientation(homeYaw, homePitch);
            camera.setPosition(homeX, homeY, homeZ);
            clamp();
            return;
        }
        Heightfield ground = (Heightfield) this.ground;
        double half = camera.fovY() / 2;
        double pitch = -(half + FRAME_TOP);
        double z = ground.maxZ() - margin;
        double depth = ground.sizeZ() - 2 * margin;
        double x = 0.5 * (ground.minX() + ground.maxX());
        // the far corners, even on the highest ground, 1.5 times FRAME_TOP below the horizon: inside the view
        double far = Math.hypot(depth, 0.5 * ground.sizeX());
        double y = ground.maxHeight() + far * Math.tan(1.5 * FRAME_TOP);
        camera.setOrientation(0, pitch);
        camera.setPosition(x, y, z);
        clamp();
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
     * Moves by the keys held: forward/right/up in [-1, 1] each, Shift ({@code fast}) four times
     * faster; while the path plays, advances it instead.
     *
     * @param dt seconds
     */
    void move(double dt, double forward, double right, double up, boolean fast) {
        move(dt, forward, right, up, fast ? FAST : 1);
    }

    /**
     * Moves by the keys held at {@code factor} times the walking speed ({@link #FAST}, {@link #SLOW}
     * or 1), then {@link #clamp clamps}; while the path plays, advances it instead.
     *
     * @param dt     seconds
     * @param factor speed factor, &gt; 0
     */
    void move(double dt, double forward, double right, double up, double factor) {
        if (playing) {
            pathTime += dt;
            follow(walk.at(pathTime));
            return;
        }
        double v = speed * factor * dt;
        double sy = Math.sin(camera.yaw());
        double cy = Math.cos(camera.yaw());
        double x = camera.x() + v * (forward * sy + right * cy);
        double z = camera.z() + v * (-forward * cy + right * sy);
        double y = camera.y() + v * up;
        camera.setPosition(x, y, z);
        clamp();
    }

    private void follow(ViewCamera walked) {
        camera.setPosition(walked.x(), walked.y(), walked.z());
        camera.setOrientation(walked.yaw(), walked.pitch());
    }
}
