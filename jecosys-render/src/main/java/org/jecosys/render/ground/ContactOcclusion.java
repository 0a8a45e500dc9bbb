package org.jecosys.render.ground;

import java.nio.ByteBuffer;
import org.jecosys.plant.SpeciesModel;
import org.jecosys.sim.World;
import org.jecosys.terrain.Heightfield;

/**
 * The ground's contact-occlusion map: how much of the sky and sun a point of the ground loses to the
 * plants standing on it, in [0, 1], on a regular grid over the terrain. Built once from the plants at
 * rest: each plant darkens its own footprint, the outline of everything it has seen from straight above
 * (the convex hull of its rest pose projected on the ground, {@link Footprint}), turned to the plant's
 * rest azimuth: fully ({@value #PEAK}) well inside it, fading to nothing across a soft edge a quarter
 * of the footprint's size wide on each side, so a thin flower darkens a small spot and a wide tuft a
 * wide one. Overlapping plants combine as independent occluders ({@code 1 - product(1 - w)}); a plant
 * smaller than a texel adds its footprint's share of the texel. The terrain shader darkens the ground by
 * {@code contactShadow * occlusion}. Texels are {@value #TEXEL} m unless the terrain needs more than
 * {@value #MAX_SIDE} of them per side. Immutable after construction; built on any thread, allocates.
 */
public final class ContactOcclusion {
    /** Preferred texel size, metres. */
    public static final double TEXEL = 0.025;
    /** Largest side of the map, texels. */
    public static final int MAX_SIDE = 2048;
    /** Occlusion well inside one plant's footprint (several plants together approach 1). */
    public static final double PEAK = 0.95;
    /** The soft edge's half width as a share of the footprint's equivalent radius. */
    public static final double EDGE = 0.5;
    /** Least and largest half width of the soft edge, metres. */
    public static final double MIN_EDGE = 0.01;
    public static final double MAX_EDGE = 0.1;

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
     * An empty map on a coarser grid over the same ground: {@code factor} texels of this one per texel
     * of it along each side, one more texel each way so it covers this one's last texel. Allocates.
     *
     * @param factor at least 1
     * @return the coarser map, all 0
     */
    ContactOcclusion coarser(int factor) {
        return new ContactOcclusion((width - 1) / factor + 2, (height - 1) / factor + 2, minX, minZ, texelX * factor,
                texelZ * factor);
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
        Footprint[][] prints = new Footprint[species][];
        for (int s = 0; s < species; s++) {
            SpeciesModel model = world.plants().species().get(s);
            prints[s] = new Footprint[model.variants()];
        }
        // accumulate the transmission 1 - w (transparency multiplies), then turn it back into occlusion
        float[] acc = m.occlusion;
        java.util.Arrays.fill(acc, 1f);
        for (int p = 0; p < world.plantCount(); p++) {
            int s = world.plantSpecies(p);
            int v = world.plantVariant(p);
            if (prints[s][v] == null) {
                prints[s][v] = Footprint.of(world.plants().species().get(s), v);
            }
            m.splat(acc, world.plantX(p), world.plantZ(p), world.plantRestAzimuth(p), prints[s][v], PEAK, 1);
        }
        for (int i = 0; i < acc.length; i++) {
            acc[i] = 1 - acc[i];
        }
        return m;
    }

    /**
     * Adds one plant's footprint to {@code acc} (on this map's grid, a transmission that starts at 1 and is
     * multiplied by {@code 1 - w}): weight
     * {@code peak} well inside it, fading over a soft edge {@code edgeScale} times the contact map's.
     */
    /** The least transmission kept: far under a float's step at 1 (so 1 - TINY is 1), far above the subnormals. */
    private static final float TINY = 1e-30f;

