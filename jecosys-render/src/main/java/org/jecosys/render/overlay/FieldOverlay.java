package org.jecosys.render.overlay;

import org.jecosys.render.gl.GlContexts;
import org.jecosys.render.gl.Closing;
import static org.lwjgl.opengl.GL11C.GL_BLEND;
import static org.lwjgl.opengl.GL11C.GL_FLOAT;
import static org.lwjgl.opengl.GL11C.GL_LINES;
import static org.lwjgl.opengl.GL11C.GL_ONE_MINUS_SRC_ALPHA;
import static org.lwjgl.opengl.GL11C.GL_SRC_ALPHA;
import static org.lwjgl.opengl.GL11C.GL_TRIANGLES;
import static org.lwjgl.opengl.GL11C.glBlendFunc;
import static org.lwjgl.opengl.GL11C.glDisable;
import static org.lwjgl.opengl.GL11C.glDrawArrays;
import static org.lwjgl.opengl.GL11C.glEnable;
import static org.lwjgl.opengl.GL11C.glViewport;
import static org.lwjgl.opengl.GL15C.GL_ARRAY_BUFFER;
import static org.lwjgl.opengl.GL20C.glEnableVertexAttribArray;
import static org.lwjgl.opengl.GL20C.glUniform4f;
import static org.lwjgl.opengl.GL20C.glVertexAttribPointer;
import static org.lwjgl.opengl.GL30C.glBindVertexArray;

import java.nio.FloatBuffer;
import org.jecosys.field.FieldDebugView;
import org.jecosys.math.Camera;
import org.joml.Vector3f;
import org.jecosys.terrain.Heightfield;
import org.lwjgl.system.MemoryUtil;
import org.jecosys.render.OverlaySettings;
import org.jecosys.render.GlContext;
import org.jecosys.render.gl.GlBuffer;
import org.jecosys.render.gl.GlProgram;
import org.jecosys.render.gl.GlTracker;
import org.jecosys.render.gl.GlVertexArray;

/**
 * The force-field overlays, drawn as a top-down map in the window's top-right corner (north up):
 * the quadtree's leaf cells in grey levels (paper Figure 2: lightest where a leaf carries its own
 * force, one step darker per level its representing ancestor is above it, darkest where invisible),
 * cell outlines, the viewer's position and heading, and the wind vector of every effective node
 * (paper Figure 3). Render thread only; {@link #draw} allocates nothing unless the tree grew past
 * the preallocated capacity.
 */
public final class FieldOverlay implements AutoCloseable {
    private static final int FLOATS = 6;
    private static final int TRI_PER_NODE = 6;
    private static final int LINE_PER_NODE = 8;
    private static final int LINE_PER_WIND = 6;
    private static final int EXTRA = 16;

    private final Vector3f heading = new Vector3f();
    private final GlTracker tracker;
    private final Heightfield terrain;
    private final GlProgram program;
    private final GlVertexArray vao;
    private final int uRect;
    private GlBuffer vertices;
    private FloatBuffer staging;
    private int capacityNodes;
    private boolean closed;

    /**
     * Creates the overlay for a terrain's bounds. Render thread; allocates.
     *
     * @param gl      the render context
     * @param terrain gives the map's extent (metres) and the marker size
     */
    public FieldOverlay(GlContext gl, Heightfield terrain) {
        this.tracker = GlContexts.tracker(gl);
        this.terrain = terrain;
        program = new GlProgram(tracker, "overlay.vert", "overlay.frag");
        uRect = program.uniform("uRect");
        GlVertexArray va = null;
        try {
            va = new GlVertexArray(tracker);
            vao = va;
            reserve(1024);
        } catch (RuntimeException e) {
            MemoryUtil.memFree((java.nio.Buffer) staging);
            Closing.closeAll(va, program);
            throw e;
        }
    }

