package org.jecosys.terrain;

import java.io.IOException;
import java.nio.file.Path;
import org.jecosys.math.Progress;
import org.jecosys.math.Require;
import org.jecosys.math.Rng;

/**
 * A terrain ready for plants: its heightfield and its initial water and nutrient maps (paper §4.3).
 * The maps are {@link ResourceMap#freeze() frozen}; a {@link TerrainDistributor} competes on copies.
 * Immutable; any thread may read it.
 */
public final class Terrain {
    /** Salt mixed into {@link TerrainDef#seed()} for the water map's noise. */
    public static final long WATER_SALT = 0x5741_5445_52L;
    /** Salt mixed into {@link TerrainDef#seed()} for the nutrient map's noise. */
    public static final long NUTRIENT_SALT = 0x4E55_5452_49L;

    private final Heightfield heightfield;
    private final ResourceMap water;
    private final ResourceMap nutrients;

    /**
     * A terrain from its parts. The maps are copied and frozen.
     *
     * @param heightfield the relief
     * @param water       the initial water map, covering the heightfield's extent
     * @param nutrients   the initial nutrient map, covering the heightfield's extent
     * @throws IllegalArgumentException on null parts or maps whose extent differs from the heightfield's
     */
    public Terrain(Heightfield heightfield, ResourceMap water, ResourceMap nutrients) {
        this.heightfield = Require.nonNull("heightfield", heightfield);
        Require.nonNull("water", water);
        Require.nonNull("nutrients", nutrients);
        checkExtent("water", water, heightfield);
        checkExtent("nutrients", nutrients, heightfield);
        this.water = water.copy().freeze();
        this.nutrients = nutrients.copy().freeze();
    }

    /**
     * {@link #build(TerrainDef, ImageSource, int, Progress)} with images from {@code baseDir}'s
     * folder tree ({@link ImageSource#folder}).
     *
     * @param def      the terrain's size, relief and resource maps
     * @param baseDir  directory relative image paths are resolved against (the scene file's folder);
     *                 may be null when the def names no image
     * @param workers  worker threads, at least 1
     * @param progress told "terrain" progress (in thousandths), on the calling thread
     * @return a new terrain
     * @throws IOException              when an image cannot be read
     * @throws IllegalArgumentException on null arguments or an unreadable image
     */
    public static Terrain build(TerrainDef def, Path baseDir, int workers, Progress progress) throws IOException {
        return build(def, baseDir == null ? ImageSource.NONE : ImageSource.folder(baseDir), workers, progress);
    }

    /**
     * Builds the terrain {@code def} describes: the heightfield (generated, or decoded from the
     * bytes of {@code def.heightmap()} read from {@code images}) and both resource maps (IMAGE maps
     * likewise; NOISE maps seeded from {@code def.seed()} with {@link #WATER_SALT} /
     * {@link #NUTRIENT_SALT}). Each image is read once, and the bytes read are the bytes decoded.
     * Deterministic for a def whatever the thread count.
     *
     * @param def      the terrain's size, relief and resource maps
     * @param images   where the images the def names come from ({@link ImageSource#NONE} when none)
     * @param workers  worker threads, at least 1
     * @param progress told "terrain" progress (in thousandths), on the calling thread
     * @return a new terrain
     * @throws IOException              when an image cannot be read, or decoding it would not fit
     *                                  in the heap
     * @throws IllegalArgumentException on null arguments or a file that is not an image
     */
    public static Terrain build(TerrainDef def, ImageSource images, int workers, Progress progress) throws IOException {
        Require.nonNull("def", def);
        Require.nonNull("images", images);
        Require.nonNull("progress", progress);
        // one "terrain" bar: the heightfield is the first 80 %, each map 10 %
        Progress relief = (step, done, total) -> progress.report("terrain", done * 800 / total, 1000);
        Heightfield hf = def.heightmap() == null
                ? Heightfield.generate(def, workers, relief)
                : Heightfield.fromImage(def, images, relief);
        ResourceMap w = ResourceMap.build(def.water(), hf, Rng.mix(def.seed() ^ WATER_SALT), images);
        progress.report("terrain", 900, 1000);
        ResourceMap n = ResourceMap.build(def.nutrients(), hf, Rng.mix(def.seed() ^ NUTRIENT_SALT), images);
        progress.report("terrain", 1000, 1000);
        return new Terrain(hf, w.freeze(), n.freeze());
    }

    /** {@return the heightfield} */
    public Heightfield heightfield() {
        return heightfield;
    }

    /** {@return the initial water map (frozen)} */
    public ResourceMap water() {
        return water;
    }

    /** {@return the initial nutrient map (frozen)} */
    public ResourceMap nutrients() {
        return nutrients;
    }

    private static void checkExtent(String name, ResourceMap m, Heightfield hf) {
        if (Math.abs(m.sizeX() - hf.sizeX()) > 1e-9 * hf.sizeX() || Math.abs(m.sizeZ() - hf.sizeZ()) > 1e-9 * hf.sizeZ()) {
            throw new IllegalArgumentException(name + " covers " + m.sizeX() + " x " + m.sizeZ()
                    + " m but the heightfield covers " + hf.sizeX() + " x " + hf.sizeZ() + " m");
        }
    }
}
