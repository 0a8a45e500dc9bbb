package org.jecosys.math;

import org.joml.Matrix4f;
import org.joml.Matrix4fc;
import org.joml.Vector3f;

/**
 * A {@link Camera} from a game's own view and projection matrices (JOML, column-major, OpenGL
 * conventions: the view looks along its -Z, clip-space depth in [-1, 1]). Any rigid view works (roll
 * included) and any projection: perspective, off-axis (asymmetric frustum) or orthographic. The eye
 * and the view direction are derived from the inverse of the view matrix; the pixel footprint from the
 * projection's vertical scale.
 *
 * <p>Mutable and not thread-safe: the owner thread calls {@link #set} (typically once per game frame)
 * and passes the camera to {@code Simulation.step} and the renderer on the same thread. No method
 * allocates after construction.
 */
public final class MatrixCamera implements Camera {
    private final Matrix4f view = new Matrix4f();
    private final Matrix4f projection = new Matrix4f();
    private final Matrix4f viewProjection = new Matrix4f();
    private double x;
    private double y;
    private double z;
    private float fx;
    private float fy;
    private float fz = -1;
    private double perMetre;
    private double atEye;

    /** An identity view (eye at the origin looking along -Z) and an identity (orthographic) projection. */
    public MatrixCamera() {
        set(view, projection);
    }

    /**
     * A camera with the given matrices. Allocates this object only.
     *
     * @param view       world to view, a rigid transform (rotation and translation)
     * @param projection view to clip space, OpenGL conventions
     */
    public MatrixCamera(Matrix4fc view, Matrix4fc projection) {
        set(view, projection);
    }

    /**
     * Copies the matrices and derives the eye, the view direction and the pixel footprint. The view
     * must be a rigid transform (its upper 3x3 orthonormal): its inverse is taken as the transpose.
     * No allocation.
     *
     * @param view       world to view; finite, rigid (checked to 1e-3)
     * @param projection view to clip space; finite, invertible, row 4 either (0, 0, -1, 0)
     *                   (perspective) or (0, 0, 0, 1) (orthographic)
     * @return this camera
     * @throws IllegalArgumentException when a matrix is not finite, the view is not rigid or the
     *                                  projection is neither perspective nor orthographic
     */
    public MatrixCamera set(Matrix4fc view, Matrix4fc projection) {
        Require.nonNull("view", view);
        Require.nonNull("projection", projection);
        if (!view.isFinite() || !projection.isFinite()) {
            throw new IllegalArgumentException("camera matrices must be finite");
        }
        // rigid: columns of the 3x3 part are orthonormal
        double c0 = view.m00() * view.m00() + view.m01() * view.m01() + view.m02() * view.m02();
        double c1 = view.m10() * view.m10() + view.m11() * view.m11() + view.m12() * view.m12();
        double c2 = view.m20() * view.m20() + view.m21() * view.m21() + view.m22() * view.m22();
        double d01 = view.m00() * view.m10() + view.m01() * view.m11() + view.m02() * view.m12();
        double d02 = view.m00() * view.m20() + view.m01() * view.m21() + view.m02() * view.m22();
        double d12 = view.m10() * view.m20() + view.m11() * view.m21() + view.m12() * view.m22();
        if (Math.abs(c0 - 1) > 1e-3 || Math.abs(c1 - 1) > 1e-3 || Math.abs(c2 - 1) > 1e-3 || Math.abs(d01) > 1e-3
                || Math.abs(d02) > 1e-3 || Math.abs(d12) > 1e-3 || view.m03() != 0 || view.m13() != 0
                || view.m23() != 0 || view.m33() != 1) {
            throw new IllegalArgumentException("the view matrix must be a rotation and a translation (no scale, "
                    + "shear or projection)");
        }
        boolean perspective = projection.m03() == 0 && projection.m13() == 0 && projection.m23() == -1
                && projection.m33() == 0;
        boolean ortho = projection.m03() == 0 && projection.m13() == 0 && projection.m23() == 0
                && projection.m33() == 1;
        if (!perspective && !ortho) {
            throw new IllegalArgumentException("the projection must be perspective (last row 0, 0, -1, 0) or "
                    + "orthographic (last row 0, 0, 0, 1)");
        }
        if (projection.m11() == 0 || projection.m00() == 0) {
            throw new IllegalArgumentException("the projection must be invertible (its x and y scales are not 0)");
        }
        this.view.set(view);
        this.projection.set(projection);
        this.projection.mul(this.view, viewProjection);
        // eye = -R^T t, with R the 3x3 rows and t the translation column
        double tx = view.m30();
        double ty = view.m31();
        double tz = view.m32();
        x = -(view.m00() * tx + view.m01() * ty + view.m02() * tz);
        y = -(view.m10() * tx + view.m11() * ty + view.m12() * tz);
        z = -(view.m20() * tx + view.m21() * ty + view.m22() * tz);
        // the view looks along its -Z: forward = -(row 2 of R)
        fx = -view.m02();
        fy = -view.m12();
        fz = -view.m22();
        double sy = Math.abs(projection.m11());
        perMetre = perspective ? 2 / sy : 0;
        atEye = perspective ? 0 : 2 / sy;
        return this;
    }

    /**
     * Copies another camera's matrices. No allocation.
     *
     * @param other the camera to copy
     * @return this camera
     */
    public MatrixCamera set(MatrixCamera other) {
        return set(Require.nonNull("other", other).view, other.projection);
    }

    @Override
    public double x() {
        return x;
    }

    @Override
    public double y() {
        return y;
    }

    @Override
    public double z() {
        return z;
    }

    @Override
    public Vector3f forward(Vector3f dest) {
        return dest.set(fx, fy, fz);
    }

    @Override
    public Matrix4f view(Matrix4f dest) {
        return dest.set(view);
    }

    @Override
    public Matrix4f projection(Matrix4f dest) {
        return dest.set(projection);
    }

    @Override
    public Matrix4f viewProjection(Matrix4f dest) {
        return dest.set(viewProjection);
    }

    @Override
    public double viewHeightPerMetre() {
        return perMetre;
    }

    @Override
    public double viewHeightAtEye() {
        return atEye;
    }
}
