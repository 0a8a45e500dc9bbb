package org.jecosys.terrain;

import java.io.IOException;
import org.jecosys.math.Noise;
import org.jecosys.math.Progress;
import org.jecosys.math.Require;
import org.jecosys.math.HeightFunction;
import org.joml.Vector3f;

/**
 * A regular-grid heightfield over [cx - sizeX/2, cx + sizeX/2] x [cz - sizeZ/2, cz + sizeZ/2]
 * (paper §4.3, "a simple terrain mesh generator"). Y is up; heights in metres. A scene's terrain is
 * centred on the origin (cx = cz = 0); a tile of an open world ({@code sim.OpenWorld}) is centred on
 * its own square ({@link #of(double, double, double, double, int, float[])}).
 *
 * <p>Storage is flat: {@code resolution * resolution} vertices, index {@code j * resolution + i},
 * with i along X (x = minX + i * cellX) and j along Z. Per-vertex normals are stored as three floats
 * per vertex. Queries at any (x, z) clamp to the border, so they never fail outside the terrain.
 *
 * <p>Immutable once built: any thread may query it concurrently; queries do not allocate. It is a
 * {@link HeightFunction}, so tiled placement ({@code org.jecosys.world.TilePlacer}) can stand plants on
 * it; its heights and slopes are the same through either.
 */
public final class Heightfield implements HeightFunction {
    /** Generated relief: hills per side of the terrain's longer edge at the first octave. */
    public static final double BASE_FEATURES_PER_SIDE = 3.0;
    /** Generated relief: the finest octave still spans at least this many grid cells. */
    public static final double FINEST_OCTAVE_CELLS = 2.0;
    /** Generated relief: most octaves summed. */
    public static final int MAX_OCTAVES = 12;
    private static final int ROW_BANDS = 32;

    private final double sizeX;
    private final double sizeZ;
    /** The centre, metres: 0 for a scene's terrain. */
    private final double centreX;
    private final double centreZ;
    private final int res;
    private final double cellX;
    private final double cellZ;
    private final float[] heights;
    private final float[] normals;
    private final float minHeight;
    private final float maxHeight;

    private Heightfield(double sizeX, double sizeZ, int res, float[] heights) {
        this(0, 0, sizeX, sizeZ, res, heights);
    }

    private Heightfield(double centreX, double centreZ, double sizeX, double sizeZ, int res, float[] heights) {
        this.centreX = centreX;
        this.centreZ = centreZ;
        this.sizeX = sizeX;
        this.sizeZ = sizeZ;
        this.res = res;
        this.cellX = sizeX / (res - 1);
        this.cellZ = sizeZ / (res - 1);
        this.heights = heights;
        float lo = Float.POSITIVE_INFINITY;
        float hi = Float.NEGATIVE_INFINITY;
        for (float h : heights) {
            lo = Math.min(lo, h);
            hi = Math.max(hi, h);
        }
        this.minHeight = lo;
        this.maxHeight = hi;
        this.normals = new float[heights.length * 3];
        for (int j = 0; j < res; j++) {
            for (int i = 0; i < res; i++) {
                double gx = vertexGradX(i, j);
                double gz = vertexGradZ(i, j);
                double inv = 1.0 / Math.sqrt(gx * gx + 1 + gz * gz);
                int k = 3 * (j * res + i);
                normals[k] = (float) (-gx * inv);
                normals[k + 1] = (float) inv;
                normals[k + 2] = (float) (-gz * inv);
            }
        }
    }

