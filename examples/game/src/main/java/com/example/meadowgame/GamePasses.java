package com.example.meadowgame;

import static org.lwjgl.opengl.GL11C.GL_FLOAT;
import static org.lwjgl.opengl.GL11C.GL_TRIANGLES;
import static org.lwjgl.opengl.GL11C.GL_UNSIGNED_INT;
import static org.lwjgl.opengl.GL11C.glDrawArrays;
import static org.lwjgl.opengl.GL11C.glDrawElements;
import static org.lwjgl.opengl.GL15C.GL_ARRAY_BUFFER;
import static org.lwjgl.opengl.GL15C.GL_ELEMENT_ARRAY_BUFFER;
import static org.lwjgl.opengl.GL15C.GL_STATIC_DRAW;
import static org.lwjgl.opengl.GL15C.glBindBuffer;
import static org.lwjgl.opengl.GL15C.glBufferData;
import static org.lwjgl.opengl.GL15C.glDeleteBuffers;
import static org.lwjgl.opengl.GL15C.glGenBuffers;
import static org.lwjgl.opengl.GL20C.glDeleteProgram;
import static org.lwjgl.opengl.GL20C.glEnableVertexAttribArray;
import static org.lwjgl.opengl.GL20C.glGetUniformLocation;
import static org.lwjgl.opengl.GL20C.glUniform4f;
import static org.lwjgl.opengl.GL20C.glUniformMatrix4fv;
import static org.lwjgl.opengl.GL20C.glUseProgram;
import static org.lwjgl.opengl.GL20C.glVertexAttribPointer;
import static org.lwjgl.opengl.GL30C.glBindVertexArray;
import static org.lwjgl.opengl.GL30C.glDeleteVertexArrays;
import static org.lwjgl.opengl.GL30C.glGenVertexArrays;

import org.jecosys.terrain.Heightfield;
import org.joml.Matrix4f;
import org.joml.Vector3f;

/**
 * The game's own drawing: a gradient sky, a ground mesh made from the scene's heightfield, and a HUD
 * rectangle. Nothing here uses the library's renderer; only the heightfield's public heights.
 */
final class GamePasses implements AutoCloseable {
    /** The HUD bar's colour, RGB in [0, 1]: a test looks for it. */
    static final float[] HUD = {240f / 255, 200f / 255, 24f / 255};
    /** Sky colour at the top and at the horizon. */
    static final float[] SKY_TOP = {0.20f, 0.35f, 0.80f};
    static final float[] SKY_HORIZON = {0.85f, 0.80f, 0.70f};

    private static final String SKY_VS = "#version 330 core\n"
            + "out float vY;\n"
            + "void main() {\n"
            + "  vec2 p = vec2(float((gl_VertexID & 1) * 4 - 1), float((gl_VertexID & 2) * 2 - 1));\n"
            + "  vY = p.y * 0.5 + 0.5;\n"
            + "  gl_Position = vec4(p, 0.0, 1.0);\n"
            + "}\n";
    private static final String SKY_FS = "#version 330 core\n"
            + "in float vY;\n"
            + "uniform vec4 uTop;\n"
            + "uniform vec4 uHorizon;\n"
            + "out vec4 colour;\n"
            + "void main() { colour = mix(uHorizon, uTop, clamp(vY, 0.0, 1.0)); }\n";
    private static final String GROUND_VS = "#version 330 core\n"
            + "layout(location = 0) in vec3 aPos;\n"
            + "layout(location = 1) in vec3 aNormal;\n"
            + "uniform mat4 uViewProj;\n"
            + "out float vLight;\n"
            + "void main() {\n"
            + "  vLight = 0.35 + 0.65 * max(dot(normalize(aNormal), normalize(vec3(-0.4, 0.8, 0.4))), 0.0);\n"
            + "  gl_Position = uViewProj * vec4(aPos, 1.0);\n"
            + "}\n";
    private static final String GROUND_FS = "#version 330 core\n"
            + "in float vLight;\n"
            + "uniform vec4 uColour;\n"
            + "out vec4 colour;\n"
            + "void main() { colour = vec4(uColour.rgb * vLight, 1.0); }\n";
    private static final String HUD_VS = "#version 330 core\n"
            + "uniform vec4 uRect;\n"
            + "void main() {\n"
            + "  vec2 c = vec2(float(gl_VertexID & 1), float((gl_VertexID >> 1) & 1));\n"
            + "  gl_Position = vec4(uRect.xy + c * uRect.zw, 0.0, 1.0);\n"
            + "}\n";
    private static final String HUD_FS = "#version 330 core\n"
            + "uniform vec4 uColour;\n"
            + "out vec4 colour;\n"
            + "void main() { colour = uColour; }\n";

