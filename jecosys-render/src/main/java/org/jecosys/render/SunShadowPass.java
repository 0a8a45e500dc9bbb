package org.jecosys.render;

import static org.lwjgl.opengl.GL11C.GL_POLYGON_OFFSET_FILL;
import static org.lwjgl.opengl.GL11C.GL_SCISSOR_TEST;
import static org.lwjgl.opengl.GL11C.glDisable;
import static org.lwjgl.opengl.GL11C.glEnable;
import static org.lwjgl.opengl.GL11C.glIsEnabled;
import static org.lwjgl.opengl.GL11C.glPolygonOffset;
import static org.lwjgl.opengl.GL11C.glViewport;

import org.jecosys.math.Camera;
import org.jecosys.render.ground.ShadowParams;
import org.jecosys.render.ground.SunShadowMap;
import org.jecosys.render.plant.PlantRenderer;

/**
 * {@link SceneRenderer}'s sun shadow map pass ({@link ShadowPath#MAP}): the plants resolved for the frame
 * drawn from the sun into the map (made at the first frame that draws it), fitted to the camera, bound
 * for the plants, the cover and the terrain, with the shaders' shadow parameters set. Render thread;
 * no allocation after the first pass.
 */
final class SunShadowPass implements AutoCloseable {
    private final GlContext gl;
    private final ShadowParams shadow;
    private SunShadowMap map;

    SunShadowPass(GlContext gl, ShadowParams shadow) {
        this.gl = gl;
        this.shadow = shadow;
    }

    /**
     * Draws the map. Puts back the host's framebuffer and scissor test, and this frame's viewport.
     *
     * @param reach how far from the camera plants cast into the map, metres
     */
    void draw(PlantRenderer plants, RenderSettings settings, double reach, Camera camera, float lx, float ly,
              float lz, int vx, int vy, int width, int height) {
        if (map == null) {
            map = new SunShadowMap(gl.tracker(), SunShadowMap.DEFAULT_SIZE);
            shadow.setMatrix(map.placement().shadowMatrix());
        }
        map.fit(camera, lx, ly, lz, reach);
        // a host's scissor box clips what the library draws into the host's picture, not the map
        boolean scissor = glIsEnabled(GL_SCISSOR_TEST);
        glDisable(GL_SCISSOR_TEST);
        map.map().begin();
        // slope-scaled offset: a blade seen edge-on from the sun does not shade itself by rounding
        glEnable(GL_POLYGON_OFFSET_FILL);
        glPolygonOffset(2f, 4f);
        plants.drawCasters(map);
        glPolygonOffset(0f, 0f);
        glDisable(GL_POLYGON_OFFSET_FILL);
        map.map().end();
        if (scissor) {
            glEnable(GL_SCISSOR_TEST);
        }
        glViewport(vx, vy, width, height);
        map.map().bind(org.jecosys.render.gl.TextureUnits.SUN_SHADOW);
        shadow.set(1f / map.map().size(), (float) map.placement().bias(), settings.shadows(),
                (float) camera.x(), (float) camera.y(), (float) camera.z(), (float) reach);
    }

    /** Deletes the map (it is made again at the next pass). Render thread; idempotent. */
    @Override
    public void close() {
        if (map != null) {
            map.close();
            map = null;
        }
    }
}
