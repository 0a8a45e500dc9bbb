package org.jecosys.render;

import static org.lwjgl.opengl.GL11C.GL_BLEND;
import static org.lwjgl.opengl.GL11C.GL_COLOR_BUFFER_BIT;
import static org.lwjgl.opengl.GL11C.GL_CULL_FACE;
import static org.lwjgl.opengl.GL11C.GL_DEPTH_BUFFER_BIT;
import static org.lwjgl.opengl.GL11C.GL_DEPTH_TEST;
import static org.lwjgl.opengl.GL11C.GL_LEQUAL;
import static org.lwjgl.opengl.GL11C.GL_SCISSOR_TEST;
import static org.lwjgl.opengl.GL11C.glClear;
import static org.lwjgl.opengl.GL11C.glClearColor;
import static org.lwjgl.opengl.GL11C.glDepthFunc;
import static org.lwjgl.opengl.GL11C.glDepthMask;
import static org.lwjgl.opengl.GL11C.glDisable;
import static org.lwjgl.opengl.GL11C.glEnable;
import static org.lwjgl.opengl.GL11C.glScissor;

/** The start of a frame that {@link SceneRenderer} and {@link OpenWorldRenderer} share. */
final class FrameStart {
    private FrameStart() {
    }

    /**
     * The start of a frame of the library's drawing, after the guest state is set: with the settings'
     * clear on, the viewport's rectangle cleared to the horizon colour and depth 1 (a scissored clear);
     * then depth tested and written ({@code GL_LEQUAL}), no culling, no blending. Render thread.
     */
    static void begin(RenderSettings settings, int vx, int vy, int width, int height) {
        if (settings.clear()) {
            Lighting light = settings.lighting();
            glEnable(GL_SCISSOR_TEST);
            glScissor(vx, vy, width, height);
            glClearColor(light.skyR(), light.skyG(), light.skyB(), 1f);
            glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
            glDisable(GL_SCISSOR_TEST);
        }
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LEQUAL);
        glDepthMask(true);
        glDisable(GL_CULL_FACE);
        glDisable(GL_BLEND);
    }
}