    void splat(float[] acc, double x, double z, double restAzimuth, Footprint f, double peak, double edgeScale) {
        double edge = edgeScale * Math.max(MIN_EDGE, Math.min(MAX_EDGE, EDGE * f.radius()));
        double reach = f.maxReach() + edge;
        double u = (x - minX) / texelX;
        double v = (z - minZ) / texelZ;
        if (reach < 0.75 * Math.min(texelX, texelZ)) {
            // smaller than a texel: its share of the four texels round it
            double share = Math.min(1, Math.PI * (f.radius() + edge) * (f.radius() + edge) / (texelX * texelZ));
            int i = (int) Math.floor(u);
            int j = (int) Math.floor(v);
            double fu = u - i;
            double fv = v - j;
            add(acc, i, j, share * (1 - fu) * (1 - fv), peak);
            add(acc, i + 1, j, share * fu * (1 - fv), peak);
            add(acc, i, j + 1, share * (1 - fu) * fv, peak);
            add(acc, i + 1, j + 1, share * fu * fv, peak);
            return;
        }
        int i0 = (int) Math.max(0, Math.ceil(u - reach / texelX));
        int i1 = (int) Math.min(width - 1, Math.floor(u + reach / texelX));
        int j0 = (int) Math.max(0, Math.ceil(v - reach / texelZ));
        int j1 = (int) Math.min(height - 1, Math.floor(v + reach / texelZ));
        // texel offsets turned back into the plant's frame (the footprint is at rest azimuth 0)
        double c = Math.cos(restAzimuth);
        double sn = Math.sin(restAzimuth);
        double reachSq = reach * reach;
        // within the least reach less the soft edge every texel takes the full weight
        double inner = f.minReach() - edge;
        double innerSq = inner > 0 ? inner * inner : -1;
        float full = (float) (1 - peak);
        for (int j = j0; j <= j1; j++) {
            double dz = minZ + j * texelZ - z;
            double dzSq = dz * dz;
            if (dzSq >= reachSq) {
                continue;
            }
            int row = j * width;
            for (int i = i0; i <= i1; i++) {
                double dx = minX + i * texelX - x;
                double rSq = dx * dx + dzSq;
                if (rSq >= reachSq) {
                    continue;
                }
                if (rSq <= innerSq) {
                    acc[row + i] = Math.max(TINY, acc[row + i] * full);
                    continue;
                }
                double r = Math.sqrt(rSq);
                double lx = dx * c + dz * sn;
                double lz = -dx * sn + dz * c;
                double t = (r - f.reach(lx, lz) + edge) / (2 * edge);
                if (t < 1) {
                    double k = t <= 0 ? 1 : 1 - t * t * (3 - 2 * t);
                    acc[row + i] = Math.max(TINY, acc[row + i] * (float) (1 - peak * k));
                }
            }
        }
    }

    private void add(float[] acc, int i, int j, double share, double peak) {
        if (i >= 0 && j >= 0 && i < width && j < height && share > 0) {
            acc[j * width + i] = Math.max(TINY, acc[j * width + i] * (float) (1 - peak * Math.min(1, share)));
        }
    }

    /** {@return the occlusion at a world point, bilinear between texels, 0 outside the terrain} */
    public double sample(double x, double z) {
        return sample(occlusion, x, z);
    }

    /**
     * A value of a map on this map's grid at a world point, bilinear between texels, 0 outside the
     * terrain. Any thread; no allocation.
     *
     * @param values {@code width * height} values, rows along X
     * @param x      world X, metres
     * @param z      world Z, metres
     * @return the value
     */
    public double sample(float[] values, double x, double z) {
        double u = (x - minX) / texelX;
        double v = (z - minZ) / texelZ;
        if (u < 0 || v < 0 || u > width - 1 || v > height - 1) {
            return 0;
        }
        int i = (int) Math.min(width - 2, Math.floor(u));
        int j = (int) Math.min(height - 2, Math.floor(v));
        double fu = u - i;
        double fv = v - j;
        double a = values[j * width + i];
        double b = values[j * width + i + 1];
        double c = values[(j + 1) * width + i];
        double d = values[(j + 1) * width + i + 1];
        return (a * (1 - fu) + b * fu) * (1 - fv) + (c * (1 - fu) + d * fu) * fv;
    }

    /**
     * Writes the map and two more on the same grid as four bytes per texel (occlusion, second, third,
     * 0; 0 for 0, 255 for 1), rows along X, into {@code dest} from its position, and flips it: the
     * terrain's four-channel texture (contact occlusion, ground cover, sun shadow).
     *
     * @param dest   at least {@code 4 * width * height} bytes remaining
     * @param second {@code width * height} values in [0, 1], or null for zeros
     * @param third  {@code width * height} values in [0, 1], or null for zeros
     * @return {@code dest}, flipped
     */
    public ByteBuffer bytes(ByteBuffer dest, float[] second, float[] third) {
        for (int i = 0; i < occlusion.length; i++) {
            dest.put(unorm(occlusion[i])).put(second == null ? 0 : unorm(second[i]))
                    .put(third == null ? 0 : unorm(third[i])).put((byte) 0);
        }
        return dest.flip();
    }

    private static byte unorm(float v) {
        return (byte) Math.round(Math.max(0, Math.min(1, v)) * 255);
    }
}
