package org.jecosys.jme;

import com.jme3.light.AmbientLight;
import com.jme3.light.DirectionalLight;
import com.jme3.light.Light;
import com.jme3.light.LightList;
import com.jme3.math.ColorRGBA;
import com.jme3.math.Vector3f;
import com.jme3.scene.Spatial;
import org.jecosys.render.Lighting;

/**
 * The lights a jME node holds (typically the root node, where games add their sun and ambient light)
 * as the plants' light: the first enabled {@link DirectionalLight} is the sun (its colour at intensity
 * 1; toward the sun is the opposite of its direction), the enabled {@link AmbientLight}s together the
 * sky light. A node with a light of one kind and not the other gives the plants none of the missing
 * kind, as jME's lit materials get none; a node with no light at all leaves the sun and ambient light
 * as they were (a game of unshaded materials keeps the scene's own). The haze is always off: jME fogs with a
 * {@code FogFilter}, a post-process that fogs the plants with the rest of the picture (they are drawn
 * before the viewport's filters). With gamma correction on, jME's light colours are linear: they are
 * encoded to display values (sRGB), in which the plants are lit. Render thread; no allocation.
 */
final class JmeLights {
    private JmeLights() {
    }

    /**
     * Writes the node's lights into {@code out}.
     *
     * @param node  the node whose own lights light the plants
     * @param gamma whether jME's gamma correction is on (light colours are linear)
     * @param out   the plants' lighting
     * @return whether the node had a light (false: {@code out}'s sun and ambient light left as they were)
     */
    static boolean apply(Spatial node, boolean gamma, Lighting out) {
        LightList lights = node.getLocalLightList();
        DirectionalLight sun = null;
        float ar = 0;
        float ag = 0;
        float ab = 0;
        boolean ambient = false;
        for (int i = 0; i < lights.size(); i++) {
            Light l = lights.get(i);
            if (!l.isEnabled()) {
                continue;
            }
            if (l instanceof DirectionalLight d && sun == null) {
                sun = d;
            } else if (l instanceof AmbientLight) {
                ColorRGBA c = l.getColor();
                ar += c.r;
                ag += c.g;
                ab += c.b;
                ambient = true;
            }
        }
        if (sun == null && !ambient) {
            out.setNoFog();
            return false;
        }
        if (sun != null) {
            Vector3f d = sun.getDirection();
            if (d.lengthSquared() > 1e-12f) {
                out.setSunDirection(-d.x, -d.y, -d.z);
            }
            ColorRGBA c = sun.getColor();
            out.setSunColour(display(c.r, gamma), display(c.g, gamma), display(c.b, gamma));
            out.setSunIntensity(1f);
        } else {
            out.setSunIntensity(0f);
        }
        out.setAmbient(display(ar, gamma), display(ag, gamma), display(ab, gamma));
        out.setNoFog();
        return true;
    }

    /** A light channel as the renderer takes it: sRGB-encoded when jME works in linear space, within [0, 4]. */
    static float display(float v, boolean gamma) {
        float x = Math.max(0f, v);
        if (gamma) {
            x = x <= 0.0031308f ? 12.92f * x : (float) (1.055 * Math.pow(x, 1 / 2.4) - 0.055);
        }
        return Math.min(Lighting.MAX_LIGHT, x);
    }
}
