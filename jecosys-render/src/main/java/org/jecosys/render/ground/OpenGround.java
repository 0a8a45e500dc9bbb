package org.jecosys.render.ground;

import static org.lwjgl.opengl.GL11C.GL_FLOAT;
import static org.lwjgl.opengl.GL11C.GL_TRIANGLES;
import static org.lwjgl.opengl.GL11C.GL_UNSIGNED_INT;
import static org.lwjgl.opengl.GL11C.glDrawElements;
import static org.lwjgl.opengl.GL15C.GL_ARRAY_BUFFER;
import static org.lwjgl.opengl.GL15C.GL_ELEMENT_ARRAY_BUFFER;
import static org.lwjgl.opengl.GL15C.GL_STATIC_DRAW;
import static org.lwjgl.opengl.GL20C.glEnableVertexAttribArray;
import static org.lwjgl.opengl.GL20C.glUniform2f;
import static org.lwjgl.opengl.GL20C.glUniform3f;
import static org.lwjgl.opengl.GL20C.glUniformMatrix4fv;
import static org.lwjgl.opengl.GL20C.glVertexAttribPointer;
import static org.lwjgl.opengl.GL30C.glBindVertexArray;

import java.nio.FloatBuffer;
import java.nio.IntBuffer;
import org.jecosys.math.Camera;
import org.jecosys.render.GlContext;
import org.jecosys.render.Lighting;
import org.jecosys.render.gl.Closing;
import org.jecosys.render.gl.GlBuffer;
import org.jecosys.render.gl.GlContexts;
import org.jecosys.render.gl.GlProgram;
import org.jecosys.render.gl.GlTracker;
import org.jecosys.render.gl.GlVertexArray;
import org.jecosys.terrain.Heightfield;
import org.joml.Matrix4f;
import org.lwjgl.system.MemoryUtil;

/**
 * An open world's ground, tile by tile: each tile's heightfield as a mesh (positions and normals,
 * uploaded once per tile), lit per vertex by the sun and the sky and hazed with distance like the
 * plants, in one colour (the scene's ground cover, where it has one). Plain next to the library's own
 * terrain: no cover grain, contact darkening, shadows or skirt. Render thread; {@link #mesh} allocates
 * (a tile's mesh), {@link #begin} and {@link Mesh#draw} do not.
 */
public final class OpenGround implements AutoCloseable {
    private final GlTracker tracker;
    private final GlProgram program;
    private final FloatBuffer matrix = MemoryUtil.memAllocFloat(16);
    private final Matrix4f viewProj = new Matrix4f();
    private final int uViewProj;
    private final int uEye;
    private final int uSunDir;
    private final int uSunColour;
    private final int uAmbient;
    private final int uColour;
    private final int uHaze;
    private final int uFog;
    private boolean closed;

    /** One tile's mesh. */
    public static final class Mesh implements AutoCloseable {
        private final GlVertexArray vao;
        private final GlBuffer vertices;
        private final GlBuffer indices;
        private final int count;

        private Mesh(GlVertexArray vao, GlBuffer vertices, GlBuffer indices, int count) {
            this.vao = vao;
            this.vertices = vertices;
            this.indices = indices;
            this.count = count;
        }

        /** Draws the tile, after {@link OpenGround#begin}. Render thread; no allocation. */
        public void draw() {
            vao.bind();
            glDrawElements(GL_TRIANGLES, count, GL_UNSIGNED_INT, 0L);
            glBindVertexArray(0);
        }

        /** Deletes its buffers. Render thread; idempotent. */
        @Override
        public void close() {
            Closing.closeAll(indices, vertices, vao);
        }
    }

    /**
     * Compiles the ground's program. Render thread; allocates.
     *
     * @param gl the render context, current on this thread
     */
    public OpenGround(GlContext gl) {
        gl.checkThread();
        tracker = GlContexts.tracker(gl);
        program = new GlProgram(tracker, "open_ground.vert", "open_ground.frag");
        uViewProj = program.uniform("uViewProj");
        uEye = program.uniform("uEye");
        uSunDir = program.uniform("uSunDir");
        uSunColour = program.uniform("uSunColour");
        uAmbient = program.uniform("uAmbient");
        uColour = program.uniform("uColour");
        uHaze = program.uniform("uHaze");
        uFog = program.uniform("uFog");
    }

