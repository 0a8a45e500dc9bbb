package org.jecosys.math;

import org.joml.Matrix4f;
import org.joml.Matrix4fc;
import org.joml.Vector3f;

/**
 * The base of an engine adapter's camera (libGDX's {@code GdxCamera}, jMonkeyEngine's
 * {@code JmeCamera}): a {@link Camera} whose matrices the host engine computes. A subclass copies the
 * host camera's view and projection into {@link #set} each frame; every {@link Camera} query then
 * answers from them as a {@link MatrixCamera} does (the eye, the view direction and the pixel footprint
 * derived once per {@code set}).
 *
 * <p>Mutable and not thread-safe: the thread that owns it (the host's render thread) sets it and hands
 * it to the simulation and the renderer. No method allocates after construction.
 */
public abstract class HostCamera implements Camera {
    private final MatrixCamera camera = new MatrixCamera();

    /** An identity view and projection until the first {@link #set}. Allocates this object only. */
    protected HostCamera() {
    }

    /**
     * Copies the host camera's matrices ({@link MatrixCamera#set}). No allocation.
     *
     * @param view       world to view; finite, a rotation and a translation
     * @param projection view to clip space, OpenGL conventions; perspective or orthographic
     * @throws IllegalArgumentException when a matrix is not finite, the view is not rigid or the
     *                                  projection is neither perspective nor orthographic
     */
    protected final void set(Matrix4fc view, Matrix4fc projection) {
        camera.set(view, projection);
    }

    @Override
    public final double x() {
        return camera.x();
    }

    @Override
    public final double y() {
        return camera.y();
    }

    @Override
    public final double z() {
        return camera.z();
    }

    @Override
    public final Vector3f forward(Vector3f dest) {
        return camera.forward(dest);
    }

    @Override
    public final Matrix4f view(Matrix4f dest) {
        return camera.view(dest);
    }

    @Override
    public final Matrix4f projection(Matrix4f dest) {
        return camera.projection(dest);
    }

    @Override
    public final Matrix4f viewProjection(Matrix4f dest) {
        return camera.viewProjection(dest);
    }

    @Override
    public final double viewHeightPerMetre() {
        return camera.viewHeightPerMetre();
    }

    @Override
    public final double viewHeightAtEye() {
        return camera.viewHeightAtEye();
    }
}
