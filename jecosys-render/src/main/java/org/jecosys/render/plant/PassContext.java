package org.jecosys.render.plant;

import java.nio.FloatBuffer;
import org.jecosys.sim.Frame;

/**
 * What one frame's plant passes share, set on every program at once ({@link PlantUniforms#frame}):
 * the view-projection, the eye, the direction toward the sun, the haze, the size of a pixel
 * ({@code pixelX + distance * pixelY} metres), the frame (its distance thinning) and whether the
 * target is multisampled. {@link PlantRenderer} makes one for the view and {@link PlantPasses} one
 * for the sun's shadow casters, once; they are filled each frame. Render thread; no allocation.
 */
final class PassContext {
    /** World to clip, 16 floats column-major (kept, not copied). */
    FloatBuffer viewProj;
    /** The eye, metres. */
    float eyeX;
    float eyeY;
    float eyeZ;
    /** Unit vector toward the sun. */
    float lightX;
    float lightY = 1f;
    float lightZ;
    /** Haze colour (the sky's horizon), and where the haze starts and is full, metres. */
    float fogR;
    float fogG;
    float fogB;
    float fogStart = 20f;
    float fogEnd = 150f;
    /** A pixel's size at the eye and its growth per metre of distance, metres. */
    float pixelX;
    float pixelY;
    /** The viewport's height over {@link PlantRenderer#HEAD_REFERENCE_HEIGHT}: flower parts' least size scales with it. */
    float headScale = 1f;
    /** The frame drawn (its distance thinning). */
    Frame frame;
    /** Whether the target is multisampled: the triangle levels then keep coverage in alpha. */
    boolean multisampled;

    /** Sets the eye, metres. */
    void setEye(float x, float y, float z) {
        eyeX = x;
        eyeY = y;
        eyeZ = z;
    }

    /** Sets the unit vector toward the sun. */
    void setLight(float x, float y, float z) {
        lightX = x;
        lightY = y;
        lightZ = z;
    }

    /** Sets the haze: its colour and where it starts and is full, metres. */
    void setFog(float r, float g, float b, float start, float end) {
        fogR = r;
        fogG = g;
        fogB = b;
        fogStart = start;
        fogEnd = end;
    }

    /** Sets a pixel's size at the eye and its growth per metre of distance, metres. */
    void setPixel(float x, float y) {
        pixelX = x;
        pixelY = y;
    }
}