    /**
     * Generates seeded fractal relief from {@code def} (its heightmap is ignored): value-noise
     * octaves from {@link #BASE_FEATURES_PER_SIDE} hills per side down to {@link #FINEST_OCTAVE_CELLS}
     * grid cells, each octave's amplitude {@code roughness} times the last (0 = one smooth octave,
     * 1 = all octaves equal), then shifted and scaled so the lowest vertex is at 0 m and the highest at
     * {@code heightScale} m. The same def gives the same heights for any thread count.
     *
     * @param def      size, resolution, seed, relief height and roughness
     * @param workers  worker threads, at least 1
     * @param progress told "terrain" progress in rows; called on the calling thread
     * @return a new heightfield (allocates its height and normal arrays)
     * @throws IllegalArgumentException naming a null def/progress or a bad thread count
     */
    public static Heightfield generate(TerrainDef def, int workers, Progress progress) {
        Require.nonNull("def", def);
        Require.range("workers", workers, 1, 1024);
        Require.nonNull("progress", progress);
        int res = def.resolution();
        double sx = def.sizeX();
        double sz = def.sizeZ();
        double wavelength = Math.max(sx, sz) / BASE_FEATURES_PER_SIDE;
        double cell = Math.min(sx, sz) / (res - 1);
        int octaves = 1 + (int) Math.floor(Math.log(wavelength / (FINEST_OCTAVE_CELLS * cell)) / Math.log(2));
        int oct = Math.max(1, Math.min(MAX_OCTAVES, octaves));
        double gain = def.roughness();
        long seed = def.seed();
        float[] raw = new float[res * res];
        int rowsPerBand = (res + ROW_BANDS - 1) / ROW_BANDS;
        int bands = (res + rowsPerBand - 1) / rowsPerBand;
        try (Workers pool = new Workers(workers)) {
            int bandsPerReport = Math.max(1, bands / 8);
            for (int b0 = 0; b0 < bands; b0 += bandsPerReport) {
                int first = b0;
                int count = Math.min(bandsPerReport, bands - b0);
                pool.run(count, c -> {
                    int j0 = (first + c) * rowsPerBand;
                    int j1 = Math.min(res, j0 + rowsPerBand);
                    for (int j = j0; j < j1; j++) {
                        double z = -sz / 2 + j * (sz / (res - 1));
                        for (int i = 0; i < res; i++) {
                            double x = -sx / 2 + i * (sx / (res - 1));
                            raw[j * res + i] = (float) Noise.fractal2(seed, x / wavelength, z / wavelength, oct, gain);
                        }
                    }
                });
                progress.report("terrain", Math.min(res, (long) (b0 + count) * rowsPerBand), res);
            }
        }
        float lo = Float.POSITIVE_INFINITY;
        float hi = Float.NEGATIVE_INFINITY;
        for (float v : raw) {
            lo = Math.min(lo, v);
            hi = Math.max(hi, v);
        }
        double range = hi - lo;
        double scale = range > 0 ? def.heightScale() / range : 0;
        for (int k = 0; k < raw.length; k++) {
            raw[k] = (float) ((raw[k] - lo) * scale);
        }
        return new Heightfield(sx, sz, res, raw);
    }

    /**
     * Reads relief from a greyscale image (8- or 16-bit grey, or colour reduced to luminance):
     * black is 0 m, white is {@code heightScale} m. The image is resampled bilinearly onto
     * {@code def.resolution()} vertices per side; image column grows with X, row with Z, and the
     * image's corner pixel centres sit on the terrain's corners. The image is
     * {@code def.heightmap()}, read once from {@code images} and decoded from those bytes.
     *
     * @param def      size, resolution, {@code heightScale} (metres) and the heightmap's path
     * @param images   where the heightmap comes from (e.g. {@link ImageSource#folder})
     * @param progress told "terrain" progress in rows; called on the calling thread
     * @return a new heightfield
     * @throws IOException              when the image cannot be read, or decoding it would not fit in
     *                                  the heap
     * @throws IllegalArgumentException when an argument is null, the def names no heightmap or the
     *                                  file is not an image
     */
    public static Heightfield fromImage(TerrainDef def, ImageSource images, Progress progress) throws IOException {
        Require.nonNull("def", def);
        Require.nonNull("progress", progress);
        if (def.heightmap() == null) {
            throw new IllegalArgumentException("the terrain names no heightmap");
        }
        GreyImage img = GreyImage.read("heightmap", images, def.heightmap());
        int res = def.resolution();
        float[] h = new float[res * res];
        double su = (img.width - 1) / (double) (res - 1);
        double sv = (img.height - 1) / (double) (res - 1);
        for (int j = 0; j < res; j++) {
            for (int i = 0; i < res; i++) {
                h[j * res + i] = (float) (img.sample(i * su, j * sv) * def.heightScale());
            }
            if ((j & 63) == 63 || j == res - 1) {
                progress.report("terrain", j + 1, res);
            }
        }
        return new Heightfield(def.sizeX(), def.sizeZ(), res, h);
    }

