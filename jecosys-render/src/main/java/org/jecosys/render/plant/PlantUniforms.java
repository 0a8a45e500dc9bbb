package org.jecosys.render.plant;

import static org.lwjgl.opengl.GL20C.glUniform1f;
import static org.lwjgl.opengl.GL20C.glUniform1i;
import static org.lwjgl.opengl.GL20C.glUniform2f;
import static org.lwjgl.opengl.GL20C.glUniform3f;
import static org.lwjgl.opengl.GL20C.glUniform4f;
import static org.lwjgl.opengl.GL20C.glUniformMatrix4fv;

import org.jecosys.sim.Frame;
import org.jecosys.render.gl.GlProgram;
import org.jecosys.render.gl.TextureUnits;

/**
 * The per-frame uniforms of the triangle, line and resolve programs (each has some of them: a
 * missing one is set at location -1, which GL ignores); the constructor binds the samplers (pose
 * tables, component records, the sun's shadow map: {@link TextureUnits}) and leaves the program in
 * use. Render thread.
 */
public final class PlantUniforms {
    /**
     * The soft edge of blades and stems on a target without samples, pixels: each ribbon grows by half
     * of it on both sides and fades over it (the near plants are blended there), so a thin part steps
     * from pixel to pixel no more than under multisampling.
     */
    public static final float FEATHER = 0.5f;
    public final GlProgram program;
    public final int viewProj;
    public final int eye;
    public final int slotCount;
    public final int componentBase;
    public final int fogColour;
    public final int fogStart;
    public final int fogEnd;
    public final int lightDir;
    public final int sunColour;
    public final int ambient;
    public final int pixelScale;
    public final int dryTips;
    public final int minPixels;
    public final int headPixels;
    public final int flowerTilt;
    public final int thin;
    public final int sheen;
    public final int alphaFloor;
    /** The core's pass: alpha cut to 0 or 1 at this ({@code uCoreCut}; 0: off). */
    public final int coreCut;
    /** The soft edge of blades and stems, pixels ({@code uFeather}). */
    public final int feather;
    /** Which part a split program keeps: 1 the opaque core, 2 the fringe ({@code uSplit}). */
    public final int split;
    public final int sunShadow;
    public final int shadowMatrix;
    public final int shadowEye;

    public PlantUniforms(GlProgram p) {
        program = p;
        p.use();
        viewProj = p.optionalUniform("uViewProj");
        eye = p.optionalUniform("uEye");
        slotCount = p.optionalUniform("uSlotCount");
        componentBase = p.optionalUniform("uComponentBase");
        fogColour = p.optionalUniform("uFogColour");
        fogStart = p.optionalUniform("uFogStart");
        fogEnd = p.optionalUniform("uFogEnd");
        lightDir = p.optionalUniform("uLightDir");
        sunColour = p.optionalUniform("uSunColour");
        ambient = p.optionalUniform("uAmbient");
        pixelScale = p.optionalUniform("uPixelScale");
        dryTips = p.optionalUniform("uDryTips");
        minPixels = p.optionalUniform("uMinPixels");
        headPixels = p.optionalUniform("uHeadPixels");
        flowerTilt = p.optionalUniform("uFlowerTilt");
        thin = p.optionalUniform("uThin");
        sheen = p.optionalUniform("uSheen");
        alphaFloor = p.optionalUniform("uAlphaFloor");
        feather = p.optionalUniform("uFeather");
        coreCut = p.optionalUniform("uCoreCut");
        split = p.optionalUniform("uSplit");
        sunShadow = p.optionalUniform("uSunShadow");
        shadowMatrix = p.optionalUniform("uShadowMatrix");
        shadowEye = p.optionalUniform("uShadowEye");
        glUniform1i(p.optionalUniform("uShadowMap"), TextureUnits.SUN_SHADOW);
        glUniform1i(p.optionalUniform("uPoses"), TextureUnits.POSES);
        glUniform1i(p.optionalUniform("uComponents"), TextureUnits.RECORDS);
        glUniform1i(p.optionalUniform("uPlantTextures"), TextureUnits.PLANT_TEXTURES);
    }

    /**
     * Sets the per-frame values on the program in use: view, eye, light, fog, the pixel's size
     * ({@code pixelX + distance * pixelY} metres) and the frame's distance thinning from the context,
     * the look's light, and the least alpha written (0: the coverage in alpha, for blending or
     * alpha-to-coverage). No allocation.
     */
    void frame(PlantLook r, PassContext c, float alphaFloorValue) {
        glUniform1f(alphaFloor, alphaFloorValue);
        glUniform1f(feather, c.multisampled ? 0f : FEATHER);
        glUniform2f(pixelScale, c.pixelX, c.pixelY);
        Frame frame = c.frame;
        glUniform3f(thin, (float) frame.thinStart(), (float) frame.thinEnd(), (float) frame.thinMinFraction());
        glUniformMatrix4fv(viewProj, false, c.viewProj);
        glUniform3f(sunColour, r.sunR, r.sunG, r.sunB);
        glUniform3f(ambient, r.ambR, r.ambG, r.ambB);
        glUniform1f(sheen, r.sheen);
        glUniform1f(minPixels, r.minPixels);
        glUniform1f(headPixels, r.headPixels * c.headScale);
        glUniform1f(flowerTilt, r.flowerTilt);
        glUniform3f(lightDir, c.lightX, c.lightY, c.lightZ);
        glUniform3f(eye, c.eyeX, c.eyeY, c.eyeZ);
        glUniform3f(fogColour, c.fogR, c.fogG, c.fogB);
        glUniform1f(fogStart, c.fogStart);
        glUniform1f(fogEnd, c.fogEnd);
    }

    /** Sets the look's sun shadow map on the program in use ({@code sun_shadow.glsl}). No allocation. */
    public void shadow(PlantLook r) {
        r.shadow.upload(sunShadow, shadowEye, shadowMatrix);
    }
}
