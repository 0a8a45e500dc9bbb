package org.jecosys.math;

import org.joml.Matrix4f;
import org.joml.Vector3f;

/**
 * The convenient {@link Camera}: a perspective viewer given by its eye, heading, pitch and lens, shared
 * by the force field (frustum culling and distance LOD, paper §3.1.1), the simulation and the renderer.
 * A game with its own matrices uses {@link MatrixCamera} instead. Conventions (same as {@link CameraDef}): metres and radians,
 * Y is up and the ground is the XZ plane; {@code yaw = 0} looks along -Z, positive yaw turns toward
 * +X; positive pitch looks up. The projection is OpenGL's (clip-space depth in [-1, 1]).
 *
 * <p>Mutable and not thread-safe: one owner thread sets it; others may read a copy made with
 * {@link #set(ViewCamera)}. No method allocates except the constructors and {@link #of}.
 */
public final class ViewCamera implements Camera {
    private double x;
    private double y;
    private double z;
    private double yaw;
    private double pitch;
    private double fovY = Math.toRadians(60);
    private double aspect = 16.0 / 9.0;
    private double near = 0.1;
    private double far = 500;

    /** A camera at the origin looking along -Z, 60 degree vertical field of view, aspect 16:9, 0.1-500 m. */
    public ViewCamera() {
    }

    /**
     * A camera from a scene's start pose.
     *
     * @param def     pose and lens; its y is a height above the ground
     * @param groundY terrain height under (def.x, def.z), metres (finite)
     * @param aspect  viewport width / height, &gt; 0
     * @return a new camera (allocates)
     */
    public static ViewCamera of(CameraDef def, double groundY, double aspect) {
        Require.nonNull("def", def);
        ViewCamera c = new ViewCamera();
        c.setPosition(def.x(), Require.finite("groundY", groundY) + def.y(), def.z());
        c.setOrientation(def.yaw(), def.pitch());
        c.setLens(def.fovY(), aspect, def.near(), def.far());
        return c;
    }

    /**
     * Copies every setting of {@code other} into this camera. No allocation.
     *
     * @param other the camera to copy, not null
     * @return this camera
     */
    public ViewCamera set(ViewCamera other) {
        Require.nonNull("other", other);
        x = other.x;
        y = other.y;
        z = other.z;
        yaw = other.yaw;
        pitch = other.pitch;
        fovY = other.fovY;
        aspect = other.aspect;
        near = other.near;
        far = other.far;
        return this;
    }

    /**
     * Sets the eye position, metres (absolute, not above terrain). No allocation.
     *
     * @param x eye X, metres (finite)
     * @param y eye Y, metres above Y = 0, not above the terrain (finite)
     * @param z eye Z, metres (finite)
     */
    public void setPosition(double x, double y, double z) {
        this.x = Require.finite("x", x);
        this.y = Require.finite("y", y);
        this.z = Require.finite("z", z);
    }

    /**
     * Sets the view direction. No allocation.
     *
     * @param yaw   radians, 0 looks along -Z, positive turns toward +X (any finite value)
     * @param pitch radians in [-pi/2, pi/2], positive looks up
     */
    public void setOrientation(double yaw, double pitch) {
        this.yaw = Require.finite("yaw", yaw);
        this.pitch = Require.range("pitch", pitch, -Math.PI / 2, Math.PI / 2);
    }

    /**
     * Sets the lens. No allocation.
     *
     * @param fovY   vertical field of view, radians, in [1e-3, pi - 1e-3]
     * @param aspect width / height, &gt; 0
     * @param near   near clip distance, metres, &gt; 0
     * @param far    far clip distance, metres, &gt; near
     */
    public void setLens(double fovY, double aspect, double near, double far) {
        Require.range("fovY", fovY, 1e-3, Math.PI - 1e-3);
        Require.positive("aspect", aspect);
        Require.positive("near", near);
        Require.positive("far", far);
        if (far <= near) {
            throw new IllegalArgumentException("far must be > near, got far=" + far + " near=" + near);
        }
        this.fovY = fovY;
        this.aspect = aspect;
        this.near = near;
        this.far = far;
    }

    /** Eye X, metres. */
    @Override
    public double x() {
        return x;
    }

    /** Eye Y (absolute height), metres. */
    @Override
    public double y() {
        return y;
    }

    /** Eye Z, metres. */
    @Override
    public double z() {
        return z;
    }

    /**
     * Heading, radians (0 looks along -Z, positive toward +X).
     *
     * @return the yaw as last set, radians (not wrapped)
     */
    public double yaw() {
        return yaw;
    }

