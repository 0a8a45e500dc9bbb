package org.jecosys.gdx;

import com.badlogic.gdx.graphics.Camera;
import com.badlogic.gdx.graphics.Color;
import com.badlogic.gdx.graphics.g3d.Environment;
import com.badlogic.gdx.graphics.g3d.attributes.ColorAttribute;
import com.badlogic.gdx.graphics.g3d.attributes.DirectionalLightsAttribute;
import com.badlogic.gdx.graphics.g3d.environment.DirectionalLight;
import com.badlogic.gdx.math.Vector3;
import org.jecosys.render.Lighting;

/**
 * A libGDX {@link Environment} as the plants' light, the way libGDX's {@code DefaultShader} lights and
 * fogs the game's models: the first directional light is the sun (its colour at intensity 1, the
 * opposite of its direction toward the sun), the ambient light ({@code ColorAttribute.AmbientLight})
 * the sky light, and the fog colour ({@code ColorAttribute.Fog}) the haze, which grows as the
 * square of the distance and is full at {@code camera.far / 1.09} (the shader's
 * {@code 1.1881 / far²}). What the environment lacks, the plants lack too, as the models do: no
 * directional light, no sun; no ambient light, none; no fog attribute, no haze. The sky colour stays
 * as it was when there is no fog. Render thread; no allocation.
 */
final class GdxLights {
    /** libGDX's {@code DefaultShader}: the fog factor is {@code distance² x 1.1881 / far²}. */
    static final float FOG_FACTOR = 1.1881f;

    private GdxLights() {
    }

    /**
     * Writes the environment's light into {@code out}.
     *
     * @param environment the game's environment, as given to {@code ModelBatch.render}
     * @param camera      the camera drawn with (its far distance sets the fog's reach)
     * @param out         the plants' lighting
     */
    static void apply(Environment environment, Camera camera, Lighting out) {
        DirectionalLightsAttribute dl = environment.has(DirectionalLightsAttribute.Type)
                ? environment.get(DirectionalLightsAttribute.class, DirectionalLightsAttribute.Type) : null;
        if (dl != null && dl.lights.size > 0) {
            DirectionalLight sun = dl.lights.first();
            Vector3 d = sun.direction;
            if (d.len2() > 1e-12f) {
                out.setSunDirection(-d.x, -d.y, -d.z);
            }
            out.setSunColour(light(sun.color.r), light(sun.color.g), light(sun.color.b));
            out.setSunIntensity(1f);
        } else {
            out.setSunIntensity(0f);
        }
        if (environment.has(ColorAttribute.AmbientLight)) {
            Color a = environment.get(ColorAttribute.class, ColorAttribute.AmbientLight).color;
            out.setAmbient(light(a.r), light(a.g), light(a.b));
        } else {
            out.setAmbient(0f, 0f, 0f);
        }
        if (environment.has(ColorAttribute.Fog)) {
            Color f = environment.get(ColorAttribute.class, ColorAttribute.Fog).color;
            out.setSky(unit(f.r), unit(f.g), unit(f.b));
            out.setFog(0f, camera.far / (float) Math.sqrt(FOG_FACTOR));
        } else {
            out.setNoFog();
        }
    }

    private static float light(float v) {
        return Math.max(0f, Math.min(Lighting.MAX_LIGHT, v));
    }

    private static float unit(float v) {
        return Math.max(0f, Math.min(1f, v));
    }
}
