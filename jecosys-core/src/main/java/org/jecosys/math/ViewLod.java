package org.jecosys.math;

import org.joml.Matrix4f;

/**
 * Level of detail by projected size (paper §4.1, Table 3): the distances of the levels are set for
 * one lens, {@link org.jecosys.field.ForceFieldDef#lodFovY()}; a view picks the level that a plant's
 * size on its screen gives, as if seen through that lens. Through a perspective lens of vertical
 * scale {@code P11 = 1 / tan(fovY / 2)} (the projection matrix's {@code m11}), a plant at distance
 * {@code d} has the size it would have at the <em>equivalent distance</em>
 * {@code d * P11ref / P11} through the reference lens; through an orthographic projection, whose size
 * on screen does not depend on distance, at {@code P11ref / P11} (with {@code P11 = 2 / viewHeight}).
 * So a narrow lens keeps detail farther away, a wide one less far, and an orthographic top view
 * picks the same level as a perspective view that shows the plant at the same size. Through the
 * reference lens itself the equivalent distance is the distance, bit for bit.
 *
 * <p>A view's metric is two numbers: the square of the scale on squared distances, and, for an
 * orthographic view, the fixed squared equivalent distance ({@code < 0} for perspective). Any thread;
 * no allocation.
 */
public final class ViewLod {
    /** Scales this close to 1 are 1: the reference lens gives the distance exactly. */
    static final double SNAP = 1e-6;

    private ViewLod() {
    }

    /**
     * {@return {@code 1 / tan(fovY / 2)}, the reference lens's vertical scale}
     *
     * @param fovY the reference vertical field of view, radians, in (0, pi)
     */
    public static double referenceScale(double fovY) {
        Require.above("fovY", fovY, 0, Math.PI - 1e-9);
        return 1 / Math.tan(fovY / 2);
    }

    /**
     * The metric of a view. No allocation.
     *
     * @param projection the view's projection matrix (OpenGL convention)
     * @param reference  {@link #referenceScale} of the scene's LOD lens
     * @param dest       receives {@code {scale^2, fixed^2}}: the squared equivalent distance is
     *                   {@code fixed^2} when {@code fixed^2 >= 0} (orthographic), else
     *                   {@code scale^2 * d^2}
     * @return {@code dest}
     */
    public static double[] metric(Matrix4f projection, double reference, double[] dest) {
        double p11 = Math.abs(projection.m11());
        boolean orthographic = projection.m23() == 0 && projection.m33() != 0;
        if (!(p11 > 0) || !Double.isFinite(p11)) {
            dest[0] = 1;
            dest[1] = -1;
            return dest;
        }
        double k = reference / p11;
        if (orthographic) {
            dest[0] = 1;
            dest[1] = k * k;
        } else {
            if (Math.abs(k - 1) < SNAP) {
                k = 1;
            }
            dest[0] = k * k;
            dest[1] = -1;
        }
        return dest;
    }

    /**
     * The metric of a camera, through {@code scratch} (overwritten). No allocation.
     *
     * @param camera    the view
     * @param reference {@link #referenceScale} of the scene's LOD lens
     * @param scratch   a matrix to hold the projection
     * @param dest      receives {@code {scale^2, fixed^2}} (see {@link #metric(Matrix4f, double, double[])})
     * @return {@code dest}
     */
    public static double[] metric(Camera camera, double reference, Matrix4f scratch, double[] dest) {
        return metric(camera.projection(scratch), reference, dest);
    }

    /**
     * {@return the squared equivalent distance of a plant at squared distance {@code d2}, metres^2}
     *
     * @param d2      squared distance from the eye, metres^2
     * @param scale2  the view's {@code scale^2}
     * @param fixed2  the view's {@code fixed^2}, or {@code < 0} for a perspective view
     */
    public static double equivalent2(double d2, double scale2, double fixed2) {
        return fixed2 >= 0 ? fixed2 : d2 * scale2;
    }
}
