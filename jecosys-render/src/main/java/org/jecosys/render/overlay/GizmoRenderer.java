package org.jecosys.render.overlay;

import org.jecosys.render.gl.GlContexts;
import org.jecosys.render.gl.Closing;
import static org.lwjgl.opengl.GL11C.GL_BLEND;
import static org.lwjgl.opengl.GL11C.GL_CULL_FACE;
import static org.lwjgl.opengl.GL11C.GL_DEPTH_TEST;
import static org.lwjgl.opengl.GL11C.GL_FLOAT;
import static org.lwjgl.opengl.GL11C.GL_GREATER;
import static org.lwjgl.opengl.GL11C.GL_LEQUAL;
import static org.lwjgl.opengl.GL11C.GL_ONE_MINUS_SRC_ALPHA;
import static org.lwjgl.opengl.GL11C.GL_SRC_ALPHA;
import static org.lwjgl.opengl.GL11C.GL_TRIANGLES;
import static org.lwjgl.opengl.GL11C.glBlendFunc;
import static org.lwjgl.opengl.GL11C.glDepthFunc;
import static org.lwjgl.opengl.GL11C.glDepthMask;
import static org.lwjgl.opengl.GL11C.glDisable;
import static org.lwjgl.opengl.GL11C.glDrawArrays;
import static org.lwjgl.opengl.GL11C.glEnable;
import static org.lwjgl.opengl.GL15C.GL_ARRAY_BUFFER;
import static org.lwjgl.opengl.GL20C.glEnableVertexAttribArray;
import static org.lwjgl.opengl.GL20C.glUniform1f;
import static org.lwjgl.opengl.GL20C.glUniformMatrix4fv;
import static org.lwjgl.opengl.GL20C.glVertexAttribPointer;
import static org.lwjgl.opengl.GL30C.glBindVertexArray;

import java.nio.FloatBuffer;
import org.jecosys.field.FieldDebugView;
import org.jecosys.math.Camera;
import org.jecosys.math.Require;
import org.jecosys.terrain.Heightfield;
import org.joml.Matrix4f;
import org.lwjgl.system.MemoryUtil;
import org.jecosys.render.GlContext;
import org.jecosys.render.gl.GlBuffer;
import org.jecosys.render.gl.GlProgram;
import org.jecosys.render.gl.GlStateGuard;
import org.jecosys.render.gl.GlTracker;
import org.jecosys.render.gl.GlVertexArray;

/**
 * Draws, in the 3D view over a rendered scene, what the wind is made of and what it does: one gizmo
 * per flow and agent ({@link Gizmos}: centre, influence radius as a ring draped on the terrain, core
 * radius, the direction of a uniform or gust flow, the outward or inward arrows of a source, sink,
 * blast or agent, the spin of a vortex, the activation state as colour and alpha; paper §3.2) and,
 * optionally, the wind the plants feel: one arrow per visible effective node of the force field
 * (paper §3, Figure 3 in 3D), coloured by speed on a scale whose colours {@link #windColour} gives
 * for a legend.
 *
 * <p>Ground lines are depth-tested against the scene already in the framebuffer, and drawn a second
 * time faintly where the scene hides them (through grass and over hills); each gizmo's handle (a
 * pole from its centre to a round head, and a dot at the centre) is drawn on top of everything so it
 * can always be seen and picked: {@link #HEAD_PX} and {@link #POLE_PX} give its size on screen.
 *
 * <p>State contract, as {@code SceneRenderer}'s: it draws into the bound framebuffer and viewport and
 * puts back every GL state it changes ({@link GlStateGuard}); the framebuffer binding is not changed.
 * Render thread only. {@link #render} allocates nothing on the Java heap unless the geometry grew
 * past its capacity; {@link #close()} releases every GL object and the native storage.
 */
public final class GizmoRenderer implements AutoCloseable {
    /** Radius of a gizmo's head on screen, pixels. */
    public static final float HEAD_PX = GizmoMesh.HEAD_PX;
    /** Height of a gizmo's pole on screen, from its centre on the ground to its head, pixels. */
    public static final float POLE_PX = GizmoMesh.POLE_PX;
    /** Alpha of the parts of the ground lines that the scene hides. */
    public static final float HIDDEN_ALPHA = 0.35f;

    private final GlTracker tracker;
    private final GizmoMesh mesh;
    private final GlProgram program;
    private final GlVertexArray vao;
    private final GlStateGuard state;
    private final FloatBuffer matrix;
    private final Matrix4f viewProj = new Matrix4f();
    private final int uViewProj;
    private final int uAlpha;
    private GlBuffer vertices;
    private boolean closed;

    /**
     * Creates the program and buffers. Render thread; allocates.
     *
     * @param gl     the render context, current on this thread
     * @param ground the terrain the gizmos and arrows are draped on
     */
    public GizmoRenderer(GlContext gl, Heightfield ground) {
        gl.checkThread();
        Require.nonNull("ground", ground);
        this.tracker = GlContexts.tracker(gl);
        GizmoMesh m = null;
        GlProgram p = null;
        GlVertexArray va = null;
        GlStateGuard g = null;
        FloatBuffer mat = null;
        try {
            m = new GizmoMesh(ground);
            p = new GlProgram(tracker, "gizmo.vert", "gizmo.frag");
            uViewProj = p.uniform("uViewProj");
            uAlpha = p.uniform("uAlpha");
            va = new GlVertexArray(tracker);
            g = new GlStateGuard();
            mat = MemoryUtil.memAllocFloat(16);
        } catch (RuntimeException e) {
            Closing.closeAll(g, va, p, m);
            throw e;
        }
        mesh = m;
        program = p;
        vao = va;
        state = g;
        matrix = mat;
        try {
            reserve(8192);
        } catch (RuntimeException e) {
            close();
            throw e;
        }
    }

