package org.jecosys.render.ground;

import static org.lwjgl.opengl.GL20C.glUniform1f;
import static org.lwjgl.opengl.GL20C.glUniform3f;
import static org.lwjgl.opengl.GL20C.glUniformMatrix4fv;

import java.nio.FloatBuffer;
import org.jecosys.math.Camera;
import org.jecosys.render.RenderSettings;
import org.jecosys.render.gl.GlProgram;
import org.joml.Matrix4f;
import org.lwjgl.system.MemoryUtil;

/**
 * The per-frame uniforms of the two programs that draw the ground's surface from {@code terrain.vert}
 * (the terrain and the cover skin over a host's ground): the view ({@code uViewProj}, {@code uEye}),
 * the light, haze, patches and cover colours ({@link GroundUniforms}), the sun's shadow map and its
 * strength ({@code uShadows}), and the cover's amount, grain and sheen ({@link CoverUniforms}). Owns a
 * 16-float native buffer freed by {@link #close}. Render thread; {@link #set} allocates nothing.
 */
final class SurfaceUniforms implements AutoCloseable {
    private final GroundUniforms ground;
    private final CoverUniforms cover;
    private final FloatBuffer matrix = MemoryUtil.memAllocFloat(16);
    private final Matrix4f viewProj = new Matrix4f();
    private final int uViewProj;
    private final int uEye;
    private final int uShadows;
    private boolean closed;

    /** Looks the uniforms up in a program that has them all. Setup time; allocates. */
    SurfaceUniforms(GlProgram program) {
        ground = new GroundUniforms(program);
        cover = new CoverUniforms(program);
        uViewProj = program.uniform("uViewProj");
        uEye = program.uniform("uEye");
        uShadows = program.uniform("uShadows");
    }

    /**
     * Sets them on the program in use.
     *
     * @param camera    the view
     * @param settings  the light, haze, patches, shadow strength and cover
     * @param shadow    the frame's sun shadow map
     * @param shadows   whether the ground's sun shadows are on this frame (strength 0 otherwise)
     * @param withCover whether the cover is drawn
     * @param withSheen whether the sheen is drawn (a bend map is bound)
     */
    void set(Camera camera, RenderSettings settings, ShadowParams shadow, boolean shadows, boolean withCover,
             boolean withSheen, float coverBeyond) {
        glUniformMatrix4fv(uViewProj, false, camera.viewProjection(viewProj).get(matrix));
        glUniform3f(uEye, (float) camera.x(), (float) camera.y(), (float) camera.z());
        ground.set(settings);
        ground.setShadowMap(shadow);
        glUniform1f(uShadows, shadows ? settings.shadows() : 0f);
        cover.set(settings, withCover, withSheen, coverBeyond);
    }

    /** Frees the matrix buffer. Idempotent. */
    @Override
    public void close() {
        if (!closed) {
            closed = true;
            MemoryUtil.memFree((java.nio.Buffer) matrix);
        }
    }
}
