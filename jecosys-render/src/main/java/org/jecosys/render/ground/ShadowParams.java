package org.jecosys.render.ground;

import static org.lwjgl.opengl.GL20C.glUniform4f;
import static org.lwjgl.opengl.GL20C.glUniformMatrix4fv;

import java.nio.FloatBuffer;

/**
 * The sun's shadow map of a frame as the receivers' shaders read it ({@code sun_shadow.glsl}):
 * {@code uSunShadow} (whether a map is drawn this frame, one texel in map coordinates, the depth bias,
 * the shadows' strength), {@code uShadowEye} (the eye and the map's reach, metres) and
 * {@code uShadowMatrix} (world to map). One object per scene renderer, made once and shared with the
 * plants, the terrain and the ground cover, which read it at every draw; the renderer fills it each
 * frame ({@link #clear}, then {@link #set} when it draws the map). Render thread; no allocation.
 */
public final class ShadowParams {
    private boolean drawn;
    private float texel;
    private float bias;
    private float strength;
    private float eyeX;
    private float eyeY;
    private float eyeZ;
    private float reach;
    private FloatBuffer matrix;

    /** No map: every receiver draws without one until {@link #set}. */
    public ShadowParams() {
    }

    /** Marks that no map is drawn this frame (the other values stay, unread). No allocation. */
    public void clear() {
        drawn = false;
    }

    /**
     * Marks that the map is drawn this frame, with its values. No allocation.
     *
     * @param texel    one texel of the map in map coordinates (1 / its size)
     * @param bias     the depth bias, in map depth units
     * @param strength the shadows' strength, in [0, 1]
     * @param eyeX     the eye, X, metres
     * @param eyeY     the eye, Y, metres
     * @param eyeZ     the eye, Z, metres
     * @param reach    how far from the eye the map reaches, metres
     */
    public void set(float texel, float bias, float strength, float eyeX, float eyeY, float eyeZ, float reach) {
        drawn = true;
        this.texel = texel;
        this.bias = bias;
        this.strength = strength;
        this.eyeX = eyeX;
        this.eyeY = eyeY;
        this.eyeZ = eyeZ;
        this.reach = reach;
    }

    /**
     * Sets the world-to-map matrix the receivers read (kept, not copied: the map's own, refitted each
     * frame). No allocation.
     *
     * @param matrix 16 floats, column-major; null while no map has been made
     */
    public void setMatrix(FloatBuffer matrix) {
        this.matrix = matrix;
    }

    /** {@return whether the map is drawn this frame} */
    public boolean drawn() {
        return drawn;
    }

    /**
     * Sets these values on the program in use: {@code uSunShadow}, {@code uShadowEye} and, once a map
     * has been made, {@code uShadowMatrix} (a location of -1, a uniform the program lacks, is ignored).
     * No allocation.
     *
     * @param sunShadow    location of {@code uSunShadow}
     * @param shadowEye    location of {@code uShadowEye}
     * @param shadowMatrix location of {@code uShadowMatrix}
     */
    public void upload(int sunShadow, int shadowEye, int shadowMatrix) {
        glUniform4f(sunShadow, drawn ? 1f : 0f, texel, bias, strength);
        glUniform4f(shadowEye, eyeX, eyeY, eyeZ, reach);
        if (matrix != null) {
            glUniformMatrix4fv(shadowMatrix, false, matrix);
        }
    }
}