    /**
     * Uploads a tile's ground: its heightfield's vertices (world positions) and normals. Render thread;
     * allocates; binds and unbinds a vertex array.
     *
     * @param ground the tile's heightfield
     * @return the mesh; the caller closes it
     */
    public Mesh mesh(Heightfield ground) {
        int res = ground.resolution();
        float[] normals = ground.copyNormals(new float[3 * res * res]);
        FloatBuffer v = MemoryUtil.memAllocFloat(6 * res * res);
        IntBuffer idx = MemoryUtil.memAllocInt(6 * (res - 1) * (res - 1));
        GlVertexArray va = null;
        GlBuffer vb = null;
        GlBuffer ib = null;
        try {
            for (int j = 0; j < res; j++) {
                for (int i = 0; i < res; i++) {
                    int k = j * res + i;
                    v.put((float) (ground.minX() + i * ground.cellX())).put(ground.vertexHeight(i, j))
                            .put((float) (ground.minZ() + j * ground.cellZ()));
                    v.put(normals[3 * k]).put(normals[3 * k + 1]).put(normals[3 * k + 2]);
                }
            }
            for (int j = 0; j < res - 1; j++) {
                for (int i = 0; i < res - 1; i++) {
                    int a = j * res + i;
                    idx.put(a).put(a + res).put(a + 1).put(a + 1).put(a + res).put(a + res + 1);
                }
            }
            v.flip();
            idx.flip();
            va = new GlVertexArray(tracker);
            va.bind();
            vb = GlBuffer.of(tracker, GL_ARRAY_BUFFER, v, GL_STATIC_DRAW);
            ib = GlBuffer.of(tracker, GL_ELEMENT_ARRAY_BUFFER, idx, GL_STATIC_DRAW);
            for (int a = 0; a < 2; a++) {
                glEnableVertexAttribArray(a);
                glVertexAttribPointer(a, 3, GL_FLOAT, false, 24, a * 12L);
            }
            glBindVertexArray(0);
            return new Mesh(va, vb, ib, 6 * (res - 1) * (res - 1));
        } catch (RuntimeException e) {
            glBindVertexArray(0);
            Closing.closeAll(ib, vb, va);
            throw e;
        } finally {
            MemoryUtil.memFree((java.nio.Buffer) v);
            MemoryUtil.memFree((java.nio.Buffer) idx);
        }
    }

    /**
     * Takes the program into use with the frame's camera, light and ground colour (sRGB, 0..1). Render
     * thread; no allocation.
     *
     * @param camera the viewer
     * @param light  sun, ambient, haze colour and fog range
     * @param r      ground colour, red
     * @param g      green
     * @param b      blue
     */
    public void begin(Camera camera, Lighting light, float r, float g, float b) {
        program.use();
        glUniformMatrix4fv(uViewProj, false, camera.viewProjection(viewProj).get(matrix));
        glUniform3f(uEye, (float) camera.x(), (float) camera.y(), (float) camera.z());
        glUniform3f(uSunDir, light.sunX(), light.sunY(), light.sunZ());
        float k = light.sunIntensity();
        glUniform3f(uSunColour, light.sunR() * k, light.sunG() * k, light.sunB() * k);
        glUniform3f(uAmbient, light.ambientR(), light.ambientG(), light.ambientB());
        glUniform3f(uColour, r, g, b);
        glUniform3f(uHaze, light.skyR(), light.skyG(), light.skyB());
        glUniform2f(uFog, light.fogStart(), light.fogEnd());
    }

    /** Deletes the program. Render thread; idempotent. */
    @Override
    public void close() {
        if (!closed) {
            closed = true;
            program.close();
            MemoryUtil.memFree((java.nio.Buffer) matrix);
        }
    }
}