    private void reserve(int nodes) {
        if (vertices != null) {
            vertices.close();
            MemoryUtil.memFree((java.nio.Buffer) staging);
        }
        capacityNodes = nodes;
        int verts = nodes * (TRI_PER_NODE + LINE_PER_NODE + LINE_PER_WIND) + EXTRA;
        staging = MemoryUtil.memAllocFloat(verts * FLOATS);
        vertices = GlBuffer.dynamic(tracker, GL_ARRAY_BUFFER, 4L * verts * FLOATS);
        vao.bind();
        vertices.bind();
        glEnableVertexAttribArray(0);
        glVertexAttribPointer(0, 2, GL_FLOAT, false, FLOATS * 4, 0L);
        glEnableVertexAttribArray(1);
        glVertexAttribPointer(1, 4, GL_FLOAT, false, FLOATS * 4, 8L);
        glBindVertexArray(0);
    }

    /** Gap between the map and the viewport's top and right edges, pixels. */
    public static final int MAP_MARGIN = 10;

    /**
     * The side of the square map for a viewport: 38% of its smaller side. The map's top-left corner
     * is {@link #MAP_MARGIN} pixels from the viewport's top and right edges, north (-Z) up, so an
     * application can draw a legend and markers around it. Pure; any thread.
     *
     * @param width  viewport width, pixels
     * @param height viewport height, pixels
     * @return the map's side, pixels
     */
    public static int mapSide(int width, int height) {
        return (int) (0.38f * Math.min(width, height));
    }

    /**
     * Grey level of a leaf cell (Figure 2). Pure; any thread.
     *
     * @param visible  whether the leaf passed the frustum test
     * @param lodLevel levels its representing ancestor is above it (0: its own force), -1 when invisible
     * @return 0.85 for its own force, 0.14 darker per level up (at least 0.30), 0.12 when invisible
     */
    public static float grey(boolean visible, int lodLevel) {
        if (!visible || lodLevel < 0) {
            return 0.12f;
        }
        return Math.max(0.30f, 0.85f - 0.14f * lodLevel);
    }

    /**
     * Draws the map in the top-right corner of the viewport {@code (x, y, width, height)}, pixels,
     * and sets that viewport again on return. Render thread.
     *
     * @param view      the field's debug view (read on this thread between field updates)
     * @param camera    the viewer, drawn as a marker pointing along its heading
     * @param shown     which overlays: the quadtree cells, the wind vectors (read, not kept)
     * @param x         viewport left, pixels
     * @param y         viewport bottom, pixels
     * @param width     viewport width, pixels
     * @param height    viewport height, pixels
     */
    public void draw(FieldDebugView view, Camera camera, OverlaySettings shown, int x, int y, int width, int height) {
        boolean showField = shown.showField();
        boolean showWind = shown.showWind();
        int nodes = view.nodeCount();
        if (nodes > capacityNodes) {
            reserve(Math.max(nodes, 2 * capacityNodes));
        }
        FloatBuffer b = staging.clear();
        int tris = 0;
        if (showField) {
            for (int n = 0; n < nodes; n++) {
                if (view.isLeaf(n)) {
                    float g = grey(view.visible(n), view.lodLevel(n));
                    quad(b, view.minX(n), view.minZ(n), view.maxX(n), view.maxZ(n), g, g, g, 1f);
                    tris += 6;
                }
            }
        }
        // viewer marker: a triangle pointing along the view heading
        float ex = (float) camera.x();
        float ez = (float) camera.z();
        float size = (float) Math.max(terrain.sizeX(), terrain.sizeZ()) * 0.025f;
        camera.forward(heading);
        float hl = (float) Math.sqrt(heading.x * heading.x + heading.z * heading.z);
        float fx = hl > 1e-6f ? heading.x / hl : 0f;
        float fz = hl > 1e-6f ? heading.z / hl : -1f;
        vertex(b, ex + fx * size * 1.6f, ez + fz * size * 1.6f, 1f, 0.85f, 0.1f, 1f);
        vertex(b, ex - fz * size * 0.6f, ez + fx * size * 0.6f, 1f, 0.85f, 0.1f, 1f);
        vertex(b, ex + fz * size * 0.6f, ez - fx * size * 0.6f, 1f, 0.85f, 0.1f, 1f);
        tris += 3;
        int lines = 0;
        if (showField) {
            for (int n = 0; n < nodes; n++) {
                if (view.isLeaf(n)) {
                    outline(b, view.minX(n), view.minZ(n), view.maxX(n), view.maxZ(n));
                    lines += 8;
                }
            }
        }
        if (showWind) {
            for (int n = 0; n < nodes; n++) {
                if (view.effective(n)) {
                    lines += arrow(b, view, n);
                }
            }
        }
        b.flip();
        vertices.orphan();
        vertices.upload(0, b);
        int side = mapSide(width, height);
        glViewport(x + width - side - MAP_MARGIN, y + height - side - MAP_MARGIN, side, side);
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        program.use();
        glUniform4f(uRect, (float) terrain.minX(), (float) terrain.minZ(), (float) terrain.sizeX(),
                (float) terrain.sizeZ());
        vao.bind();
        glDrawArrays(GL_TRIANGLES, 0, tris);
        if (lines > 0) {
            glDrawArrays(GL_LINES, tris, lines);
        }
        glBindVertexArray(0);
        glDisable(GL_BLEND);
        glViewport(x, y, width, height);
    }

