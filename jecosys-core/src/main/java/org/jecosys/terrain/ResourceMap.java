package org.jecosys.terrain;

import java.io.IOException;
import org.jecosys.math.Noise;
import org.jecosys.math.Require;

/**
 * A resource (water or nutrients) over the terrain, paper §4.3: a {@code resolution x resolution}
 * grid of cells covering the terrain's extent, each holding a level in [0, 1].
 *
 * <p>Two readings: {@link #sample} interpolates bilinearly between cell centres (smooth, for display
 * and for preference masks); {@link #footprintLevel} averages the cells under a plant's footprint
 * disc, weighted by overlap area, which is what a plant "sees" during competition. {@link #consume}
 * removes {@code use} level from the footprint disc, i.e. {@code use * overlap / cellArea} from each
 * cell it overlaps, and never takes a cell below zero.
 *
 * <p>Thread rules: concurrent reads are safe; {@link #consume} needs exclusive access. A map can be
 * {@link #freeze() frozen} (the initial maps of a {@link Terrain} are): {@code consume} then throws,
 * and competition works on a {@link #copy()}. Only factories and {@code copy} allocate.
 */
public final class ResourceMap {
    /** NOISE maps: octaves of value noise. */
    public static final int NOISE_OCTAVES = 4;
    /** NOISE maps: amplitude ratio between octaves. */
    public static final double NOISE_GAIN = 0.5;
    /** Integration strips across a footprint disc when computing its overlap with a cell. */
    static final int OVERLAP_STRIPS = 8;

    private final double sizeX;
    private final double sizeZ;
    private final int res;
    private final double cellX;
    private final double cellZ;
    private final double[] levels;
    private boolean frozen;

    private ResourceMap(double sizeX, double sizeZ, int res, double[] levels) {
        this.sizeX = sizeX;
        this.sizeZ = sizeZ;
        this.res = res;
        this.cellX = sizeX / res;
        this.cellZ = sizeZ / res;
        this.levels = levels;
    }

    /**
     * Builds the map {@code def} describes over {@code terrain}'s extent, multiplied by
     * {@code def.amount()}. UNIFORM: level 1. NOISE: fractal value noise of feature size
     * {@code def.scale()} metres from {@code seed}, stretched to [0, 1] over the map. VALLEYS: water
     * gathering in low ground and along valleys (see {@link ValleyWater}), in [0, 1]. IMAGE: the
     * greyscale image {@code def.image()}, read once from {@code images} and resampled bilinearly
     * (column along X, row along Z).
     *
     * @param def     the map's source, resolution, amount and noise scale
     * @param terrain gives the extent (and, for VALLEYS, the relief)
     * @param seed    seed of NOISE maps (ignored otherwise)
     * @param images  where an IMAGE map's image comes from; ignored (may be null) otherwise
     * @return a new, mutable map
     * @throws IOException              when an IMAGE map's file cannot be read or would not fit in the
     *                                  heap
     * @throws IllegalArgumentException on a null def/terrain, or a missing or unreadable image
     */
    public static ResourceMap build(ResourceMapDef def, Heightfield terrain, long seed, ImageSource images)
            throws IOException {
        Require.nonNull("def", def);
        Require.nonNull("terrain", terrain);
        int res = def.resolution();
        double[] v = new double[res * res];
        double sx = terrain.sizeX();
        double sz = terrain.sizeZ();
        switch (def.source()) {
            case UNIFORM -> java.util.Arrays.fill(v, 1.0);
            case NOISE -> {
                for (int j = 0; j < res; j++) {
                    double z = -sz / 2 + (j + 0.5) * sz / res;
                    for (int i = 0; i < res; i++) {
                        double x = -sx / 2 + (i + 0.5) * sx / res;
                        v[j * res + i] = Noise.fractal2(seed, x / def.scale(), z / def.scale(), NOISE_OCTAVES, NOISE_GAIN);
                    }
                }
                stretch(v);
            }
            case VALLEYS -> ValleyWater.compute(terrain, res, v);
            case IMAGE -> {
                GreyImage img = GreyImage.read("image", Require.nonNull("images", images), def.image());
                for (int j = 0; j < res; j++) {
                    double vv = (j + 0.5) / res * img.height - 0.5;
                    for (int i = 0; i < res; i++) {
                        v[j * res + i] = img.sample((i + 0.5) / res * img.width - 0.5, vv);
                    }
                }
            }
            default -> throw new IllegalArgumentException("unknown source " + def.source());
        }
        for (int k = 0; k < v.length; k++) {
            v[k] = Math.max(0, Math.min(1, v[k])) * def.amount();
        }
        return new ResourceMap(sx, sz, res, v);
    }

