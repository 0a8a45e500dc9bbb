package org.jecosys.render.ground;

import java.nio.ByteBuffer;
import org.jecosys.plant.ComponentDef;
import org.jecosys.plant.SpeciesDef;
import org.jecosys.sim.World;
import org.jecosys.terrain.Heightfield;

/**
 * The ground's contact-occlusion map: how much of the sky and sun a point of the ground loses to the
 * plants standing on it, in [0, 1], on a regular grid over the terrain. Built once from the plants'
 * base positions: each plant splats a disc of radius {@link #radius} (its species' spread plus a
 * margin, at least {@value #MIN_RADIUS} m) with weight {@code 1 - (d / radius)^2}, and overlapping
 * discs combine as independent occluders ({@code 1 - product(1 - w)}). The terrain shader darkens the
 * ground by {@code contactShadow * occlusion}. Texels are {@value #TEXEL} m unless the terrain needs
 * more than {@value #MAX_SIDE} of them per side. Immutable after construction; built on any thread,
 * allocates.
 */
public final class ContactOcclusion {
    /** Preferred texel size, metres. */
    public static final double TEXEL = 0.1;
    /** Largest side of the map, texels. */
    public static final int MAX_SIDE = 2048;
    /** Smallest splat radius, metres: ground within 0.2 m of a base is clearly darkened. */
    public static final double MIN_RADIUS = 0.3;
    /** Largest splat radius, metres. */
    public static final double MAX_RADIUS = 0.8;
    /** Occlusion at the centre of one plant's disc (several plants together approach 1). */
    public static final double PEAK = 0.85;

    public final int width;
    public final int height;
    public final double minX;
    public final double minZ;
    public final double texelX;
    public final double texelZ;
    /** Occlusion per texel, rows along X, in [0, 1]. */
    public final float[] occlusion;

    private ContactOcclusion(int width, int height, double minX, double minZ, double texelX, double texelZ) {
        this.width = width;
        this.height = height;
        this.minX = minX;
        this.minZ = minZ;
        this.texelX = texelX;
        this.texelZ = texelZ;
        this.occlusion = new float[width * height];
    }

    /**
     * The splat radius of a species: how far its ground components reach sideways at rest, plus
     * 0.15 m, clamped to [{@value #MIN_RADIUS}, {@value #MAX_RADIUS}] m.
     */
    public static double radius(SpeciesDef species) {
        double spread = 0;
        for (ComponentDef c : species.components()) {
            if (c.attachTo() == null) {
                spread = Math.max(spread, c.length() * Math.sin(Math.min(Math.PI / 2, c.tilt() + 0.5 * Math.abs(c.curvature()))));
            }
        }
        return Math.max(MIN_RADIUS, Math.min(MAX_RADIUS, 0.6 * spread + 0.15));
    }

    /**
     * Builds the map of a world's plants over its terrain.
     *
     * @param world the terrain and plants
     * @return the map
     */
    public static ContactOcclusion of(World world) {
        Heightfield h = world.terrain().heightfield();
        double sizeX = (h.resolution() - 1) * h.cellX();
        double sizeZ = (h.resolution() - 1) * h.cellZ();
        int w = (int) Math.max(2, Math.min(MAX_SIDE, Math.ceil(sizeX / TEXEL) + 1));
        int ht = (int) Math.max(2, Math.min(MAX_SIDE, Math.ceil(sizeZ / TEXEL) + 1));
        ContactOcclusion m = new ContactOcclusion(w, ht, h.minX(), h.minZ(), sizeX / (w - 1), sizeZ / (ht - 1));
        int species = world.plants().species().size();
        double[] radius = new double[species];
        for (int s = 0; s < species; s++) {
            radius[s] = radius(world.plants().species().get(s).def());
        }
        // accumulate -log(1 - w) (transparency multiplies), then turn it back into occlusion
        float[] acc = m.occlusion;
        for (int p = 0; p < world.plantCount(); p++) {
            m.splat(acc, world.plantX(p), world.plantZ(p), radius[world.plantSpecies(p)]);
        }
        for (int i = 0; i < acc.length; i++) {
            acc[i] = (float) (1 - Math.exp(-acc[i]));
        }
        return m;
    }

    private void splat(float[] acc, double x, double z, double r) {
        // texel centres sit on the grid points: texel i covers x = minX + i * texelX
        double u = (x - minX) / texelX;
        double v = (z - minZ) / texelZ;
        int i0 = (int) Math.max(0, Math.ceil(u - r / texelX));
        int i1 = (int) Math.min(width - 1, Math.floor(u + r / texelX));
        int j0 = (int) Math.max(0, Math.ceil(v - r / texelZ));
        int j1 = (int) Math.min(height - 1, Math.floor(v + r / texelZ));
        double r2 = r * r;
        for (int j = j0; j <= j1; j++) {
            double dz = minZ + j * texelZ - z;
            for (int i = i0; i <= i1; i++) {
                double dx = minX + i * texelX - x;
                double d2 = dx * dx + dz * dz;
                if (d2 < r2) {
                    double wgt = PEAK * (1 - d2 / r2);
                    acc[j * width + i] += (float) -Math.log(1 - wgt);
                }
            }
        }
    }

    /** {@return the occlusion at a world point, bilinear between texels, 0 outside the terrain} */
    public double sample(double x, double z) {
        double u = (x - minX) / texelX;
        double v = (z - minZ) / texelZ;
        if (u < 0 || v < 0 || u > width - 1 || v > height - 1) {
            return 0;
        }
        int i = (int) Math.min(width - 2, Math.floor(u));
        int j = (int) Math.min(height - 2, Math.floor(v));
        double fu = u - i;
        double fv = v - j;
        double a = occlusion[j * width + i];
        double b = occlusion[j * width + i + 1];
        double c = occlusion[(j + 1) * width + i];
        double d = occlusion[(j + 1) * width + i + 1];
        return (a * (1 - fu) + b * fu) * (1 - fv) + (c * (1 - fu) + d * fu) * fv;
    }

    /**
     * Writes the map as bytes (0 open, 255 fully occluded), rows along X, into {@code dest} from its
     * position, and flips it.
     *
     * @param dest at least {@code width * height} bytes remaining
     * @return {@code dest}, flipped
     */
    public ByteBuffer bytes(ByteBuffer dest) {
        for (float o : occlusion) {
            dest.put((byte) Math.round(Math.max(0, Math.min(1, o)) * 255));
        }
        return dest.flip();
    }
}
