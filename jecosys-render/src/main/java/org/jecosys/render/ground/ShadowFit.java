package org.jecosys.render.ground;

import java.nio.FloatBuffer;
import org.jecosys.math.Camera;
import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.lwjgl.system.MemoryUtil;

/**
 * Where the sun's shadow map ({@link SunShadowMap}) lies, worked out per frame without GL: an
 * orthographic view along the sun over the sphere that holds the camera's frustum from the eye to
 * {@code reach} metres. The sphere's size depends only on the reach and the lens, not on where the
 * camera looks, and its centre is moved to whole texels of a grid fixed to the sun's direction, so a
 * texel covers the same patch of the world while the camera moves and turns: the shadows' edges do not
 * swim. The view reaches {@link #CASTER_MARGIN} beyond the sphere toward the sun, so plants there still
 * cast into it.
 *
 * <p>Render thread (or any single owner); allocates at construction only ({@link #close()} frees the
 * matrices' native copies; idempotent).
 */
public final class ShadowFit implements AutoCloseable {
    /** How far beyond the covered sphere, toward the sun, plants still cast into the map, metres. */
    public static final double CASTER_MARGIN = 30;
    /** Depth bias of a receiver, metres along the sun's rays (no plant shades itself by rounding). */
    public static final double BIAS_METRES = 0.03;

    private final int size;
    private final Matrix4f sunView = new Matrix4f();
    private final Matrix4f projection = new Matrix4f();
    private final Matrix4f viewProjection = new Matrix4f();
    private final Matrix4f shadowMatrix = new Matrix4f();
    private final Matrix4f scratch = new Matrix4f();
    private final Vector3f forward = new Vector3f();
    private final Vector3f centre = new Vector3f();
    private final FloatBuffer viewProjectionBuffer;
    private final FloatBuffer shadowBuffer;
    private final double[] sunward = new double[3];
    private double texelMetres;
    private double bias;
    private double radius;
    private boolean closed;

    /**
     * A fit for a map of {@code size x size} texels. Allocates.
     *
     * @param size texels along each side, in [16, 8192]
     */
    public ShadowFit(int size) {
        if (size < 16 || size > 8192) {
            throw new IllegalArgumentException("shadow map size must be in [16, 8192], got " + size);
        }
        this.size = size;
        viewProjectionBuffer = MemoryUtil.memAllocFloat(16);
        shadowBuffer = MemoryUtil.memAllocFloat(16);
    }

    /**
     * Fits the map to a view and a sun (see the class comment). No allocation.
     *
     * @param camera the view whose near part the map covers (a symmetric perspective projection)
     * @param lx     unit vector toward the sun, X
     * @param ly     unit vector toward the sun, Y (&gt; 0)
     * @param lz     unit vector toward the sun, Z
     * @param reach  distance from the eye the map covers, metres, &gt; 0
     */
    public void fit(Camera camera, float lx, float ly, float lz, double reach) {
        camera.projection(scratch);
        // the frustum's corner at depth z lies z * k off its axis: k^2 = tan(half fovX)^2 + tan(half fovY)^2
        double k2 = 1 / ((double) scratch.m00() * scratch.m00()) + 1 / ((double) scratch.m11() * scratch.m11());
        // the sphere's centre m metres along the axis: as near the eye as holds both the eye and the far corners
        double m = Math.min(reach, 0.5 * reach * (1 + k2));
        radius = Math.max(Math.sqrt((reach - m) * (reach - m) + reach * reach * k2), m);
        camera.forward(forward);
        double ox = camera.x() + forward.x * m;
        double oy = camera.y() + forward.y * m;
        double oz = camera.z() + forward.z * m;
        texelMetres = 2 * radius / size;
        // the sun's fixed frame: looking along -L from the origin (up: +Y, or +Z under a sun near the zenith)
        boolean high = Math.abs(ly) > 0.99f;
        sunView.setLookAt(lx, ly, lz, 0, 0, 0, 0, high ? 0 : 1, high ? 1 : 0);
        centre.set((float) ox, (float) oy, (float) oz);
        sunView.transformPosition(centre);
        double cx = Math.floor(centre.x / texelMetres + 0.5) * texelMetres;
        double cy = Math.floor(centre.y / texelMetres + 0.5) * texelMetres;
        double cz = centre.z;
        double near = -(cz + radius + CASTER_MARGIN);
        double far = -(cz - radius);
        projection.setOrtho((float) (cx - radius), (float) (cx + radius), (float) (cy - radius), (float) (cy + radius),
                (float) near, (float) far);
        projection.mul(sunView, viewProjection);
        // clip [-1, 1] to texture coordinates and depth [0, 1]
        shadowMatrix.translation(0.5f, 0.5f, 0.5f).scale(0.5f).mul(viewProjection);
        viewProjection.get(viewProjectionBuffer);
        shadowMatrix.get(shadowBuffer);
        bias = BIAS_METRES / (far - near);
        // a point far toward the sun over the middle of the map: the casters' "eye", across which thin
        // parts are widened to a texel
        double d = radius + CASTER_MARGIN + 1000;
        sunward[0] = ox + lx * d;
        sunward[1] = oy + ly * d;
        sunward[2] = oz + lz * d;
    }

    /** {@return texels along each side} */
    public int size() {
        return size;
    }

    /** {@return the sun's view-projection of the last {@link #fit} (column-major, 16 floats), for the casters} */
    public FloatBuffer viewProjection() {
        return viewProjectionBuffer;
    }

    /** {@return world to map coordinates (texel and depth in [0, 1]) of the last {@link #fit}, 16 floats} */
    public FloatBuffer shadowMatrix() {
        return shadowBuffer;
    }

    /**
     * Writes the world-to-map transform of the last {@link #fit} into dest (texel coordinates and depth
     * in [0, 1]). No allocation.
     *
     * @param dest where to write
     * @return {@code dest}
     */
    public Matrix4f shadowMatrix(Matrix4f dest) {
        return dest.set(shadowMatrix);
    }

    /** {@return the side of a texel, metres, of the last {@link #fit}} */
    public double texelMetres() {
        return texelMetres;
    }

    /** {@return the radius of the sphere the last {@link #fit} covers, metres} */
    public double radius() {
        return radius;
    }

    /** {@return a receiver's depth bias of the last {@link #fit}, map depth units} */
    public double bias() {
        return bias;
    }

    /**
     * A point far toward the sun over the map's middle (the casters' eye), metres.
     *
     * @param axis 0 X, 1 Y, 2 Z
     * @return the coordinate
     */
    public double sunward(int axis) {
        return sunward[axis];
    }

    /** Frees the matrices' native copies. Idempotent. */
    @Override
    public void close() {
        if (!closed) {
            closed = true;
            MemoryUtil.memFree((java.nio.Buffer) viewProjectionBuffer);
            MemoryUtil.memFree((java.nio.Buffer) shadowBuffer);
        }
    }
}