    /**
     * A heightfield from explicit vertex heights (index {@code j * resolution + i}), e.g. for tests
     * or procedural callers. Copies {@code heights}.
     *
     * @param sizeX      extent along X, metres, in [1e-3, 100000]
     * @param sizeZ      extent along Z, metres, in [1e-3, 100000]
     * @param resolution vertices per side, in [2, 2049]
     * @param heights    {@code resolution * resolution} finite heights, metres
     * @return a new heightfield
     * @throws IllegalArgumentException on bad sizes, a wrong array length or non-finite heights
     */
    public static Heightfield of(double sizeX, double sizeZ, int resolution, float[] heights) {
        Require.range("sizeX", sizeX, 1e-3, 100_000);
        Require.range("sizeZ", sizeZ, 1e-3, 100_000);
        Require.range("resolution", resolution, 2, 2049);
        Require.nonNull("heights", heights);
        if (heights.length != resolution * resolution) {
            throw new IllegalArgumentException("heights must have resolution^2 = " + resolution * resolution
                    + " entries, got " + heights.length);
        }
        for (float v : heights) {
            Require.finite("heights[]", v);
        }
        return new Heightfield(sizeX, sizeZ, resolution, heights.clone());
    }

    /**
     * A heightfield centred on (centreX, centreZ) from explicit vertex heights, as
     * {@link #of(double, double, int, float[])}: a tile of an open world. Copies {@code heights}.
     *
     * @param centreX    the centre's X, metres, |centreX| &lt;= 1e9
     * @param centreZ    the centre's Z, metres, |centreZ| &lt;= 1e9
     * @param sizeX      extent along X, metres, in [1e-3, 100000]
     * @param sizeZ      extent along Z, metres, in [1e-3, 100000]
     * @param resolution vertices per side, in [2, 2049]
     * @param heights    {@code resolution * resolution} finite heights, metres
     * @return a new heightfield
     * @throws IllegalArgumentException on a bad centre or size, a wrong array length or non-finite heights
     */
    public static Heightfield of(double centreX, double centreZ, double sizeX, double sizeZ, int resolution,
                                 float[] heights) {
        Require.range("centreX", centreX, -1e9, 1e9);
        Require.range("centreZ", centreZ, -1e9, 1e9);
        Heightfield h = of(sizeX, sizeZ, resolution, heights);
        return new Heightfield(centreX, centreZ, sizeX, sizeZ, resolution, h.heights);
    }

    /** {@return the centre's X, metres (0 for a scene's terrain)} */
    public double centreX() {
        return centreX;
    }

    /** {@return the centre's Z, metres (0 for a scene's terrain)} */
    public double centreZ() {
        return centreZ;
    }

    /** {@return the extent along X, metres} */
    public double sizeX() {
        return sizeX;
    }

    /** {@return the extent along Z, metres} */
    public double sizeZ() {
        return sizeZ;
    }

    /** {@return the number of vertices per side, at least 2} */
    public int resolution() {
        return res;
    }

    /** {@return the lowest X, metres (= centreX - sizeX/2)} */
    public double minX() {
        return centreX - sizeX / 2;
    }

    /** {@return the highest X, metres (= centreX + sizeX/2)} */
    public double maxX() {
        return centreX + sizeX / 2;
    }

    /** {@return the lowest Z, metres (= centreZ - sizeZ/2)} */
    public double minZ() {
        return centreZ - sizeZ / 2;
    }

    /** {@return the highest Z, metres (= centreZ + sizeZ/2)} */
    public double maxZ() {
        return centreZ + sizeZ / 2;
    }

    /** {@return the lowest vertex height, metres} */
    public double minHeight() {
        return minHeight;
    }

    /** {@return the highest vertex height, metres} */
    public double maxHeight() {
        return maxHeight;
    }

    /** {@return the grid spacing along X, metres: sizeX / (resolution - 1)} */
    public double cellX() {
        return cellX;
    }

    /** {@return the grid spacing along Z, metres: sizeZ / (resolution - 1)} */
    public double cellZ() {
        return cellZ;
    }

    /**
     * {@return whether (x, z) lies inside the terrain's extent (borders included)}
     *
     * @param x world X, metres
     * @param z world Z, metres
     */
    public boolean contains(double x, double z) {
        double u = x - centreX;
        double v = z - centreZ;
        return u >= -sizeX / 2 && u <= sizeX / 2 && v >= -sizeZ / 2 && v <= sizeZ / 2;
    }

    /**
     * {@return the height of vertex (i, j), metres}
     *
     * @param i vertex column, along X, in [0, resolution)
     * @param j vertex row, along Z, in [0, resolution)
     */
    public float vertexHeight(int i, int j) {
        return heights[j * res + i];
    }

