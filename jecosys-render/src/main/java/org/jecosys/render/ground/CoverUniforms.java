package org.jecosys.render.ground;

import static org.lwjgl.opengl.GL20C.glUniform1f;
import static org.lwjgl.opengl.GL20C.glUniform1i;
import static org.lwjgl.opengl.GL20C.glUniform2f;
import static org.lwjgl.opengl.GL20C.glUniform3f;
import static org.lwjgl.opengl.GL20C.glUniform4f;

import org.jecosys.math.Rgb;
import org.jecosys.render.RenderSettings;
import org.jecosys.render.gl.GlProgram;
import org.jecosys.render.gl.TextureUnits;
import org.jecosys.scene.RenderDef;

/**
 * The uniforms of {@code ground_cover.glsl} (the cover's look on the ground) that a program takes
 * from the settings: the cover's amount and grain scale ({@code uCover}), the wind's sheen
 * ({@code uSheen}, {@code uSheenLight}, {@code uSunXZ}); the cover's colours come with
 * {@link GroundUniforms}. The terrain's program and the cover skin's set them through this one class,
 * so the two show the same cover. Render thread; {@link #set} allocates nothing.
 */
final class CoverUniforms {
    /** Side of the grain tile on the ground, metres. */
    static final float GRAIN_TILE = 0.7f;

    private final int cover;
    private final int sheen;
    private final int sheenLight;
    private final int sunXZ;

    /** Looks the uniforms up in a program that includes {@code ground_cover.glsl}. Setup time. */
    CoverUniforms(GlProgram program) {
        cover = program.uniform("uCover");
        sheen = program.uniform("uSheen");
        sheenLight = program.uniform("uSheenLight");
        sunXZ = program.uniform("uSunXZ");
    }

    /**
     * Points the program's grain and bend samplers at {@link TextureUnits#COVER_GRAIN} and
     * {@link TextureUnits#TILE_BENDS}; the program is in use. Setup time.
     */
    static void bindSamplers(GlProgram program) {
        glUniform1i(program.uniform("uGrain"), TextureUnits.COVER_GRAIN);
        glUniform1i(program.uniform("uBend"), TextureUnits.TILE_BENDS);
    }

    /**
     * Sets them on the program in use. No allocation.
     *
     * @param settings the cover, the sheen's strength, the light
     * @param withCover whether the cover is drawn (amount 0 otherwise)
     * @param withSheen whether the sheen is drawn (a bend map is bound; strength 0 otherwise)
     */
    void set(RenderSettings settings, boolean withCover, boolean withSheen) {
        RenderDef.GroundCover gc = settings.groundCover();
        Rgb sun = settings.sunColour();
        float k = settings.sunIntensity();
        Rgb amb = settings.ambient();
        Rgb fog = settings.sky();
        glUniform4f(cover, withCover ? (float) gc.amount() : 0f, 1f / GRAIN_TILE, (float) gc.height(), 0f);
        glUniform1f(sheen, withSheen ? settings.sheen() : 0f);
        glUniform3f(sheenLight, 0.35f * fog.r() * (amb.r() + 0.5f * sun.r() * k),
                0.35f * fog.g() * (amb.g() + 0.5f * sun.g() * k), 0.35f * fog.b() * (amb.b() + 0.5f * sun.b() * k));
        float sl = (float) Math.hypot(settings.sunX(), settings.sunZ());
        glUniform2f(sunXZ, sl > 1e-6f ? settings.sunX() / sl : 0f, sl > 1e-6f ? settings.sunZ() / sl : 0f);
    }
}
