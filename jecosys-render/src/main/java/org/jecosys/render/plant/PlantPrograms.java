package org.jecosys.render.plant;

import java.util.ArrayList;
import java.util.List;
import org.jecosys.render.GlContext;
import org.jecosys.render.ResolvePath;
import org.jecosys.render.gl.Closing;
import org.jecosys.render.gl.GlContexts;
import org.jecosys.render.gl.GlProgram;
import org.jecosys.render.gl.GlTracker;

/**
 * The programs every {@link PlantRenderer} of one context can share: the {@link PlantPasses#COUNT} draw
 * programs and the two resolve programs of one {@link ResolvePath}; and, made by the first renderer that
 * takes them, its plant model's pose tables and meshes, which the renderers of later worlds of the same
 * model read instead of uploading their own. Compiling them is most of what
 * making a renderer costs (tens of milliseconds on a software rasteriser), so renderers made often (an
 * open world's tiles) take them from here ({@link PlantRenderer#PlantRenderer(GlContext,
 * org.jecosys.sim.World, PlantPrograms)}) and leave them to this owner. The per-frame uniforms are set
 * by each renderer before its own draws. Render thread; {@link #compile} allocates; {@link #close()}
 * deletes them (after every renderer using them is closed).
 */
public final class PlantPrograms implements AutoCloseable {
    private final GlProgram[] draw = new GlProgram[PlantPasses.COUNT];
    private final GlProgram[] resolve = new GlProgram[2];
    private final ResolvePath path;
    private final List<AutoCloseable> owned = new ArrayList<>();
    /** The components' images as one array, shared by the renderers; null without textures. */
    private org.jecosys.render.gl.GlTextureArray textures;
    private boolean textured;
    /** The pose tables and meshes of the first model a renderer asked for ({@link #species}); null before. */
    private SpeciesGpu species;

    private PlantPrograms(ResolvePath path) {
        this.path = path;
    }

    /**
     * Compiles the programs for this context. Render thread; allocates.
     *
     * @param gl   the render context, current on this thread
     * @param path the resolve path; null: the best for this context ({@link ResolvePath#best(GlContext)})
     * @return the programs
     */
    public static PlantPrograms compile(GlContext gl, ResolvePath path) {
        return compile(gl, path, org.jecosys.plant.PlantTextures.NONE);
    }

    /**
     * Compiles the programs for worlds whose components draw {@code textures} (the triangle programs with
     * {@code TEXTURED}) and uploads the images once, for every renderer that takes these programs (an open
     * world's tiles share one model). Render thread; allocates.
     *
     * @param gl       the render context, current on this thread
     * @param path     the resolve path; null: the best for this context
     * @param textures the images of the worlds to draw ({@code PlantModel.textures()}), or NONE
     * @return the programs
     */
    public static PlantPrograms compile(GlContext gl, ResolvePath path, org.jecosys.plant.PlantTextures textures) {
        gl.checkThread();
        GlTracker t = GlContexts.tracker(gl);
        PlantPrograms p = new PlantPrograms(path == null ? ResolvePath.best(gl) : path);
        p.textured = !textures.isEmpty();
        try {
            for (int k = 0; k < p.draw.length; k++) {
                p.draw[k] = p.own(PlantPasses.compile(t, k, p.textured));
            }
            if (p.textured) {
                p.textures = p.own(new org.jecosys.render.gl.GlTextureArray(t, textures.side(), textures.layers(),
                        textures::level, !org.jecosys.render.gl.SoftwareGl.is(gl.describe())));
            }
            for (int k = 0; k < p.resolve.length; k++) {
                p.resolve[k] = p.own(ComponentResolver.compile(t, p.path, k));
            }
        } catch (RuntimeException | Error e) {
            p.close();
            throw e;
        }
        return p;
    }

    private <T extends AutoCloseable> T own(T resource) {
        owned.add(resource);
        return resource;
    }

    /**
     * The pose tables and meshes of {@code model}, made at the first call and kept, deleted with these
     * programs; every renderer of a world of that model reads them instead of its own. Null when an
     * earlier call made them for another model: that renderer uploads its own. Render thread; allocates
     * at the first call only.
     */
    SpeciesGpu species(GlTracker t, org.jecosys.plant.PlantModel model) {
        if (species == null) {
            species = own(new SpeciesGpu(t, model));
        }
        return species.model == model ? species : null;
    }

    /** {@return whether the draw programs read the components' images} */
    boolean textured() {
        return textured;
    }

    /** {@return the images' array shared by the renderers, or null without textures} */
    org.jecosys.render.gl.GlTextureArray textures() {
        return textures;
    }

    /** {@return the resolve path these programs run} */
    public ResolvePath path() {
        return path;
    }

    GlProgram draw(int k) {
        return draw[k];
    }

    GlProgram[] resolve() {
        return resolve;
    }

    /** Deletes the programs and the shared tables and meshes. Render thread; idempotent. */
    @Override
    public void close() {
        Closing.closeReverse(owned);
        owned.clear();
        species = null;
    }
}
