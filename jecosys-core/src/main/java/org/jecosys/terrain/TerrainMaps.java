package org.jecosys.terrain;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.jecosys.math.Require;

/**
 * PNG pictures of the water, nutrient and species maps, so a user sees why plants grow where they
 * do (paper §4.3). Pure functions of their arguments: image column grows with X, row with Z (row 0
 * at the terrain's lowest Z), each pixel sampled at its centre. Any thread; each call allocates its
 * image and writes one file, creating missing parent folders.
 */
public final class TerrainMaps {
    /** Dry end of the water ramp (pale sand), 0xRRGGBB. */
    public static final int WATER_LOW = 0xF2E6C8;
    /** Wet end of the water ramp (deep blue). */
    public static final int WATER_HIGH = 0x1F4FB8;
    /** Poor end of the nutrient ramp (pale grey). */
    public static final int NUTRIENTS_LOW = 0xE8E4DC;
    /** Rich end of the nutrient ramp (dark brown-green). */
    public static final int NUTRIENTS_HIGH = 0x3B5B1E;
    /** Largest image side, pixels. */
    public static final int MAX_SIDE = 16384;

    private TerrainMaps() {
    }

    /**
     * Writes {@code map} (e.g. {@link Terrain#water()}) with the {@link #WATER_LOW}-{@link #WATER_HIGH} ramp.
     *
     * @param map    the water map to draw
     * @param width  image width, pixels, in [1, {@link #MAX_SIDE}]
     * @param height image height, pixels, in [1, {@link #MAX_SIDE}]
     * @param out    the PNG file to write (replaced if it exists)
     * @throws IOException              when the file cannot be written
     * @throws IllegalArgumentException on null arguments or bad sizes
     */
    public static void writeWater(ResourceMap map, int width, int height, Path out) throws IOException {
        writeLevels(map, WATER_LOW, WATER_HIGH, width, height, out);
    }

    /**
     * Writes {@code map} with the {@link #NUTRIENTS_LOW}-{@link #NUTRIENTS_HIGH} ramp.
     *
     * @param map    the nutrient map to draw
     * @param width  image width, pixels, in [1, {@link #MAX_SIDE}]
     * @param height image height, pixels, in [1, {@link #MAX_SIDE}]
     * @param out    the PNG file to write (replaced if it exists)
     * @throws IOException              when the file cannot be written
     * @throws IllegalArgumentException on null arguments or bad sizes
     */
    public static void writeNutrients(ResourceMap map, int width, int height, Path out) throws IOException {
        writeLevels(map, NUTRIENTS_LOW, NUTRIENTS_HIGH, width, height, out);
    }

    /**
     * Writes a resource map as a colour ramp: level 0 is {@code lowRgb}, level 1 {@code highRgb}
     * (0xRRGGBB), bilinear levels ({@link ResourceMap#sample}) at pixel centres.
     *
     * @param map     the map to draw
     * @param lowRgb  colour of level 0, 0xRRGGBB
     * @param highRgb colour of level 1, 0xRRGGBB
     * @param width   image width, pixels, in [1, {@link #MAX_SIDE}]
     * @param height  image height, pixels, in [1, {@link #MAX_SIDE}]
     * @param out     the PNG file to write (replaced if it exists)
     * @throws IOException              when the file cannot be written
     * @throws IllegalArgumentException on null arguments or bad sizes
     */
    public static void writeLevels(ResourceMap map, int lowRgb, int highRgb, int width, int height, Path out)
            throws IOException {
        Require.nonNull("map", map);
        checkSize(width, height, out);
        BufferedImage img = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        for (int py = 0; py < height; py++) {
            double z = -map.sizeZ() / 2 + (py + 0.5) / height * map.sizeZ();
            for (int px = 0; px < width; px++) {
                double x = -map.sizeX() / 2 + (px + 0.5) / width * map.sizeX();
                img.setRGB(px, py, lerpRgb(lowRgb, highRgb, map.sample(x, z)));
            }
        }
        write(img, out);
    }

