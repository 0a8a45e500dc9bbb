package org.jecosys.render;

import static org.lwjgl.opengl.GL11C.glDepthMask;

import org.jecosys.math.Camera;
import org.jecosys.render.ground.CoverBlades;
import org.jecosys.render.ground.CoverSkin;
import org.jecosys.render.ground.ShadowParams;
import org.jecosys.render.ground.SkyRenderer;
import org.jecosys.render.ground.TerrainRenderer;

/**
 * {@link SceneRenderer}'s ground and sky passes: the library's terrain (bare, as it is without the
 * vegetation, when the plants are left out), or, with the settings' terrain off, the ground cover's skin
 * over the host's own ground (made at the first frame that draws it, reading the sun's shadow map); and
 * the sky where nothing is drawn yet, when the settings clear. Owns the skin, closed (or, after its
 * context is gone, forgotten) by {@link #close()}, after which the next frame that draws it makes it
 * again. Render thread; no allocation after the skin is made.
 */
final class GroundPass implements AutoCloseable {
    private final GlContext gl;
    /** The shadow map's per-frame values, shared with the renderer's other parts. */
    private final ShadowParams shadow;
    /** The cover over a host's own ground (terrain off), made at the first frame that draws it. */
    private CoverSkin skin;

    GroundPass(GlContext gl, ShadowParams shadow) {
        this.gl = gl;
        this.shadow = shadow;
    }

    /**
     * The library's terrain, or the cover skin over a host's ground, as the settings ask.
     *
     * @param drawTerrain whether the terrain is drawn at all (the benchmark's breakdown, tests)
     * @param drawPlants  whether the vegetation is drawn: without it the terrain is bare and no skin is laid
     */
    void drawGround(Camera camera, RenderSettings settings, TerrainRenderer terrain, CoverBlades cover,
                    boolean drawTerrain, boolean drawPlants) {
        if (drawTerrain && settings.terrain()) {
            if (drawPlants) {
                terrain.draw(camera, settings);
            } else {
                terrain.drawBare(camera, settings); // the ground as it is without the vegetation
            }
        } else if (drawPlants && !settings.terrain() && settings.coverSkin() && terrain.prepareCover(settings)) {
            if (skin == null) {
                skin = new CoverSkin(gl, terrain, cover);
                skin.useShadowMap(shadow);
            }
            skin.draw(camera, settings); // the cover over the host's own ground
        }
    }

    /** The sky where nothing is drawn yet (depth still 1), when the settings clear; before any blended plants. */
    static void drawSky(SkyRenderer sky, Camera camera, RenderSettings settings) {
        if (settings.clear()) {
            glDepthMask(false);
            sky.draw(camera, settings);
            glDepthMask(true);
        }
    }

    /** Closes the skin, if made, and forgets it. */
    @Override
    public void close() {
        if (skin != null) {
            skin.close();
            skin = null;
        }
    }
}
