package org.jecosys.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.lwjgl.opengl.GL11C.GL_TEXTURE_2D;
import static org.lwjgl.opengl.GL11C.glBindTexture;
import static org.lwjgl.opengl.GL11C.glDeleteTextures;
import static org.lwjgl.opengl.GL11C.glGenTextures;
import static org.lwjgl.opengl.GL13C.GL_TEXTURE0;
import static org.lwjgl.opengl.GL13C.glActiveTexture;
import static org.lwjgl.opengl.GL15C.GL_ARRAY_BUFFER;
import static org.lwjgl.opengl.GL15C.GL_STATIC_DRAW;
import static org.lwjgl.opengl.GL15C.glBindBuffer;
import static org.lwjgl.opengl.GL15C.glBufferData;
import static org.lwjgl.opengl.GL15C.glDeleteBuffers;
import static org.lwjgl.opengl.GL15C.glGenBuffers;
import static org.lwjgl.opengl.GL20C.glUseProgram;
import static org.lwjgl.opengl.GL30C.glBindVertexArray;
import static org.lwjgl.opengl.GL30C.glDeleteVertexArrays;
import static org.lwjgl.opengl.GL30C.glGenVertexArrays;
import static org.lwjgl.opengl.GL31C.GL_TEXTURE_BUFFER;

import org.jecosys.render.GlContext.DebugOutput;
import java.util.Map;
import org.jecosys.sim.World;
import org.junit.jupiter.api.Test;
import org.jecosys.render.gl.GlProgram;
import org.jecosys.render.gl.TextureUnits;
import org.jecosys.render.gl.GlTracker;
import org.junit.jupiter.api.Tag;

/**
 * Making and closing a renderer in a host's context leaves the host's state as it was, like a frame
 * does ({@link HostCompositionTest}): engines cache their bindings (jMonkeyEngine binds the one vertex
 * array of its core profile once and never again, and skips binding a program or texture it believes
 * bound), so a vertex array, program or texture changed under them breaks every later draw.
 */
@Tag("lwjgl-compat")
class GuestLifecycleTest {
    @Test
    void constructingAndClosingPutBackTheHostsBindings() {
        World world = RenderScenes.build(RenderScenes.load("c1.xml"));
        try (GlContext owner = GlContext.headless(DebugOutput.ON)) {
            GlContext gl = GlContext.current(DebugOutput.OFF);
            GlProgram hostProgram = new GlProgram(new GlTracker(), "overlay.vert", "overlay.frag");
            int vao = glGenVertexArrays();
            int vbo = glGenBuffers();
            int[] textures = {glGenTextures(), glGenTextures()};
            try {
                glBindVertexArray(vao);
                glBindBuffer(GL_ARRAY_BUFFER, vbo);
                glBufferData(GL_ARRAY_BUFFER, 64, GL_STATIC_DRAW);
                hostProgram.use();
                glActiveTexture(GL_TEXTURE0 + TextureUnits.GROUND_MAPS);
                glBindTexture(GL_TEXTURE_2D, textures[0]);
                glActiveTexture(GL_TEXTURE0);
                glBindTexture(GL_TEXTURE_BUFFER, textures[1]);
                glActiveTexture(GL_TEXTURE0 + 2);
                Map<String, String> host = HostCompositionTest.census();
                SceneRenderer renderer = new SceneRenderer(gl, world, RenderSettings.standalone());
                assertEquals(host, HostCompositionTest.census(), "after the constructor");
                renderer.close();
                assertEquals(host, HostCompositionTest.census(), "after close()");
            } finally {
                glUseProgram(0);
                glBindVertexArray(0);
                hostProgram.close();
                glDeleteVertexArrays(vao);
                glDeleteBuffers(vbo);
                glDeleteTextures(textures);
                gl.close();
                owner.debug().check("the guest lifecycle test");
            }
        }
    }
}