    /**
     * Writes the species map: the terrain as grey hill shading (light from the north-west, darker
     * where steep), each plant a disc of its footprint (at least one pixel) in {@code palette[species]}.
     * Plants are drawn in layout order.
     *
     * @param terrain the relief to shade; its extent maps onto the image
     * @param layout  the plants to draw
     * @param palette 0xRRGGBB per species index; longer than the largest species index in the layout
     * @param width   image width, pixels, in [1, {@link #MAX_SIDE}]
     * @param height  image height, pixels, in [1, {@link #MAX_SIDE}]
     * @param out     the PNG file to write (replaced if it exists)
     * @throws IOException              when the file cannot be written
     * @throws IllegalArgumentException on null arguments, bad sizes or a palette too short
     */
    public static void writeSpecies(Heightfield terrain, PlantLayout layout, int[] palette, int width, int height,
                                    Path out) throws IOException {
        Require.nonNull("terrain", terrain);
        Require.nonNull("layout", layout);
        Require.nonNull("palette", palette);
        checkSize(width, height, out);
        for (int i = 0; i < layout.count(); i++) {
            if (layout.species(i) >= palette.length) {
                throw new IllegalArgumentException("palette has " + palette.length + " colours but plant " + i
                        + " has species index " + layout.species(i));
            }
        }
        double sx = terrain.sizeX();
        double sz = terrain.sizeZ();
        BufferedImage img = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        org.joml.Vector3f n = new org.joml.Vector3f();
        double lx = -0.5;
        double ly = 0.75;
        double lz = -0.43;
        double ll = Math.sqrt(lx * lx + ly * ly + lz * lz);
        for (int py = 0; py < height; py++) {
            double z = -sz / 2 + (py + 0.5) / height * sz;
            for (int px = 0; px < width; px++) {
                double x = -sx / 2 + (px + 0.5) / width * sx;
                terrain.normal(x, z, n);
                double lambert = Math.max(0, (n.x * lx + n.y * ly + n.z * lz) / ll);
                int g = (int) Math.round(90 + 110 * lambert);
                img.setRGB(px, py, (g << 16) | (g << 8) | g);
            }
        }
        double ppmX = width / sx;
        double ppmZ = height / sz;
        for (int i = 0; i < layout.count(); i++) {
            double cx = (layout.x(i) + sx / 2) * ppmX - 0.5;
            double cz = (layout.z(i) + sz / 2) * ppmZ - 0.5;
            double rx = layout.footprint(i) * ppmX;
            double rz = layout.footprint(i) * ppmZ;
            int rgb = palette[layout.species(i)] & 0xFFFFFF;
            int x0 = (int) Math.max(0, Math.floor(cx - rx));
            int x1 = (int) Math.min(width - 1, Math.ceil(cx + rx));
            int z0 = (int) Math.max(0, Math.floor(cz - rz));
            int z1 = (int) Math.min(height - 1, Math.ceil(cz + rz));
            boolean any = false;
            for (int py = z0; py <= z1; py++) {
                for (int px = x0; px <= x1; px++) {
                    double dx = (px - cx) / Math.max(rx, 1e-9);
                    double dz = (py - cz) / Math.max(rz, 1e-9);
                    if (dx * dx + dz * dz <= 1) {
                        img.setRGB(px, py, rgb);
                        any = true;
                    }
                }
            }
            if (!any) {
                int px = (int) Math.max(0, Math.min(width - 1, Math.round(cx)));
                int py = (int) Math.max(0, Math.min(height - 1, Math.round(cz)));
                img.setRGB(px, py, rgb);
            }
        }
        write(img, out);
    }

    private static void checkSize(int width, int height, Path out) {
        Require.range("width", width, 1, MAX_SIDE);
        Require.range("height", height, 1, MAX_SIDE);
        Require.nonNull("out", out);
    }

    private static int lerpRgb(int a, int b, double t) {
        t = Math.max(0, Math.min(1, t));
        int r = (int) Math.round(((a >> 16) & 0xFF) + (((b >> 16) & 0xFF) - ((a >> 16) & 0xFF)) * t);
        int g = (int) Math.round(((a >> 8) & 0xFF) + (((b >> 8) & 0xFF) - ((a >> 8) & 0xFF)) * t);
        int bl = (int) Math.round((a & 0xFF) + ((b & 0xFF) - (a & 0xFF)) * t);
        return (r << 16) | (g << 8) | bl;
    }

    private static void write(BufferedImage img, Path out) throws IOException {
        Path parent = out.toAbsolutePath().getParent();
        if (parent != null) {
            Files.createDirectories(parent);
        }
        if (!ImageIO.write(img, "png", out.toFile())) {
            throw new IOException("no PNG writer available for " + out);
        }
    }
}
