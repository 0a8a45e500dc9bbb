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
 * programs and the two resolve programs of one {@link ResolvePath}. Compiling them is most of what
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
        gl.checkThread();
        GlTracker t = GlContexts.tracker(gl);
        PlantPrograms p = new PlantPrograms(path == null ? ResolvePath.best(gl) : path);
        try {
            for (int k = 0; k < p.draw.length; k++) {
                p.draw[k] = p.own(PlantPasses.compile(t, k));
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

    private GlProgram own(GlProgram program) {
        owned.add(program);
        return program;
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

    /** Deletes the programs. Render thread; idempotent. */
    @Override
    public void close() {
        Closing.closeReverse(owned);
        owned.clear();
    }
}
