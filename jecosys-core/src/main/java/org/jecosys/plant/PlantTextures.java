package org.jecosys.plant;

import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import javax.imageio.ImageIO;
import org.jecosys.math.Require;

/**
 * The images drawn on components ({@link ComponentDef#texture()}), decoded once for every renderer: each
 * distinct image is one layer of a square texture array, {@link #side()} texels a side (the largest
 * image's larger side, rounded up to a power of two, at most {@link #MAX_LAYER_SIDE}), with its whole
 * mip chain, so a renderer uploads them as they are and draws every textured species in its usual
 * instanced draws (a layer index per vertex, no draw per texture).
 *
 * <p>Prepared for thin, alpha-cut parts seen from afar:
 * <ul>
 * <li><b>No dark fringes.</b> The colour of transparent texels is not the file's (often black): each
 *     takes the colour of the nearest visible texel (grown outward a texel at a time, then the image's
 *     mean), so filtering across an outline never mixes in a colour that is not there.</li>
 * <li><b>Coverage kept in the distance.</b> Each mip level's alpha is scaled so that the share of its
 *     texels at or above one half (the alpha test's and the coverage's midpoint) is the full image's:
 *     a blade does not thin out and vanish as its texture shrinks (plain averaging would halve a
 *     one-texel-wide stem's alpha at every level).</li>
 * <li><b>Orientation.</b> Layer row 0 is the image's bottom row: on a strip v runs from the base
 *     (the image's bottom) to the tip (its top), u across from the left edge (side -1) to the right;
 *     on a fan the image is centred on the base, its edge on the rim.</li>
 * </ul>
 * The colours stay as stored (sRGB values, the way component colours are used); the component's
 * {@code colour} multiplies them, and the far levels drawn as lines use the colour times the layer's
 * {@link #meanColour mean} (alpha-weighted).
 *
 * <p>Immutable after construction; any thread; accessors do not allocate. {@link #load} allocates.
 */
public final class PlantTextures {
    /** Largest side of a texture file, pixels. */
    public static final int MAX_SIDE = 2048;
    /** Largest side of a layer, texels: larger images are resampled down to it. */
    public static final int MAX_LAYER_SIDE = 512;
    /** Smallest side of a layer, texels. */
    public static final int MIN_LAYER_SIDE = 8;
    /** Most distinct textures in one scene. */
    public static final int MAX_TEXTURES = 64;
    /** No textures. */
    public static final PlantTextures NONE = new PlantTextures(List.of(), 0, new byte[0][][], new float[0][],
            new int[0][]);

    private final List<String> paths;
    private final int side;
    private final byte[][][] levels;
    private final float[][] mean;
    private final int[][] layerOf;

    private PlantTextures(List<String> paths, int side, byte[][][] levels, float[][] mean, int[][] layerOf) {
        this.paths = paths;
        this.side = side;
        this.levels = levels;
        this.mean = mean;
        this.layerOf = layerOf;
    }

    /**
     * Reads and prepares the textures the species name. Build time; allocates.
     *
     * @param species the species, in the scene's order
     * @param images  where the paths are read from (the scene's image source: {@code images::read})
     * @return the textures; {@link #NONE} when no component names one
     * @throws IOException naming the path, when an image cannot be read or decoded, is larger than
     *                     {@link #MAX_SIDE}, or there are more than {@link #MAX_TEXTURES}
     */
    public static PlantTextures load(List<SpeciesDef> species, Files images) throws IOException {
        Require.nonNull("species", species);
        Require.nonNull("images", images);
        Map<String, int[]> decoded = new LinkedHashMap<>();
        Map<String, int[]> sizes = new HashMap<>();
        for (SpeciesDef s : species) {
            for (ComponentDef c : s.components()) {
                String path = c.texture();
                if (path == null || decoded.containsKey(path)) {
                    continue;
                }
                if (decoded.size() == MAX_TEXTURES) {
                    throw new IOException("texture '" + path + "': a scene has at most " + MAX_TEXTURES
                            + " distinct textures");
                }
                BufferedImage img = ImageIO.read(new ByteArrayInputStream(images.read(path)));
                if (img == null) {
                    throw new IOException("texture '" + path + "': not an image this reader knows (PNG, JPEG, BMP, GIF)");
                }
                if (img.getWidth() > MAX_SIDE || img.getHeight() > MAX_SIDE) {
                    throw new IOException("texture '" + path + "': " + img.getWidth() + "x" + img.getHeight()
                            + " pixels; at most " + MAX_SIDE + " a side");
                }
                decoded.put(path, img.getRGB(0, 0, img.getWidth(), img.getHeight(), null, 0, img.getWidth()));
                sizes.put(path, new int[] {img.getWidth(), img.getHeight()});
            }
        }
        if (decoded.isEmpty()) {
            return NONE;
        }
        Map<String, Image> byPath = new LinkedHashMap<>();
        for (Map.Entry<String, int[]> e : decoded.entrySet()) {
            int[] wh = sizes.get(e.getKey());
            byPath.put(e.getKey(), new Image(wh[0], wh[1], e.getValue()));
        }
        return of(species, byPath);
    }

