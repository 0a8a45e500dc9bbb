package org.jecosys.render.gl;

import org.lwjgl.opengl.GL11C;
import org.lwjgl.opengl.GL13C;
import org.lwjgl.opengl.GL20C;
import org.lwjgl.opengl.GL30C;

/**
 * What a full-screen pass of a framebuffer's resolve changes, saved before it and put back after it:
 * the program, the vertex array, the active texture unit, the 2D texture of each unit the pass binds, and
 * the depth test, blending, scissor and culling switches (which {@link #save} turns off). Owned by one
 * pass; render thread only; no allocation after construction. {@link #close()} frees its query word.
 */
final class PassState implements AutoCloseable {
    private final GlInts query = new GlInts();
    private final int[] units;
    private final int[] textures;
    private int program;
    private int vao;
    private int unit;
    private boolean depth;
    private boolean blend;
    private boolean scissor;
    private boolean cull;

    /** @param units the texture units whose 2D binding the pass changes */
    PassState(int... units) {
        this.units = units.clone();
        this.textures = new int[units.length];
    }

    /** Records the state and turns the four switches off. */
    void save() {
        program = query.get(GL20C.GL_CURRENT_PROGRAM);
        vao = query.get(GL30C.GL_VERTEX_ARRAY_BINDING);
        unit = query.get(GL13C.GL_ACTIVE_TEXTURE);
        for (int i = 0; i < units.length; i++) {
            GL13C.glActiveTexture(GL13C.GL_TEXTURE0 + units[i]);
            textures[i] = query.get(GL11C.GL_TEXTURE_BINDING_2D);
        }
        GL13C.glActiveTexture(unit);
        depth = GL11C.glIsEnabled(GL11C.GL_DEPTH_TEST);
        blend = GL11C.glIsEnabled(GL11C.GL_BLEND);
        scissor = GL11C.glIsEnabled(GL11C.GL_SCISSOR_TEST);
        cull = GL11C.glIsEnabled(GL11C.GL_CULL_FACE);
        GL11C.glDisable(GL11C.GL_DEPTH_TEST);
        GL11C.glDisable(GL11C.GL_BLEND);
        GL11C.glDisable(GL11C.GL_SCISSOR_TEST);
        GL11C.glDisable(GL11C.GL_CULL_FACE);
    }

    /** Binds a 2D texture on a unit (leaves that unit active). */
    static void bind(int textureUnit, int texture) {
        GL13C.glActiveTexture(GL13C.GL_TEXTURE0 + textureUnit);
        GL11C.glBindTexture(GL11C.GL_TEXTURE_2D, texture);
    }

    /** Puts back what {@link #save} recorded. */
    void restore() {
        GL30C.glBindVertexArray(vao);
        GL20C.glUseProgram(program);
        for (int i = 0; i < units.length; i++) {
            bind(units[i], textures[i]);
        }
        GL13C.glActiveTexture(unit);
        enable(GL11C.GL_DEPTH_TEST, depth);
        enable(GL11C.GL_BLEND, blend);
        enable(GL11C.GL_SCISSOR_TEST, scissor);
        enable(GL11C.GL_CULL_FACE, cull);
    }

    private static void enable(int cap, boolean on) {
        if (on) {
            GL11C.glEnable(cap);
        } else {
            GL11C.glDisable(cap);
        }
    }

    @Override
    public void close() {
        query.close();
    }
}
