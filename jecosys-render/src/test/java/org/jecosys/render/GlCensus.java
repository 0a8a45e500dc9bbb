package org.jecosys.render;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.function.IntPredicate;
import org.lwjgl.opengl.GL11C;
import org.lwjgl.opengl.GL15C;
import org.lwjgl.opengl.GL20C;
import org.lwjgl.opengl.GL30C;
import org.lwjgl.opengl.GL33C;
import org.jecosys.render.gl.GlTracker;

/**
 * Every GL object of the current context, whoever made it, found by asking the driver about each
 * name ({@code glIsBuffer}, {@code glIsTexture}, ...) from 1 to {@link #NAMES}: the count that
 * {@link GlTracker} cannot give for objects made by code we do not own (the ImGui GL3 backend), and a
 * cross-check that ours are all tracked. Mesa hands out the lowest free name of each kind, so the
 * names of a test's objects stay small; {@link #take} fails if one comes near the probed range, where
 * the census could miss some. Render thread; allocates a little.
 */
public record GlCensus(int buffers, int textures, int vertexArrays, int programs, int shaders, int framebuffers,
                int renderbuffers, int samplers) {
    /** Highest name probed for each kind. */
    static final int NAMES = 1 << 13;

    public static GlCensus take() {
        return new GlCensus(count("buffer", GL15C::glIsBuffer), count("texture", GL11C::glIsTexture),
                count("vertex array", GL30C::glIsVertexArray), count("program", GL20C::glIsProgram),
                count("shader", GL20C::glIsShader), count("framebuffer", GL30C::glIsFramebuffer),
                count("renderbuffer", GL30C::glIsRenderbuffer), count("sampler", GL33C::glIsSampler));
    }

    private static int count(String kind, IntPredicate exists) {
        int n = 0;
        int highest = 0;
        for (int name = 1; name <= NAMES; name++) {
            if (exists.test(name)) {
                n++;
                highest = name;
            }
        }
        assertTrue(highest < NAMES / 2, "the census of " + kind + " names reached " + highest
                + ": raise NAMES, or it may miss objects");
        return n;
    }

    /** All objects of every kind. */
    int total() {
        return buffers + textures + vertexArrays + programs + shaders + framebuffers + renderbuffers + samplers;
    }

    /** This census less {@code before}, kind by kind. */
    public GlCensus minus(GlCensus before) {
        return new GlCensus(buffers - before.buffers, textures - before.textures,
                vertexArrays - before.vertexArrays, programs - before.programs, shaders - before.shaders,
                framebuffers - before.framebuffers, renderbuffers - before.renderbuffers, samplers - before.samplers);
    }
}
