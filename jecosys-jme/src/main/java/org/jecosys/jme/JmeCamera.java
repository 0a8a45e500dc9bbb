package org.jecosys.jme;

import org.jecosys.math.Camera;
import org.jecosys.math.HostCamera;
import org.joml.Matrix4f;

/**
 * A jMonkeyEngine {@link com.jme3.renderer.Camera} seen as a JEcoSys {@link Camera}: the force field
 * culls and picks levels of detail with it and the renderer draws with its matrices. {@link #update}
 * copies the jME camera's view and projection matrices ({@code getViewMatrix()},
 * {@code getProjectionMatrix()}, OpenGL conventions); perspective and parallel projections both
 * work. World units are the library's: metres, Y up, the ground in the XZ plane.
 *
 * <p>Mutable and not thread-safe: the thread that owns it (jME's render thread, "jME3 Main") calls
 * {@link #update} and hands it to the simulation and the renderer. No method allocates after
 * construction.
 */
public final class JmeCamera extends HostCamera {
    private final Matrix4f view = new Matrix4f();
    private final Matrix4f projection = new Matrix4f();
    private final float[] columns = new float[16];

    /** An identity view and projection until the first {@link #update}. Allocates this object only. */
    public JmeCamera() {
    }

    /**
     * Copies the matrices of a jME camera (as its last {@code update()} or frame left them). No
     * allocation.
     *
     * @param camera the game's camera (a viewport's, typically {@code app.getCamera()}); its view must
     *               be a rotation and a translation (what jME's cameras make) and its projection
     *               perspective or parallel
     * @return this camera
     * @throws IllegalArgumentException when the matrices are not finite, the view is not rigid, or the
     *                                  projection is neither perspective nor parallel
     */
    public JmeCamera update(com.jme3.renderer.Camera camera) {
        camera.getViewMatrix().fillFloatArray(columns, true);
        view.set(columns);
        camera.getProjectionMatrix().fillFloatArray(columns, true);
        projection.set(columns);
        set(view, projection);
        return this;
    }
}