    private static void quad(FloatBuffer b, float x0, float z0, float x1, float z1, float r, float g, float bl, float a) {
        vertex(b, x0, z0, r, g, bl, a);
        vertex(b, x1, z0, r, g, bl, a);
        vertex(b, x1, z1, r, g, bl, a);
        vertex(b, x0, z0, r, g, bl, a);
        vertex(b, x1, z1, r, g, bl, a);
        vertex(b, x0, z1, r, g, bl, a);
    }

    private static void outline(FloatBuffer b, float x0, float z0, float x1, float z1) {
        float c = 0.05f;
        float a = 0.6f;
        vertex(b, x0, z0, c, c, c, a);
        vertex(b, x1, z0, c, c, c, a);
        vertex(b, x1, z0, c, c, c, a);
        vertex(b, x1, z1, c, c, c, a);
        vertex(b, x1, z1, c, c, c, a);
        vertex(b, x0, z1, c, c, c, a);
        vertex(b, x0, z1, c, c, c, a);
        vertex(b, x0, z0, c, c, c, a);
    }

    private static int arrow(FloatBuffer b, FieldDebugView view, int n) {
        float wx = view.windX(n);
        float wz = view.windZ(n);
        float speed = (float) Math.sqrt(wx * wx + wz * wz);
        if (speed < 1e-4f) {
            return 0;
        }
        float cx = 0.5f * (view.minX(n) + view.maxX(n));
        float cz = 0.5f * (view.minZ(n) + view.maxZ(n));
        float half = 0.5f * Math.min(view.maxX(n) - view.minX(n), view.maxZ(n) - view.minZ(n));
        float len = 0.9f * half * Math.min(1f, speed / 8f);
        float dx = wx / speed;
        float dz = wz / speed;
        float tx = cx + dx * len;
        float tz = cz + dz * len;
        float h = 0.35f * len;
        vertex(b, cx, cz, 0.85f, 0.1f, 0.1f, 1f);
        vertex(b, tx, tz, 0.85f, 0.1f, 0.1f, 1f);
        vertex(b, tx, tz, 0.85f, 0.1f, 0.1f, 1f);
        vertex(b, tx - dx * h - dz * h * 0.6f, tz - dz * h + dx * h * 0.6f, 0.85f, 0.1f, 0.1f, 1f);
        vertex(b, tx, tz, 0.85f, 0.1f, 0.1f, 1f);
        vertex(b, tx - dx * h + dz * h * 0.6f, tz - dz * h - dx * h * 0.6f, 0.85f, 0.1f, 0.1f, 1f);
        return 6;
    }

    private static void vertex(FloatBuffer b, float x, float z, float r, float g, float bl, float a) {
        b.put(x).put(z).put(r).put(g).put(bl).put(a);
    }

    /** Deletes the GL objects. Render thread; idempotent. */
    @Override
    public void close() {
        if (!closed) {
            closed = true;
            Closing.closeAll(vertices, vao, program);
            MemoryUtil.memFree((java.nio.Buffer) staging);
        }
    }
}
