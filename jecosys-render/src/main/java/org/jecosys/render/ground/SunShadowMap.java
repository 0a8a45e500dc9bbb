package org.jecosys.render.ground;

import java.nio.FloatBuffer;
import org.jecosys.math.Camera;
import org.jecosys.render.gl.GlDepthMap;
import org.jecosys.render.gl.GlTracker;
import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.lwjgl.system.MemoryUtil;

/**
 * The sun's shadow map, the light's full path (issue 26): the plants' depth seen from the sun, drawn
 * every frame with the plants as they sway, read by the plants (so they shade each other), the ground
 * cover's blades and the terrain ({@code sun_shadow.glsl}). Beyond its reach the ground keeps the
 * splatted rest-pose shadows of {@link SunShadow}, the cheap path, which the map fades into.
 *
 * <p>Fitted to the view ({@link #fit}): an orthographic view along the sun over the sphere that holds
 * the camera's frustum from the eye to {@code reach} metres. The sphere's size depends only on the
 * reach and the lens, not on where the camera looks, and its centre is moved to whole texels of a
 * grid fixed to the sun's direction, so a texel covers the same patch of ground while the camera moves
 * and turns: the shadows' edges do not swim.
 *
 * <p>Render thread; allocates at construction only. {@link #close()} deletes the map; idempotent.
 */
public final class SunShadowMap implements AutoCloseable {
    /** Default texels along each side of the map. */
    public static final int DEFAULT_SIZE = 2048;
    /** Default reach: the map covers the view from the eye to this distance, metres. */
    public static final double DEFAULT_REACH = 20;
    /** How far beyond the covered sphere, toward the sun, plants still cast into it, metres. */
    static final double CASTER_MARGIN = 30;
    /** Depth bias of a receiver, metres along the sun's rays (no plant shadows itself by rounding). */
    static final double BIAS_METRES = 0.03;

    private final GlDepthMap map;
    private final Matrix4f rotation = new Matrix4f();
    private final Matrix4f projection = new Matrix4f();
    private final Matrix4f viewProjection = new Matrix4f();
    private final Matrix4f shadowMatrix = new Matrix4f();
    private final Matrix4f scratch = new Matrix4f();
    private final Vector3f forward = new Vector3f();
    private final Vector3f centre = new Vector3f();
    private final FloatBuffer viewProjectionBuffer;
    private final FloatBuffer shadowBuffer;
    private double texelMetres;
    private double bias;
    private double radius;
    private final double[] sunward = new double[3];

    /**
     * Makes the map. Render thread; allocates.
     *
     * @param tracker counts the GL objects
     * @param size    texels along each side, in [16, 8192]
     * @throws IllegalArgumentException when the size is out of range
     * @throws IllegalStateException    when the GL cannot draw into a depth texture
     */
    public SunShadowMap(GlTracker tracker, int size) {
        map = new GlDepthMap(tracker, size);
        viewProjectionBuffer = MemoryUtil.memAllocFloat(16);
        shadowBuffer = MemoryUtil.memAllocFloat(16);
    }

    /** {@return the depth map (draw into it between its begin and end; bind it for reading)} */
    public GlDepthMap map() {
        return map;
    }

    /**
     * Fits the map to a view and a sun (see the class comment). No allocation.
     *
     * @param camera the view whose near part the map covers (a perspective projection)
     * @param lx     unit vector toward the sun, X
     * @param ly     unit vector toward the sun, Y (&gt; 0)
     * @param lz     unit vector toward the sun, Z
     * @param reach  distance from the eye the map covers, metres, &gt; 0
     */
    public void fit(Camera camera, float lx, float ly, float lz, double reach) {
        camera.projection(scratch);
        // half the diagonal of the view per metre of depth: tan(half fovX)^2 + tan(half fovY)^2
        double k2 = 1 / ((double) scratch.m00() * scratch.m00()) + 1 / ((double) scratch.m11() * scratch.m11());
        double m = Math.min(reach, 0.5 * reach * (1 + k2));
        radius = Math.max(Math.sqrt((reach - m) * (reach - m) + reach * reach * k2), m);
        camera.forward(forward);
        centre.set((float) (camera.x() + forward.x * m), (float) (camera.y() + forward.y * m),
                (float) (camera.z() + forward.z * m));
        int size = map.size();
        texelMetres = 2 * radius / size;
        // the sun's fixed frame: looking along -L from the origin
        boolean high = Math.abs(ly) > 0.99f;
        rotation.setLookAt(lx, ly, lz, 0, 0, 0, high ? 0 : 0, high ? 0 : 1, high ? 1 : 0);
        rotation.transformPosition(centre);
        double cx = Math.floor(centre.x / texelMetres + 0.5) * texelMetres;
        double cy = Math.floor(centre.y / texelMetres + 0.5) * texelMetres;
        double cz = centre.z;
        double near = -(cz + radius + CASTER_MARGIN);
        double far = -(cz - radius);
        projection.setOrtho((float) (cx - radius), (float) (cx + radius), (float) (cy - radius), (float) (cy + radius),
                (float) near, (float) far);
        projection.mul(rotation, viewProjection);
        // clip [-1, 1] to texture coordinates and depth [0, 1]
        shadowMatrix.translation(0.5f, 0.5f, 0.5f).scale(0.5f).mul(viewProjection);
        viewProjection.get(viewProjectionBuffer);
        shadowMatrix.get(shadowBuffer);
        bias = BIAS_METRES / (far - near);
        // a point far toward the sun over the middle of the map: the casters' "eye", across which
        // thin parts are widened to a texel
        double d = radius + CASTER_MARGIN + 1000;
        sunward[0] = camera.x() + forward.x * m + lx * d;
        sunward[1] = camera.y() + forward.y * m + ly * d;
        sunward[2] = camera.z() + forward.z * m + lz * d;
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

    /** {@return the side of a texel on the ground under a high sun, metres, of the last {@link #fit}} */
    public double texelMetres() {
        return texelMetres;
    }

    /** {@return the radius of the sphere the last {@link #fit} covers, metres} */
    public double radius() {
        return radius;
    }

    /** {@return a receiver's depth bias, map depth units} */
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

    /** Deletes the map and frees the matrices' memory. Render thread; idempotent. */
    @Override
    public void close() {
        if (!map.closed()) {
            map.close();
            MemoryUtil.memFree((java.nio.Buffer) viewProjectionBuffer);
            MemoryUtil.memFree((java.nio.Buffer) shadowBuffer);
        }
    }
}
