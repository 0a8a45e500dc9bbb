package org.jecosys.render.ground;

import org.jecosys.render.Lighting;
import org.jecosys.render.gl.GlContexts;
import org.jecosys.render.gl.Closing;
import static org.lwjgl.opengl.GL11C.GL_TRIANGLES;
import static org.lwjgl.opengl.GL11C.glDrawArrays;
import static org.lwjgl.opengl.GL20C.glUniform3f;
import static org.lwjgl.opengl.GL20C.glUniformMatrix4fv;
import static org.lwjgl.opengl.GL30C.glBindVertexArray;

import java.nio.FloatBuffer;
import org.jecosys.math.Camera;
import org.joml.Matrix4f;
import org.lwjgl.system.MemoryUtil;
import org.jecosys.render.GlContext;
import org.jecosys.render.RenderSettings;
import org.jecosys.render.gl.GlProgram;
import org.jecosys.render.gl.GlVertexArray;

/**
 * The sky: one full-screen triangle at depth 1 shading a vertical gradient from
 * {@link RenderSettings#sky()} at the horizon (and below it) to {@link RenderSettings#skyZenith()},
 * brighter toward the sun, with a glow and the sun's disc. Drawn with the depth test on
 * ({@code GL_LEQUAL}) and depth writes off after the opaque geometry, so it shades only the pixels
 * nothing covers. Render thread only; {@link #draw} allocates nothing.
 */
public final class SkyRenderer implements AutoCloseable {
    private final GlProgram program;
    private final GlVertexArray vao;
    private final FloatBuffer matrix;
    private final Matrix4f viewProj = new Matrix4f();
    private final int uInvViewProj;
    private final int uHorizon;
    private final int uZenith;
    private final int uSunDir;
    private final int uSunColour;
    private final int uClouds;
    private boolean closed;

    /**
     * Compiles the sky program. Render thread; allocates.
     *
     * @param gl the render context, current on this thread
     */
    public SkyRenderer(GlContext gl) {
        gl.checkThread();
        GlProgram p = new GlProgram(GlContexts.tracker(gl), "sky.vert", "sky.frag");
        GlVertexArray v;
        try {
            v = new GlVertexArray(GlContexts.tracker(gl));
        } catch (RuntimeException e) {
            p.close();
            throw e;
        }
        program = p;
        vao = v;
        matrix = MemoryUtil.memAllocFloat(16);
        uInvViewProj = program.uniform("uInvViewProj");
        uHorizon = program.uniform("uHorizon");
        uZenith = program.uniform("uZenith");
        uSunDir = program.uniform("uSunDir");
        uSunColour = program.uniform("uSunColour");
        uClouds = program.uniform("uClouds");
    }

    /**
     * Draws the sky over the bound viewport where the depth buffer still holds 1, with the caller's
     * depth state (the scene renderer sets the test on, {@code GL_LEQUAL}, writes off). Render thread;
     * no allocation.
     *
     * @param camera   the viewer
     * @param settings the horizon and zenith colours and the sun
     */
    public void draw(Camera camera, RenderSettings settings) {
        program.use();
        glUniformMatrix4fv(uInvViewProj, false, camera.viewProjection(viewProj).invert().get(matrix));
        Lighting l = settings.lighting();
        float k = l.sunIntensity();
        glUniform3f(uHorizon, l.skyR(), l.skyG(), l.skyB());
        glUniform3f(uZenith, l.zenithR(), l.zenithG(), l.zenithB());
        glUniform3f(uSunDir, l.sunX(), l.sunY(), l.sunZ());
        glUniform3f(uSunColour, l.sunR() * k, l.sunG() * k, l.sunB() * k);
        org.lwjgl.opengl.GL20C.glUniform1f(uClouds, l.clouds());
        vao.bind();
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glBindVertexArray(0);
    }

    /** Deletes the GL objects. Render thread; idempotent. */
    @Override
    public void close() {
        if (!closed) {
            closed = true;
            Closing.closeAll(vao, program);
            MemoryUtil.memFree((java.nio.Buffer) matrix);
        }
    }
}
