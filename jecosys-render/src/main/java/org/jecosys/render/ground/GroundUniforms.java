package org.jecosys.render.ground;

import org.jecosys.render.Lighting;
import static org.lwjgl.opengl.GL20C.glUniform1f;
import static org.lwjgl.opengl.GL20C.glUniform1i;
import static org.lwjgl.opengl.GL20C.glUniform3f;

import org.jecosys.render.RenderSettings;
import org.jecosys.render.gl.GlProgram;
import org.jecosys.render.gl.TextureUnits;
import org.jecosys.scene.RenderDef;

/**
 * The uniforms the ground's two programs (the terrain's and the cover blades') take alike from the
 * settings: the sun's direction and colour, the sky's ambient light, the haze, the healthy/dry patches,
 * the contact shadow and the ground cover's colours ({@code uLightDir}, {@code uSunColour},
 * {@code uAmbient}, {@code uFogColour}, {@code uFogStart}, {@code uFogEnd}, {@code uPatch},
 * {@code uPatchSeed}, {@code uContactShadow}, {@code uCoverColour}, {@code uCoverDry}), and the sun's
 * shadow map of the frame ({@code uShadowMap}, {@code uSunShadow}, {@code uShadowMatrix}). Render thread;
 * {@link #set} allocates nothing.
 */
final class GroundUniforms {
    private final int lightDir;
    private final int sunColour;
    private final int ambient;
    private final int fogColour;
    private final int fogStart;
    private final int fogEnd;
    private final int patch;
    private final int patchSeed;
    private final int contactShadow;
    private final int coverColour;
    private final int coverDry;
    private final int sunShadow;
    private final int shadowMatrix;
    private final int shadowEye;

    /** Looks the uniforms up in a program that has them all. Setup time. */
    GroundUniforms(GlProgram program) {
        lightDir = program.uniform("uLightDir");
        sunColour = program.uniform("uSunColour");
        ambient = program.uniform("uAmbient");
        fogColour = program.uniform("uFogColour");
        fogStart = program.uniform("uFogStart");
        fogEnd = program.uniform("uFogEnd");
        patch = program.uniform("uPatch");
        patchSeed = program.uniform("uPatchSeed");
        contactShadow = program.uniform("uContactShadow");
        coverColour = program.uniform("uCoverColour");
        coverDry = program.uniform("uCoverDry");
        sunShadow = program.uniform("uSunShadow");
        shadowMatrix = program.uniform("uShadowMatrix");
        shadowEye = program.uniform("uShadowEye");
    }

    /** Points the program's shadow-map sampler at {@link TextureUnits#SUN_SHADOW}; the program is in use. */
    static void bindShadowSampler(GlProgram program) {
        glUniform1i(program.uniform("uShadowMap"), TextureUnits.SUN_SHADOW);
    }

    /** Sets the sun's shadow map on the program in use ({@code sun_shadow.glsl}). No allocation. */
    void setShadowMap(ShadowParams params) {
        params.upload(sunShadow, shadowEye, shadowMatrix);
    }

    /** Sets them from the settings on the program in use. No allocation. */
    void set(RenderSettings settings) {
        Lighting l = settings.lighting();
        glUniform3f(lightDir, l.sunX(), l.sunY(), l.sunZ());
        float k = l.sunIntensity();
        glUniform3f(sunColour, l.sunR() * k, l.sunG() * k, l.sunB() * k);
        glUniform3f(ambient, l.ambientR(), l.ambientG(), l.ambientB());
        glUniform3f(fogColour, l.skyR(), l.skyG(), l.skyB());
        glUniform1f(fogStart, l.fogStart());
        glUniform1f(fogEnd, l.fogEnd());
        glUniform3f(patch, 1 / settings.patchScale(), settings.patchStrength(), settings.patchStrength() > 0 ? 1 : 0);
        glUniform1i(patchSeed, settings.patchSeed());
        glUniform1f(contactShadow, settings.contactShadow());
        RenderDef.GroundCover gc = settings.groundCover();
        glUniform3f(coverColour, gc.colour().r(), gc.colour().g(), gc.colour().b());
        glUniform3f(coverDry, gc.dryColour().r(), gc.dryColour().g(), gc.dryColour().b());
    }
}
