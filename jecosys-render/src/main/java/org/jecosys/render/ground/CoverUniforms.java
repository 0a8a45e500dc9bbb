package org.jecosys.render.ground;

import org.jecosys.render.Lighting;
import static org.lwjgl.opengl.GL20C.glUniform1f;
import static org.lwjgl.opengl.GL20C.glUniform1i;
import static org.lwjgl.opengl.GL20C.glUniform2f;
import static org.lwjgl.opengl.GL20C.glUniform3f;
import static org.lwjgl.opengl.GL20C.glUniform4f;

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
     * @param beyond    the cover level beyond the terrain's square (the cover map's mean), in [0, 1]
     */
    void set(RenderSettings settings, boolean withCover, boolean withSheen, float beyond) {
        RenderDef.GroundCover gc = settings.groundCover();
        Lighting l = settings.lighting();
        float k = l.sunIntensity();
        glUniform4f(cover, withCover ? (float) gc.amount() : 0f, 1f / GRAIN_TILE, (float) gc.height(), beyond);
        glUniform1f(sheen, withSheen ? settings.sheen() : 0f);
        glUniform3f(sheenLight, 0.35f * l.skyR() * (l.ambientR() + 0.5f * l.sunR() * k),
                0.35f * l.skyG() * (l.ambientG() + 0.5f * l.sunG() * k),
                0.35f * l.skyB() * (l.ambientB() + 0.5f * l.sunB() * k));
        float sl = (float) Math.hypot(l.sunX(), l.sunZ());
        glUniform2f(sunXZ, sl > 1e-6f ? l.sunX() / sl : 0f, sl > 1e-6f ? l.sunZ() / sl : 0f);
    }
}