    /**
     * Copies all vertex heights (metres, index j * resolution + i) into dest. No allocation.
     *
     * @param dest at least resolution^2 floats
     * @return {@code dest}
     */
    public float[] copyHeights(float[] dest) {
        System.arraycopy(heights, 0, dest, 0, heights.length);
        return dest;
    }

    /**
     * Copies all unit vertex normals (x, y, z per vertex, same order as the heights) into dest.
     * No allocation.
     *
     * @param dest at least 3 * resolution^2 floats
     * @return {@code dest}
     */
    public float[] copyNormals(float[] dest) {
        System.arraycopy(normals, 0, dest, 0, normals.length);
        return dest;
    }

    /**
     * Bilinear height at (x, z); (x, z) clamped to the terrain. No allocation.
     *
     * @param x world X, metres
     * @param z world Z, metres
     * @return the ground height, metres
     */
    @Override
    public double height(double x, double z) {
        double u = Grid.clamp((x - centreX + sizeX / 2) / cellX, res - 1);
        double v = Grid.clamp((z - centreZ + sizeZ / 2) / cellZ, res - 1);
        return Grid.bilinear(heights, res, u, v);
    }

    /**
     * Slope at (x, z), radians in [0, pi/2): the angle of the ground from horizontal, from the
     * bilinear blend of the vertices' central-difference gradients (the same gradients as the
     * normals). (x, z) is clamped to the terrain. No allocation.
     *
     * @param x world X, metres
     * @param z world Z, metres
     * @return the slope, radians in [0, pi/2)
     */
    @Override
    public double slope(double x, double z) {
        double u = Grid.clamp((x - centreX + sizeX / 2) / cellX, res - 1);
        double v = Grid.clamp((z - centreZ + sizeZ / 2) / cellZ, res - 1);
        int i = Math.min((int) u, res - 2);
        int j = Math.min((int) v, res - 2);
        double fu = u - i;
        double fv = v - j;
        double w00 = (1 - fu) * (1 - fv);
        double w10 = fu * (1 - fv);
        double w01 = (1 - fu) * fv;
        double w11 = fu * fv;
        double gx = w00 * vertexGradX(i, j) + w10 * vertexGradX(i + 1, j)
                + w01 * vertexGradX(i, j + 1) + w11 * vertexGradX(i + 1, j + 1);
        double gz = w00 * vertexGradZ(i, j) + w10 * vertexGradZ(i + 1, j)
                + w01 * vertexGradZ(i, j + 1) + w11 * vertexGradZ(i + 1, j + 1);
        return Math.atan(Math.sqrt(gx * gx + gz * gz));
    }

    /**
     * Writes the unit normal at (x, z) (bilinear blend of vertex normals) into dest; (x, z) clamped
     * to the terrain. No allocation.
     *
     * @param x    world X, metres
     * @param z    world Z, metres
     * @param dest where to write
     * @return {@code dest}
     */
    @Override
    public Vector3f normal(double x, double z, Vector3f dest) {
        double u = Grid.clamp((x - centreX + sizeX / 2) / cellX, res - 1);
        double v = Grid.clamp((z - centreZ + sizeZ / 2) / cellZ, res - 1);
        int i = Math.min((int) u, res - 2);
        int j = Math.min((int) v, res - 2);
        double fu = u - i;
        double fv = v - j;
        double nx = 0;
        double ny = 0;
        double nz = 0;
        for (int c = 0; c < 4; c++) {
            int di = c & 1;
            int dj = c >> 1;
            double w = (di == 0 ? 1 - fu : fu) * (dj == 0 ? 1 - fv : fv);
            int k = 3 * ((j + dj) * res + i + di);
            nx += w * normals[k];
            ny += w * normals[k + 1];
            nz += w * normals[k + 2];
        }
        return dest.set((float) nx, (float) ny, (float) nz).normalize();
    }

    private double vertexGradX(int i, int j) {
        int i0 = Math.max(0, i - 1);
        int i1 = Math.min(res - 1, i + 1);
        return (heights[j * res + i1] - heights[j * res + i0]) / ((i1 - i0) * cellX);
    }

    private double vertexGradZ(int i, int j) {
        int j0 = Math.max(0, j - 1);
        int j1 = Math.min(res - 1, j + 1);
        return (heights[j1 * res + i] - heights[j0 * res + i]) / ((j1 - j0) * cellZ);
    }
}
