package org.jecosys.render.ground;

import org.jecosys.plant.SpeciesModel;
import org.jecosys.sim.World;

/**
 * The plants' shadows on the ground from the sun, the light's cheap path (no shadow-map pass): for
 * each plant, the outline of its rest pose's shadow on flat ground (every rest-pose point moved away
 * from the sun by its height over the tangent of the sun's elevation, the hull taken with the base,
 * {@link Footprint#of(SpeciesModel, int, double, double)}), darkened like a contact footprint but
 * lighter ({@value #PEAK} well inside: light passes between the blades) and with a softer edge, on the
 * contact-occlusion map's grid over the terrain. The terrain shader takes that share of the sun's
 * direct light away (times {@code <light shadows>}); the sky's light is the contact occlusion's.
 *
 * <p>The map is a world-space texture, so it does not swim as the camera moves; it follows the plants
 * at rest, not their sway, and it is rebuilt when the sun moves. Plants do not shade each other on this
 * path. The shadows are soft, so they are worked out on a coarser grid (texels of about
 * {@value #TEXEL} m) and read bilinearly onto the contact map's; footprints are cached per species,
 * variant and rest azimuth rounded to {@value #AZIMUTHS} steps a turn. Built on any thread; allocates.
 */
public final class SunShadow {
    /** Share of the sun a point well inside one plant's shadow loses. */
    public static final double PEAK = 0.7;
    /** The shadow's soft edge, in contact-edge widths (the sun's half-degree disc blurs with height). */
    public static final double EDGE_SCALE = 2;
    /** The lowest sun that casts shadows, radians above the horizon: lower, the shadows would run to infinity. */
    public static final double MIN_ELEVATION = Math.toRadians(5);
    /** Size of the texels the shadows are worked out on, metres (at least the contact map's). */
    public static final double TEXEL = 0.12;
    /** Rest-azimuth steps a turn in the footprint cache. */
    static final int AZIMUTHS = 64;

    private SunShadow() {
    }

    /**
     * The share of the sun's direct light each texel of the grid loses to the plants' shadows.
     *
     * @param world the plants
     * @param grid  the grid (the contact-occlusion map's)
     * @param sunX  unit vector toward the sun, X (likewise sunY up, sunZ)
     * @return {@code grid.width * grid.height} values in [0, 1), rows along X; all 0 for a sun below
     *         {@link #MIN_ELEVATION}
     */
    public static float[] of(World world, ContactOcclusion grid, double sunX, double sunY, double sunZ) {
        float[] fine = new float[grid.width * grid.height];
        double elevation = Math.asin(Math.max(-1, Math.min(1, sunY)));
        if (elevation < MIN_ELEVATION) {
            return fine;
        }
        int factor = Math.max(1, (int) Math.round(TEXEL / Math.min(grid.texelX, grid.texelZ)));
        ContactOcclusion coarse = grid.coarser(factor);
        float[] acc = coarse.occlusion;
        java.util.Arrays.fill(acc, 1f); // the transmission, multiplied by each plant's 1 - w
        double horizontal = Math.hypot(sunX, sunZ);
        double run = horizontal < 1e-9 ? 0 : 1 / Math.tan(elevation);
        // world offset on the ground per metre of height: away from the sun
        double wx = horizontal < 1e-9 ? 0 : -sunX / horizontal * run;
        double wz = horizontal < 1e-9 ? 0 : -sunZ / horizontal * run;
        int species = world.plants().species().size();
        Footprint[][][] cache = new Footprint[species][][];
        for (int s = 0; s < species; s++) {
            cache[s] = new Footprint[world.plants().species().get(s).variants()][];
        }
        for (int p = 0; p < world.plantCount(); p++) {
            int s = world.plantSpecies(p);
            int v = world.plantVariant(p);
            double az = world.plantRestAzimuth(p);
            int step = Math.floorMod((int) Math.round(az / (2 * Math.PI) * AZIMUTHS), AZIMUTHS);
            if (cache[s][v] == null) {
                cache[s][v] = new Footprint[AZIMUTHS];
            }
            double rounded = step * 2 * Math.PI / AZIMUTHS;
            Footprint f = cache[s][v][step];
            if (f == null) {
                // the shear turned into the plant's frame (the footprint is at rest azimuth 0)
                double c = Math.cos(rounded);
                double sn = Math.sin(rounded);
                f = Footprint.of(world.plants().species().get(s), v, wx * c + wz * sn, -wx * sn + wz * c);
                cache[s][v][step] = f;
            }
            coarse.splat(acc, world.plantX(p), world.plantZ(p), rounded, f, PEAK, EDGE_SCALE);
        }
        for (int i = 0; i < acc.length; i++) {
            acc[i] = 1 - acc[i];
        }
        for (int j = 0; j < grid.height; j++) {
            double z = grid.minZ + j * grid.texelZ;
            for (int i = 0; i < grid.width; i++) {
                fine[j * grid.width + i] = (float) coarse.sample(acc, grid.minX + i * grid.texelX, z);
            }
        }
        return fine;
    }
}