    /**
     * A map of one level everywhere over a sizeX x sizeZ terrain centred on the origin.
     *
     * @param sizeX      extent along X, metres, in [1e-3, 100000]
     * @param sizeZ      extent along Z, metres, in [1e-3, 100000]
     * @param resolution cells per side, in [2, 1024]
     * @param level      the level of every cell, in [0, 1]
     * @return a new, mutable map
     * @throws IllegalArgumentException when an argument is out of range
     */
    public static ResourceMap uniform(double sizeX, double sizeZ, int resolution, double level) {
        Require.range("level", level, 0, 1);
        double[] v = new double[Require.range("resolution", resolution, 2, 1024) * resolution];
        java.util.Arrays.fill(v, level);
        return of(sizeX, sizeZ, resolution, v);
    }

    /**
     * A map from explicit cell levels (index {@code j * resolution + i}, i along X), each in [0, 1].
     * Copies {@code levels}.
     *
     * @param sizeX      extent along X, metres, in [1e-3, 100000]
     * @param sizeZ      extent along Z, metres, in [1e-3, 100000]
     * @param resolution cells per side, in [2, 1024]
     * @param levels     {@code resolution * resolution} levels, each in [0, 1]
     * @return a new, mutable map
     * @throws IllegalArgumentException when an argument is out of range or the array has the wrong length
     */
    public static ResourceMap of(double sizeX, double sizeZ, int resolution, double[] levels) {
        Require.range("sizeX", sizeX, 1e-3, 100_000);
        Require.range("sizeZ", sizeZ, 1e-3, 100_000);
        Require.range("resolution", resolution, 2, 1024);
        Require.nonNull("levels", levels);
        if (levels.length != resolution * resolution) {
            throw new IllegalArgumentException("levels must have resolution^2 = " + resolution * resolution
                    + " entries, got " + levels.length);
        }
        for (double l : levels) {
            Require.range("levels[]", l, 0, 1);
        }
        return new ResourceMap(sizeX, sizeZ, resolution, levels.clone());
    }

    /** {@return a mutable copy (not frozen) with the same levels} Allocates. */
    public ResourceMap copy() {
        return new ResourceMap(sizeX, sizeZ, res, levels.clone());
    }

    /**
     * Makes this map read-only for good: {@link #consume} then throws.
     *
     * @return this map
     */
    public ResourceMap freeze() {
        frozen = true;
        return this;
    }

    /** {@return whether this map is frozen, so that {@link #consume} is refused} */
    public boolean frozen() {
        return frozen;
    }

    /** {@return the number of cells per side, in [2, 1024]} */
    public int resolution() {
        return res;
    }

    /** {@return the extent along X, metres} */
    public double sizeX() {
        return sizeX;
    }

    /** {@return the extent along Z, metres} */
    public double sizeZ() {
        return sizeZ;
    }

    /**
     * {@return the level of cell (i, j), in [0, 1]}
     *
     * @param i cell column, along X, in [0, resolution)
     * @param j cell row, along Z, in [0, resolution)
     */
    public double level(int i, int j) {
        return levels[j * res + i];
    }

    /** {@return the lowest cell level, in [0, 1]} Scans every cell; no allocation. */
    public double min() {
        double m = Double.POSITIVE_INFINITY;
        for (double l : levels) {
            m = Math.min(m, l);
        }
        return m;
    }

    /** {@return the highest cell level, in [0, 1]} Scans every cell; no allocation. */
    public double max() {
        double m = Double.NEGATIVE_INFINITY;
        for (double l : levels) {
            m = Math.max(m, l);
        }
        return m;
    }

    /** {@return the sum of level times cell area over all cells, level * square metres} */
    public double total() {
        double s = 0;
        for (double l : levels) {
            s += l;
        }
        return s * cellX * cellZ;
    }

