package org.jecosys.math;

import org.joml.Matrix4f;
import org.joml.Vector3f;

/**
 * What the force field, the simulation and the renderer need to know of a viewer: the eye, the view
 * direction and OpenGL's view and projection matrices. The field culls its quadtree against the
 * frustum of {@link #viewProjection} and measures LOD distances from the eye (paper §3.1.1); the
 * renderer draws with the same matrices. World conventions: metres, Y up, the ground is the XZ plane.
 *
 * <p>Two implementations: {@link ViewCamera}, the convenient form (position, yaw, pitch and a
 * perspective lens), and {@link MatrixCamera}, which takes a game's own view and projection matrices
 * (roll, off-axis and orthographic projections included). Implementations are mutable and not
 * thread-safe: one owner thread sets them; pass a copy to another thread. No method allocates.
 */
public interface Camera {
    /**
     * Eye X, metres.
     *
     * @return the eye's world X coordinate
     */
    double x();

    /**
     * Eye Y (absolute height), metres.
     *
     * @return the eye's world Y coordinate
     */
    double y();

    /**
     * Eye Z, metres.
     *
     * @return the eye's world Z coordinate
     */
    double z();

    /**
     * Writes the unit view direction in world space. No allocation.
     *
     * @param dest where to write
     * @return {@code dest}
     */
    Vector3f forward(Vector3f dest);

    /**
     * Writes the world-to-view matrix. No allocation.
     *
     * @param dest where to write
     * @return {@code dest}
     */
    Matrix4f view(Matrix4f dest);

    /**
     * Writes the OpenGL projection matrix (clip-space depth in [-1, 1]). No allocation.
     *
     * @param dest where to write
     * @return {@code dest}
     */
    Matrix4f projection(Matrix4f dest);

    /**
     * Writes projection * view: world to clip space. No allocation.
     *
     * @param dest where to write
     * @return {@code dest}
     */
    Matrix4f viewProjection(Matrix4f dest);

    /**
     * The height of the view, in metres, that one unit of distance from the eye adds: 2 tan(fovY / 2)
     * for a perspective projection, 0 for an orthographic one. With {@link #viewHeightAtEye()} it gives
     * the world size of a pixel at distance d as {@code (viewHeightAtEye() + d * viewHeightPerMetre())
     * / viewportHeight}, which the renderer uses to keep thin parts at least a pixel wide.
     *
     * @return metres of view height per metre of distance, &ge; 0
     */
    double viewHeightPerMetre();

    /**
     * The height of the view at the eye, metres: 0 for a perspective projection, the height of the
     * view volume for an orthographic one. See {@link #viewHeightPerMetre()}.
     *
     * @return metres, &ge; 0
     */
    double viewHeightAtEye();

    /**
     * Whether the camera's eye and its view-projection matrix are finite (no NaN, no infinity). Any
     * thread that may read the camera; no allocation.
     *
     * @param c       the camera
     * @param scratch receives the view-projection matrix
     * @return true when every coordinate and matrix element is finite
     */
    static boolean isFinite(Camera c, Matrix4f scratch) {
        if (!(Double.isFinite(c.x()) && Double.isFinite(c.y()) && Double.isFinite(c.z()))) {
            return false;
        }
        return c.viewProjection(scratch).isFinite();
    }

    /**
     * Refuses a camera whose eye or view-projection matrix is not finite: such a camera would
     * silently cull everything (nothing animates, nothing is drawn). The simulation checks its step's
     * camera and registered views each fixed step, the renderer each frame. No allocation unless it
     * throws.
     *
     * @param what    the camera's name in the message ("camera", "view 2")
     * @param c       the camera
     * @param scratch receives the view-projection matrix
     * @throws IllegalArgumentException saying what is not finite
     */
    static void requireFinite(String what, Camera c, Matrix4f scratch) {
        if (isFinite(c, scratch)) {
            return;
        }
        if (!(Double.isFinite(c.x()) && Double.isFinite(c.y()) && Double.isFinite(c.z()))) {
            throw new IllegalArgumentException(what + ": its eye position must be finite, got (" + c.x() + ", "
                    + c.y() + ", " + c.z() + ") metres");
        }
        throw new IllegalArgumentException(what + ": its view-projection matrix (projection * view) must be finite, got "
                + c.viewProjection(scratch).toString().replace('\n', ' ').trim());
    }
}
