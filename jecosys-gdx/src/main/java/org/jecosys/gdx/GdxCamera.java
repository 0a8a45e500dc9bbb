package org.jecosys.gdx;

import org.jecosys.math.Camera;
import org.jecosys.math.HostCamera;
import org.joml.Matrix4f;

/**
 * A libGDX {@link com.badlogic.gdx.graphics.Camera} seen as a JEcoSys {@link Camera}: the force field
 * culls and picks levels of detail with it and the renderer draws with its matrices. {@link #update}
 * copies the libGDX camera's {@code view} and {@code projection} matrices ({@code Matrix4.val},
 * column-major, OpenGL conventions, as {@code camera.update()} left them); a
 * {@code PerspectiveCamera} and an {@code OrthographicCamera} both work. World units are the library's:
 * metres, Y up, the ground in the XZ plane.
 *
 * <p>Mutable and not thread-safe: the thread that owns it (libGDX's render thread) calls
 * {@link #update} and hands it to the simulation and the renderer. No method allocates after
 * construction.
 */
public final class GdxCamera extends HostCamera {
    private final Matrix4f view = new Matrix4f();
    private final Matrix4f projection = new Matrix4f();

    /** An identity view and projection until the first {@link #update}. Allocates this object only. */
    public GdxCamera() {
    }

    /**
     * Copies the matrices of a libGDX camera, as they are after its {@code update()}. No allocation.
     *
     * @param camera the game's camera; its view must be a rotation and a translation (what libGDX's
     *               cameras make) and its projection perspective or orthographic
     * @return this camera
     * @throws IllegalArgumentException when the matrices are not finite, the view is not rigid, or the
     *                                  projection is neither perspective nor orthographic
     */
    public GdxCamera update(com.badlogic.gdx.graphics.Camera camera) {
        view.set(camera.view.val);
        projection.set(camera.projection.val);
        set(view, projection);
        return this;
    }
}