    /**
     * Bilinear level at (x, z) between cell centres, clamped to the terrain. No allocation.
     *
     * @param x world X, metres
     * @param z world Z, metres
     * @return the level, in [0, 1]
     */
    public double sample(double x, double z) {
        double u = Grid.clamp((x + sizeX / 2) / cellX - 0.5, res - 1);
        double v = Grid.clamp((z + sizeZ / 2) / cellZ - 0.5, res - 1);
        return Grid.bilinear(levels, res, u, v);
    }

    /**
     * Mean level under the disc of {@code radius} metres at (x, z), weighted by each cell's overlap
     * with the disc (the part outside the terrain does not count). No allocation.
     *
     * @param x      disc centre X, metres
     * @param z      disc centre Z, metres
     * @param radius disc radius, metres
     * @return the mean level, in [0, 1]; {@link #sample} at (x, z) when the disc covers no cell area
     */
    public double footprintLevel(double x, double z, double radius) {
        int i0 = cellIndex(x - radius, sizeX, cellX);
        int i1 = cellIndex(x + radius, sizeX, cellX);
        int j0 = cellIndex(z - radius, sizeZ, cellZ);
        int j1 = cellIndex(z + radius, sizeZ, cellZ);
        double sum = 0;
        double area = 0;
        for (int j = j0; j <= j1; j++) {
            for (int i = i0; i <= i1; i++) {
                double a = overlap(x, z, radius, i, j);
                sum += a * levels[j * res + i];
                area += a;
            }
        }
        return area > 0 ? sum / area : sample(x, z);
    }

    /**
     * Removes {@code use} level from the disc of {@code radius} metres at (x, z): each overlapped
     * cell loses {@code use * overlap / cellArea}, clamped so no level goes below zero. No allocation.
     * Needs exclusive access to this map.
     *
     * @param x      disc centre X, metres
     * @param z      disc centre Z, metres
     * @param radius disc radius, metres
     * @param use    level * square metres taken in all; 0 or less takes nothing
     * @throws IllegalStateException when the map is frozen
     */
    public void consume(double x, double z, double radius, double use) {
        if (frozen) {
            throw new IllegalStateException("this resource map is frozen; consume a copy()");
        }
        if (use <= 0) {
            return;
        }
        int i0 = cellIndex(x - radius, sizeX, cellX);
        int i1 = cellIndex(x + radius, sizeX, cellX);
        int j0 = cellIndex(z - radius, sizeZ, cellZ);
        int j1 = cellIndex(z + radius, sizeZ, cellZ);
        double perArea = use / (cellX * cellZ);
        for (int j = j0; j <= j1; j++) {
            for (int i = i0; i <= i1; i++) {
                double a = overlap(x, z, radius, i, j);
                if (a > 0) {
                    int k = j * res + i;
                    levels[k] = Math.max(0, levels[k] - perArea * a);
                }
            }
        }
    }

    /** Area, m^2, of the disc (x, z, r) inside cell (i, j), by midpoint strips along X. */
    private double overlap(double x, double z, double r, int i, int j) {
        double cx0 = -sizeX / 2 + i * cellX;
        double cz0 = -sizeZ / 2 + j * cellZ;
        double a = Math.max(cx0, x - r);
        double b = Math.min(cx0 + cellX, x + r);
        if (b <= a) {
            return 0;
        }
        double za = cz0;
        double zb = cz0 + cellZ;
        double w = (b - a) / OVERLAP_STRIPS;
        double sum = 0;
        for (int s = 0; s < OVERLAP_STRIPS; s++) {
            double dx = a + (s + 0.5) * w - x;
            double h = Math.sqrt(Math.max(0, r * r - dx * dx));
            double len = Math.min(zb, z + h) - Math.max(za, z - h);
            if (len > 0) {
                sum += len;
            }
        }
        return sum * w;
    }

    private int cellIndex(double coord, double size, double cell) {
        int i = (int) Math.floor((coord + size / 2) / cell);
        return i < 0 ? 0 : (i >= res ? res - 1 : i);
    }

    /** Linearly maps v's range onto [0, 1]; a constant array becomes all 1. */
    static void stretch(double[] v) {
        double lo = Double.POSITIVE_INFINITY;
        double hi = Double.NEGATIVE_INFINITY;
        for (double x : v) {
            lo = Math.min(lo, x);
            hi = Math.max(hi, x);
        }
        double range = hi - lo;
        for (int k = 0; k < v.length; k++) {
            v[k] = range > 0 ? (v[k] - lo) / range : 1.0;
        }
    }
}
