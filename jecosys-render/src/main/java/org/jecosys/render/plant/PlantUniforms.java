package org.jecosys.render.plant;

import static org.lwjgl.opengl.GL20C.glUniform1f;
import static org.lwjgl.opengl.GL20C.glUniform1i;
import static org.lwjgl.opengl.GL20C.glUniform2f;
import static org.lwjgl.opengl.GL20C.glUniform3f;
import static org.lwjgl.opengl.GL20C.glUniform4f;
import static org.lwjgl.opengl.GL20C.glUniformMatrix4fv;

import java.nio.FloatBuffer;
import org.jecosys.math.Rgb;
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
        sunShadow = p.optionalUniform("uSunShadow");
        shadowMatrix = p.optionalUniform("uShadowMatrix");
        shadowEye = p.optionalUniform("uShadowEye");
        glUniform1i(p.optionalUniform("uShadowMap"), TextureUnits.SUN_SHADOW);
        glUniform1i(p.optionalUniform("uPoses"), TextureUnits.POSES);
        glUniform1i(p.optionalUniform("uComponents"), TextureUnits.RECORDS);
    }

    /**
     * Sets the per-frame values on the program in use: view, eye, light, fog, the pixel's size
     * ({@code pixelX + distance * pixelY} metres), the frame's distance thinning and the least alpha
     * written (1 when not multisampled, so plants are opaque; 0 for alpha-to-coverage). No allocation.
     */
    public void frame(PlantLook r, FloatBuffer viewProjMatrix, float ex, float ey, float ez, Rgb fog, float start,
               float end, float lx, float ly, float lz, float pixelX, float pixelY, Frame frame, float alphaFloorValue) {
        glUniform1f(alphaFloor, alphaFloorValue);
        glUniform2f(pixelScale, pixelX, pixelY);
        glUniform3f(thin, (float) frame.thinStart(), (float) frame.thinEnd(), (float) frame.thinMinFraction());
        glUniformMatrix4fv(viewProj, false, viewProjMatrix);
        glUniform3f(sunColour, r.sunR, r.sunG, r.sunB);
        glUniform3f(ambient, r.ambR, r.ambG, r.ambB);
        glUniform1f(sheen, r.sheen);
        glUniform1f(minPixels, r.minPixels);
        glUniform1f(headPixels, r.headPixels);
        glUniform1f(flowerTilt, r.flowerTilt);
        glUniform3f(lightDir, lx, ly, lz);
        glUniform3f(eye, ex, ey, ez);
        glUniform3f(fogColour, fog.r(), fog.g(), fog.b());
        glUniform1f(fogStart, start);
        glUniform1f(fogEnd, end);
    }

    /** Sets the look's sun shadow map on the program in use ({@code sun_shadow.glsl}). No allocation. */
    public void shadow(PlantLook r) {
        glUniform4f(sunShadow, r.shadow[0], r.shadow[1], r.shadow[2], r.shadow[3]);
        glUniform4f(shadowEye, r.shadowEye[0], r.shadowEye[1], r.shadowEye[2], r.shadowEye[3]);
        if (r.shadowMatrix != null) {
            glUniformMatrix4fv(shadowMatrix, false, r.shadowMatrix);
        }
    }
}