    /** Where image files come from: the whole file's bytes by the path a scene writes (a scene's image source). */
    @FunctionalInterface
    public interface Files {
        /**
         * {@return the file's bytes}
         *
         * @param path as the scene writes it
         * @throws IOException naming the path, when it cannot be read
         */
        byte[] read(String path) throws IOException;
    }

    /**
     * An image as ARGB pixels, rows from the top (as {@code BufferedImage.getRGB} gives them).
     *
     * @param width  pixels, &gt;= 1
     * @param height pixels, &gt;= 1
     * @param argb   width x height pixels, 0xAARRGGBB, not premultiplied
     */
    public record Image(int width, int height, int[] argb) {
        /**
         * Checks the size.
         *
         * @param width  pixels, in [1, {@link #MAX_SIDE}]
         * @param height pixels, in [1, {@link #MAX_SIDE}]
         * @param argb   width x height pixels
         */
        public Image {
            Require.range("width", width, 1, MAX_SIDE);
            Require.range("height", height, 1, MAX_SIDE);
            if (argb.length != width * height) {
                throw new IllegalArgumentException("argb holds " + argb.length + " pixels, not " + width * height);
            }
        }
    }

    /**
     * Prepares decoded images (a game's own, or a test's). Build time; allocates.
     *
     * @param species the species, in the scene's order
     * @param images  by path: every texture a component names
     * @return the textures; {@link #NONE} when no component names one
     * @throws IllegalArgumentException when a named texture is missing from {@code images}
     */
    public static PlantTextures of(List<SpeciesDef> species, Map<String, Image> images) {
        List<String> paths = new ArrayList<>();
        int[][] layerOf = new int[species.size()][];
        int largest = 1;
        for (int s = 0; s < species.size(); s++) {
            List<ComponentDef> comps = species.get(s).components();
            layerOf[s] = new int[comps.size()];
            for (int c = 0; c < comps.size(); c++) {
                String path = comps.get(c).texture();
                if (path == null) {
                    layerOf[s][c] = -1;
                    continue;
                }
                Image img = images.get(path);
                if (img == null) {
                    throw new IllegalArgumentException("texture '" + path + "' was not given");
                }
                int k = paths.indexOf(path);
                if (k < 0) {
                    k = paths.size();
                    paths.add(path);
                    largest = Math.max(largest, Math.max(img.width(), img.height()));
                }
                layerOf[s][c] = k;
            }
        }
        if (paths.isEmpty()) {
            return NONE;
        }
        int side = MIN_LAYER_SIDE;
        while (side < largest && side < MAX_LAYER_SIDE) {
            side *= 2;
        }
        byte[][][] levels = new byte[paths.size()][][];
        float[][] mean = new float[paths.size()][];
        for (int k = 0; k < paths.size(); k++) {
            Image img = images.get(paths.get(k));
            float[] rgba = TextureFilter.bleed(TextureFilter.floats(img), img.width(), img.height());
            float[] square = TextureFilter.resample(rgba, img.width(), img.height(), side);
            mean[k] = TextureFilter.mean(square);
            levels[k] = TextureFilter.mips(square, side);
        }
        return new PlantTextures(List.copyOf(paths), side, levels, mean, layerOf);
    }

    /** {@return whether there is no texture} */
    public boolean isEmpty() {
        return paths.isEmpty();
    }

    /** {@return the number of layers: distinct textures} */
    public int layers() {
        return paths.size();
    }

    /**
     * {@return the path of layer k, as the scene writes it}
     *
     * @param k the layer
     */
    public String path(int k) {
        return paths.get(k);
    }

    /** {@return the side of every layer, texels (a power of two); 0 without textures} */
    public int side() {
        return side;
    }

    /** {@return the number of mip levels of each layer: log2(side) + 1} */
    public int levelCount() {
        return side == 0 ? 0 : Integer.numberOfTrailingZeros(side) + 1;
    }

    /**
     * The texels of one level of one layer: RGBA, one byte each, rows from the base (the image's bottom
     * row) up; level {@code m} is {@code side >> m} texels a side. Shared: do not modify.
     *
     * @param layer the layer
     * @param level the mip level, 0 the full size
     * @return the texels
     */
    public byte[] level(int layer, int level) {
        return levels[layer][level];
    }

    /**
     * The layer of a species' component, or -1 when it has no texture. No allocation.
     *
     * @param species   the species' index in the scene
     * @param component the component's index in its species
     * @return the layer, or -1
     */
    public int layer(int species, int component) {
        return species < layerOf.length ? layerOf[species][component] : -1;
    }

    /**
     * The layer's mean colour, weighted by alpha, red, green and blue in [0, 1] (sRGB values): what a
     * far line standing for a textured part is tinted with.
     *
     * @param layer the layer
     * @param dest  three floats
     * @return {@code dest}
     */
    public float[] meanColour(int layer, float[] dest) {
        dest[0] = mean[layer][0];
        dest[1] = mean[layer][1];
        dest[2] = mean[layer][2];
        return dest;
    }

    /**
     * {@return the share of the layer's full-size texels with alpha at or above one half}
     *
     * @param layer the layer
     */
    public double coverage(int layer) {
        return TextureFilter.coverage(levels[layer][0]);
    }
}
