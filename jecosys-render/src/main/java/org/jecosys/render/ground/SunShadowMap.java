package org.jecosys.render.ground;

import org.jecosys.math.Camera;
import org.jecosys.render.gl.GlDepthMap;
import org.jecosys.render.gl.GlTracker;

/**
 * The sun's shadow map, the light's full path (issue 26; {@code ShadowPath.MAP}): the plants' depth
 * seen from the sun, drawn every frame with the plants as they sway, read by the plants (so they shade
 * each other), the ground cover's blades and the terrain ({@code sun_shadow.glsl}). Beyond its reach the
 * ground keeps the splatted rest-pose shadows of {@link SunShadow}, the cheap path, which the map fades
 * into. Where it lies each frame: {@link ShadowFit}.
 *
 * <p>Render thread; allocates at construction only. {@link #close()} deletes the map; idempotent.
 */
public final class SunShadowMap implements AutoCloseable {
    /** Default texels along each side of the map. */
    public static final int DEFAULT_SIZE = 2048;
    /** Default reach: the map covers the view from the eye to this distance, metres. */
    public static final double DEFAULT_REACH = 20;

    private final GlDepthMap map;
    private final ShadowFit fit;

    /**
     * Makes the map. Render thread; allocates.
     *
     * @param tracker counts the GL objects
     * @param size    texels along each side, in [16, 8192]
     * @throws IllegalArgumentException when the size is out of range
     * @throws IllegalStateException    when the GL cannot draw into a depth texture
     */
    public SunShadowMap(GlTracker tracker, int size) {
        fit = new ShadowFit(size);
        try {
            map = new GlDepthMap(tracker, size);
        } catch (RuntimeException | Error e) {
            fit.close();
            throw e;
        }
    }

    /** {@return the depth map (draw into it between its begin and end; bind it for reading)} */
    public GlDepthMap map() {
        return map;
    }

    /** {@return where the map lies: the last {@link #fit}} */
    public ShadowFit placement() {
        return fit;
    }

    /**
     * Fits the map to a view and a sun ({@link ShadowFit#fit}). No allocation.
     *
     * @param camera the view whose near part the map covers
     * @param lx     unit vector toward the sun, X
     * @param ly     unit vector toward the sun, Y (&gt; 0)
     * @param lz     unit vector toward the sun, Z
     * @param reach  distance from the eye the map covers, metres, &gt; 0
     */
    public void fit(Camera camera, float lx, float ly, float lz, double reach) {
        fit.fit(camera, lx, ly, lz, reach);
    }

    /** Deletes the map and frees the matrices' memory. Render thread; idempotent. */
    @Override
    public void close() {
        map.close();
        fit.close();
    }

    /**
     * How far from the eye plants cast into the map: the nearest distance at which a species of the
     * world draws lines (lines do not cast), at least 2 metres. Any thread; setup time (iterates a list).
     *
     * @param world the plants' species and their levels of detail
     * @return metres; infinite when no species has a line level
     */
    public static double castReach(org.jecosys.sim.World world) {
        double reach = Double.POSITIVE_INFINITY;
        for (org.jecosys.plant.SpeciesModel m : world.plants().species()) {
            double triangles = 0;
            for (org.jecosys.plant.LodDef l : m.def().lods()) {
                if (l.primitive() != org.jecosys.plant.Primitive.TRIANGLES) {
                    reach = Math.min(reach, triangles);
                    break;
                }
                triangles = l.maxDistance();
            }
        }
        return Math.max(2, reach);
    }
}