    /**
     * Pitch, radians (positive looks up).
     *
     * @return radians, in [-pi/2, pi/2]
     */
    public double pitch() {
        return pitch;
    }

    /**
     * Vertical field of view, radians.
     *
     * @return radians, in [1e-3, pi - 1e-3]
     */
    public double fovY() {
        return fovY;
    }

    /**
     * Viewport aspect ratio, width / height.
     *
     * @return width / height, &gt; 0
     */
    public double aspect() {
        return aspect;
    }

    /**
     * Near clip distance, metres.
     *
     * @return metres, &gt; 0
     */
    public double near() {
        return near;
    }

    /**
     * Far clip distance, metres.
     *
     * @return metres, &gt; {@link #near()}
     */
    public double far() {
        return far;
    }

    /**
     * The unit view direction in world space: (sin yaw cos pitch, sin pitch, -cos yaw cos pitch).
     * No allocation.
     */
    @Override
    public Vector3f forward(Vector3f dest) {
        double cp = Math.cos(pitch);
        return dest.set((float) (Math.sin(yaw) * cp), (float) Math.sin(pitch), (float) (-Math.cos(yaw) * cp));
    }

    /**
     * Writes the world-to-view matrix: {@code Rx(-pitch) * Ry(yaw) * T(-eye)}, the inverse of the
     * camera's world transform {@code T(eye) * Ry(-yaw) * Rx(pitch)}. No allocation.
     */
    @Override
    public Matrix4f view(Matrix4f dest) {
        return write(dest, 1, 1, 0, 0, false);
    }

    /** Writes the OpenGL perspective projection (depth in [-1, 1]). No allocation. */
    @Override
    public Matrix4f projection(Matrix4f dest) {
        double h = Math.tan(fovY * 0.5);
        double p22 = (far + near) / (near - far);
        double p23 = 2 * far * near / (near - far);
        return dest.set((float) (1 / (h * aspect)), 0, 0, 0, 0, (float) (1 / h), 0, 0, 0, 0, (float) p22, -1, 0, 0,
                (float) p23, 0);
    }

    /** Writes projection * view: world to clip space. No allocation. */
    @Override
    public Matrix4f viewProjection(Matrix4f dest) {
        double h = Math.tan(fovY * 0.5);
        return write(dest, 1 / (h * aspect), 1 / h, (far + near) / (near - far), 2 * far * near / (near - far), true);
    }

    /**
     * Writes diag(sx, sy, P) * [R | -R eye] with R = Rx(-pitch) Ry(yaw), where P is the perspective's
     * depth rows (p22, p23, and row 3 = -R row 2) when {@code perspective}, else the identity. Plain
     * arithmetic on the matrix fields: the per-frame path calls no JOML helper that might allocate
     * after a deoptimisation. Column-major arguments as {@link Matrix4f#set(float, float, float, float,
     * float, float, float, float, float, float, float, float, float, float, float, float)} takes them.
     */
    private Matrix4f write(Matrix4f dest, double sx, double sy, double p22, double p23, boolean perspective) {
        double cy = Math.cos(yaw);
        double sny = Math.sin(yaw);
        double ca = Math.cos(-pitch);
        double sa = Math.sin(-pitch);
        // rows of R
        double r00 = cy;
        double r01 = 0;
        double r02 = sny;
        double r10 = sa * sny;
        double r11 = ca;
        double r12 = -sa * cy;
        double r20 = -ca * sny;
        double r21 = sa;
        double r22 = ca * cy;
        double t0 = -(r00 * x + r01 * y + r02 * z);
        double t1 = -(r10 * x + r11 * y + r12 * z);
        double t2 = -(r20 * x + r21 * y + r22 * z);
        if (!perspective) {
            return dest.set((float) r00, (float) r10, (float) r20, 0, (float) r01, (float) r11, (float) r21, 0,
                    (float) r02, (float) r12, (float) r22, 0, (float) t0, (float) t1, (float) t2, 1);
        }
        return dest.set(
                (float) (sx * r00), (float) (sy * r10), (float) (p22 * r20), (float) -r20,
                (float) (sx * r01), (float) (sy * r11), (float) (p22 * r21), (float) -r21,
                (float) (sx * r02), (float) (sy * r12), (float) (p22 * r22), (float) -r22,
                (float) (sx * t0), (float) (sy * t1), (float) (p22 * t2 + p23), (float) -t2);
    }

    @Override
    public double viewHeightPerMetre() {
        return 2 * Math.tan(fovY * 0.5);
    }

    @Override
    public double viewHeightAtEye() {
        return 0;
    }
}