    private final int skyProgram = GameGl.program(SKY_VS, SKY_FS);
    private final int groundProgram = GameGl.program(GROUND_VS, GROUND_FS);
    private final int hudProgram = GameGl.program(HUD_VS, HUD_FS);
    private final int emptyVao = glGenVertexArrays();
    private final int groundVao = glGenVertexArrays();
    private final int groundVertices = glGenBuffers();
    private final int groundIndices = glGenBuffers();
    private final int groundIndexCount;
    private final float[] matrix = new float[16];

    /**
     * Uploads the ground mesh: {@code cells x cells} quads over the heightfield. Game thread with the
     * context current.
     */
    GamePasses(Heightfield terrain, int cells) {
        int n = cells + 1;
        float[] v = new float[n * n * 6];
        Vector3f normal = new Vector3f();
        for (int j = 0; j < n; j++) {
            for (int i = 0; i < n; i++) {
                double x = terrain.minX() + terrain.sizeX() * i / cells;
                double z = terrain.minZ() + terrain.sizeZ() * j / cells;
                terrain.normal(x, z, normal);
                int o = 6 * (j * n + i);
                v[o] = (float) x;
                // a centimetre low, so the plants' bases never dip under the game's coarser mesh
                v[o + 1] = (float) terrain.height(x, z) - 0.01f;
                v[o + 2] = (float) z;
                v[o + 3] = normal.x;
                v[o + 4] = normal.y;
                v[o + 5] = normal.z;
            }
        }
        int[] idx = new int[cells * cells * 6];
        int k = 0;
        for (int j = 0; j < cells; j++) {
            for (int i = 0; i < cells; i++) {
                int a = j * n + i;
                idx[k++] = a;
                idx[k++] = a + n;
                idx[k++] = a + 1;
                idx[k++] = a + 1;
                idx[k++] = a + n;
                idx[k++] = a + n + 1;
            }
        }
        groundIndexCount = idx.length;
        glBindVertexArray(groundVao);
        glBindBuffer(GL_ARRAY_BUFFER, groundVertices);
        glBufferData(GL_ARRAY_BUFFER, v, GL_STATIC_DRAW);
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, groundIndices);
        glBufferData(GL_ELEMENT_ARRAY_BUFFER, idx, GL_STATIC_DRAW);
        glEnableVertexAttribArray(0);
        glVertexAttribPointer(0, 3, GL_FLOAT, false, 24, 0L);
        glEnableVertexAttribArray(1);
        glVertexAttribPointer(1, 3, GL_FLOAT, false, 24, 12L);
        glBindVertexArray(0);
    }

    /** Full-screen gradient; call with depth test off. */
    void sky() {
        glUseProgram(skyProgram);
        glUniform4f(glGetUniformLocation(skyProgram, "uTop"), SKY_TOP[0], SKY_TOP[1], SKY_TOP[2], 1f);
        glUniform4f(glGetUniformLocation(skyProgram, "uHorizon"), SKY_HORIZON[0], SKY_HORIZON[1], SKY_HORIZON[2],
                1f);
        glBindVertexArray(emptyVao);
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }

    /** The ground mesh, depth tested and written. */
    void ground(Matrix4f viewProjection) {
        glUseProgram(groundProgram);
        glUniformMatrix4fv(glGetUniformLocation(groundProgram, "uViewProj"), false, viewProjection.get(matrix));
        glUniform4f(glGetUniformLocation(groundProgram, "uColour"), 0.45f, 0.36f, 0.24f, 1f);
        glBindVertexArray(groundVao);
        glDrawElements(GL_TRIANGLES, groundIndexCount, GL_UNSIGNED_INT, 0L);
    }

    /** A HUD bar in the top-left corner, in normalised device coordinates; call with depth test off. */
    void hud(float fill) {
        glUseProgram(hudProgram);
        glUniform4f(glGetUniformLocation(hudProgram, "uRect"), -0.95f, 0.85f, 0.6f * fill, 0.08f);
        glUniform4f(glGetUniformLocation(hudProgram, "uColour"), HUD[0], HUD[1], HUD[2], 1f);
        glBindVertexArray(emptyVao);
        glDrawArrays(org.lwjgl.opengl.GL11C.GL_TRIANGLE_STRIP, 0, 4);
    }

    @Override
    public void close() {
        glUseProgram(0);
        glBindVertexArray(0);
        glDeleteProgram(skyProgram);
        glDeleteProgram(groundProgram);
        glDeleteProgram(hudProgram);
        glDeleteVertexArrays(emptyVao);
        glDeleteVertexArrays(groundVao);
        glDeleteBuffers(groundVertices);
        glDeleteBuffers(groundIndices);
    }
}