    private void reserve(int vertexCount) {
        GlBuffer old = vertices;
        vertices = null;
        if (old != null) {
            old.close();
        }
        int saved = org.lwjgl.opengl.GL11C.glGetInteger(org.lwjgl.opengl.GL15C.GL_ARRAY_BUFFER_BINDING);
        int savedVao = org.lwjgl.opengl.GL11C.glGetInteger(org.lwjgl.opengl.GL30C.GL_VERTEX_ARRAY_BINDING);
        try {
            vertices = GlBuffer.dynamic(tracker, GL_ARRAY_BUFFER, 4L * GizmoMesh.FLOATS * vertexCount);
            vao.bind();
            vertices.bind();
            glEnableVertexAttribArray(0);
            glVertexAttribPointer(0, 3, GL_FLOAT, false, GizmoMesh.FLOATS * 4, 0L);
            glEnableVertexAttribArray(1);
            glVertexAttribPointer(1, 4, GL_FLOAT, false, GizmoMesh.FLOATS * 4, 12L);
        } finally {
            glBindVertexArray(savedVao);
            org.lwjgl.opengl.GL15C.glBindBuffer(GL_ARRAY_BUFFER, saved);
        }
    }

    /**
     * The colour of a wind speed on the overlay's scale: blue at 0, then cyan, yellow, and red at
     * {@code scale} and above, for a legend drawn by the application. Any thread; no allocation.
     *
     * @param speed wind speed, m/s
     * @param scale speed at the top of the scale, m/s, &gt; 0
     * @param rgb   where the red, green and blue components (in [0, 1]) are written, length &ge; 3
     * @return {@code rgb}
     */
    public static float[] windColour(double speed, double scale, float[] rgb) {
        Require.positive("scale", scale);
        GizmoMesh.windColour(speed, scale, rgb);
        return rgb;
    }

    /**
     * The colour a gizmo is drawn in: its kind's colour at full alpha when switched on and fully
     * active, fainter and greyer as its activation weight falls, grey and faint when switched off.
     * Any thread; no allocation.
     *
     * @param kind    the gizmo's kind
     * @param enabled the flow's switch
     * @param weight  its activation weight, in [0, 1]
     * @param rgba    where red, green, blue and alpha (in [0, 1]) are written, length &ge; 4
     * @return {@code rgba}
     */
    public static float[] shade(GizmoKind kind, boolean enabled, double weight, float[] rgba) {
        Require.nonNull("kind", kind);
        GizmoMesh.shade(kind, enabled, weight, rgba);
        return rgba;
    }

    /**
     * Draws the wind arrows (when {@code wind} is not null) and the gizmos into the bound framebuffer
     * and viewport, over what is there (depth-tested against its depth buffer), and puts back every
     * GL state it changed. Render thread; no allocation unless the geometry grew.
     *
     * @param gizmos    the flows' and agents' gizmos, or null for none
     * @param wind      the force field's debug view, for one arrow per visible effective node, or null
     * @param windScale the wind speed drawn red and full length, m/s, &gt; 0
     * @param camera    the viewer; its aspect should match the viewport's
     */
    public void render(Gizmos gizmos, FieldDebugView wind, double windScale, Camera camera) {
        if (closed) {
            throw new IllegalStateException("the gizmo renderer is closed");
        }
        Require.nonNull("camera", camera);
        Require.positive("windScale", windScale);
        state.save();
        state.setGuestState();
        try {
            int height = state.viewportHeight();
            if (height <= 0 || state.viewportWidth() <= 0) {
                return;
            }
            mesh.build(gizmos, wind, windScale, camera, height);
            int groundCount = mesh.groundVertices();
            int handleCount = mesh.handleVertices();
            if (groundCount + handleCount == 0) {
                return;
            }
            long needed = 4L * GizmoMesh.FLOATS * (groundCount + handleCount);
            if (needed > vertices.capacity()) {
                reserve(Math.max(groundCount + handleCount, (int) (vertices.capacity() / (2L * GizmoMesh.FLOATS))));
            }
            vertices.orphan();
            vertices.upload(0, mesh.groundPart());
            vertices.upload(4L * GizmoMesh.FLOATS * groundCount, mesh.handlePart());
            program.use();
            glUniformMatrix4fv(uViewProj, false, camera.viewProjection(viewProj).get(matrix));
            vao.bind();
            glEnable(GL_BLEND);
            glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
            glDisable(GL_CULL_FACE);
            glDepthMask(false);
            if (groundCount > 0) {
                glEnable(GL_DEPTH_TEST);
                glDepthFunc(GL_GREATER);
                glUniform1f(uAlpha, HIDDEN_ALPHA);
                glDrawArrays(GL_TRIANGLES, 0, groundCount);
                glDepthFunc(GL_LEQUAL);
                glUniform1f(uAlpha, 1f);
                glDrawArrays(GL_TRIANGLES, 0, groundCount);
            }
            if (handleCount > 0) {
                glDisable(GL_DEPTH_TEST);
                glUniform1f(uAlpha, 1f);
                glDrawArrays(GL_TRIANGLES, groundCount, handleCount);
            }
        } finally {
            state.restore();
        }
    }

    /** {@return triangles drawn by the last {@link #render} (ground section once, handles)} */
    public int triangles() {
        return (mesh.groundVertices() + mesh.handleVertices()) / 3;
    }

    /** Deletes the GL objects and frees the native storage. Render thread; idempotent. */
    @Override
    public void close() {
        if (!closed) {
            closed = true;
            Closing.closeAll(vertices, vao, program, state, mesh);
            MemoryUtil.memFree((java.nio.Buffer) matrix);
        }
    }
}
