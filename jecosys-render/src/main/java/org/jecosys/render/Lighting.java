package org.jecosys.render;

import org.jecosys.math.Require;
import org.jecosys.math.Rgb;

/**
 * The light and haze the plants, their ground cover and the library's terrain and sky are drawn in:
 * the sun (direction, colour, intensity), the sky's ambient light, the sky's colours and the fog
 * (aerial perspective). A scene file gives them in its {@code <render><light>}
 * ({@link RenderSettings#of}); a game sets them from its own lights every frame (the libGDX and jME
 * adapters do it from the engine's directional and ambient lights and fog). Colours are display
 * values, written by the shaders unconverted.
 *
 * <p>Each colour has two setters: one taking an {@link Rgb} (a scene file's value, [0, 1]) and one
 * taking three floats, for a game's per-frame light. Light colours (sun, ambient) may exceed 1, as
 * engines' lights do, up to 4. Getters give the floats ({@code sunR()}, ...); the {@code Rgb} getters
 * allocate and are meant for editors and tests. Render thread only (or whichever thread owns the
 * settings while the renderer does not read them); no setter and no float getter allocates.
 */
public final class Lighting {
    /** Default sun azimuth, radians: 135 degrees (behind and to the left of a camera looking along -Z). */
    public static final double DEFAULT_SUN_AZIMUTH = Math.toRadians(135);
    /** Default sun elevation, radians: 50 degrees. */
    public static final double DEFAULT_SUN_ELEVATION = Math.toRadians(50);
    /** The largest value of a light colour's channel (sun colour, ambient). */
    public static final float MAX_LIGHT = 4;
    /** {@link #fogStart()} when there is no fog: beyond any view's reach. */
    private static final float NO_FOG = 1e30f;

    private float skyR = 0.62f;
    private float skyG = 0.76f;
    private float skyB = 0.92f;
    private float zenithR = 0.30f;
    private float zenithG = 0.50f;
    private float zenithB = 0.85f;
    private float sunR = 1f;
    private float sunG = 0.95f;
    private float sunB = 0.85f;
    private float sunIntensity = 0.8f;
    private float ambientR = 0.42f;
    private float ambientG = 0.46f;
    private float ambientB = 0.52f;
    private double sunAzimuth;
    private double sunElevation;
    private float sunX;
    private float sunY;
    private float sunZ;
    private float fogStart = 20;
    private float fogEnd = 150;
    private float clouds;

    /**
     * A scene file's default light: a light blue horizon (the haze colour) and a deeper blue zenith,
     * the sun at azimuth 135 degrees and elevation 50 degrees, warm white at intensity 0.8, a cool
     * ambient of about 0.45, haze from 20 m to 150 m. Allocates.
     */
    public Lighting() {
        setSun(DEFAULT_SUN_AZIMUTH, DEFAULT_SUN_ELEVATION);
    }

    /**
     * Sets the sun's direction by its angles; the unit vector toward the sun is
     * {@code (cos el cos az, sin el, cos el sin az)}, so azimuth 0 is +X, pi/2 is +Z, pi is -X (the
     * scene's {@code <light sunAzimuth sunElevation>}, which the file gives in degrees). No allocation.
     *
     * @param azimuth   compass angle of the sun, radians, in [-2 pi, 2 pi]
     * @param elevation height above the horizon, radians, in [0, pi / 2]
     * @throws IllegalArgumentException when an angle is out of range or not finite
     */
    public void setSun(double azimuth, double elevation) {
        Require.range("sunAzimuth", azimuth, -2 * Math.PI, 2 * Math.PI);
        Require.range("sunElevation", elevation, 0, Math.PI / 2);
        sunAzimuth = azimuth;
        sunElevation = elevation;
        sunX = (float) (Math.cos(elevation) * Math.cos(azimuth));
        sunY = (float) Math.sin(elevation);
        sunZ = (float) (Math.cos(elevation) * Math.sin(azimuth));
    }

    /**
     * Sets the sun's direction by a vector toward it (the opposite of the direction an engine's
     * directional light shines in), normalised here; its angles follow ({@link #sunAzimuth()}, and an
     * elevation below 0 for a sun under the horizon, which lights nothing from above). No allocation.
     *
     * @param x X of a vector toward the sun, any length &gt; 0
     * @param y Y (up) of the vector
     * @param z Z of the vector
     * @throws IllegalArgumentException when the vector is not finite or (nearly) zero
     */
    public void setSunDirection(float x, float y, float z) {
        double len = Math.sqrt((double) x * x + (double) y * y + (double) z * z);
        if (!Double.isFinite(len) || len < 1e-12) {
            throw new IllegalArgumentException("sun direction must be finite and not zero, got " + x + ", " + y
                    + ", " + z);
        }
        sunX = (float) (x / len);
        sunY = (float) (y / len);
        sunZ = (float) (z / len);
        sunElevation = Math.asin(Math.max(-1, Math.min(1, y / len)));
        sunAzimuth = Math.atan2(z, x);
    }

    /** {@return the sun's azimuth, radians, as last set (from a direction: in [-pi, pi])} */
    public double sunAzimuth() {
        return sunAzimuth;
    }

    /** {@return the sun's elevation above the horizon, radians (below 0 only when set by a direction)} */
    public double sunElevation() {
        return sunElevation;
    }

    /** {@return X of the unit vector toward the sun} */
    public float sunX() {
        return sunX;
    }

    /** {@return Y (up) of the unit vector toward the sun} */
    public float sunY() {
        return sunY;
    }

    /** {@return Z of the unit vector toward the sun} */
    public float sunZ() {
        return sunZ;
    }

    /**
     * Sets the colour of the sunlight (the direct light is the colour times {@link #sunIntensity()}).
     * No allocation.
     *
     * @param colour the sun colour, not null
     */
    public void setSunColour(Rgb colour) {
        Require.nonNull("sunColour", colour);
        setSunColour(colour.r(), colour.g(), colour.b());
    }

    /**
     * Sets the colour of the sunlight from a game's light, channels in [0, {@link #MAX_LIGHT}] (an
     * engine's light colour may exceed 1). No allocation.
     *
     * @param r red
     * @param g green
     * @param b blue
     * @throws IllegalArgumentException when a channel is out of range or not finite
     */
    public void setSunColour(float r, float g, float b) {
        checkLight("sunColour", r, g, b);
        sunR = r;
        sunG = g;
        sunB = b;
    }

    /** {@return red of the sun's colour} */
    public float sunR() {
        return sunR;
    }

    /** {@return green of the sun's colour} */
    public float sunG() {
        return sunG;
    }

    /** {@return blue of the sun's colour} */
    public float sunB() {
        return sunB;
    }

    /**
     * {@return the sun's colour, clamped to [0, 1] per channel} Allocates (for editors and tests).
     */
    public Rgb sunColour() {
        return clamped(sunR, sunG, sunB);
    }

    /** {@return the multiplier of the sun colour: the direct light is sunColour x sunIntensity} */
    public float sunIntensity() {
        return sunIntensity;
    }

    /**
     * Sets the sun's intensity. No allocation.
     *
     * @param intensity multiplier of the sun's colour, in [0, 4]
     * @throws IllegalArgumentException when out of range
     */
    public void setSunIntensity(float intensity) {
        Require.range("sunIntensity", intensity, 0, 4);
        this.sunIntensity = intensity;
    }

    /**
     * Sets the ambient (sky) light on an upward-facing surface. No allocation.
     *
     * @param ambient colour times strength of the light from the whole sky, not null
     */
    public void setAmbient(Rgb ambient) {
        Require.nonNull("ambient", ambient);
        setAmbient(ambient.r(), ambient.g(), ambient.b());
    }

    /**
     * Sets the ambient light from a game's ambient light, channels in [0, {@link #MAX_LIGHT}]. No
     * allocation.
     *
     * @param r red
     * @param g green
     * @param b blue
     * @throws IllegalArgumentException when a channel is out of range or not finite
     */
    public void setAmbient(float r, float g, float b) {
        checkLight("ambient", r, g, b);
        ambientR = r;
        ambientG = g;
        ambientB = b;
    }

    /** {@return red of the ambient light} */
    public float ambientR() {
        return ambientR;
    }

    /** {@return green of the ambient light} */
    public float ambientG() {
        return ambientG;
    }

    /** {@return blue of the ambient light} */
    public float ambientB() {
        return ambientB;
    }

    /** {@return the ambient light, clamped to [0, 1] per channel} Allocates (for editors and tests). */
    public Rgb ambient() {
        return clamped(ambientR, ambientG, ambientB);
    }

    /**
     * Sets the sky's colour at the horizon: also the fog (haze) colour and the colour a clearing
     * renderer clears to. No allocation.
     *
     * @param sky the horizon, fog and clear colour, not null
     */
    public void setSky(Rgb sky) {
        Require.nonNull("sky", sky);
        setSky(sky.r(), sky.g(), sky.b());
    }

    /**
     * Sets the horizon, fog and clear colour from floats (a game's fog colour). No allocation.
     *
     * @param r red, in [0, 1]
     * @param g green, in [0, 1]
     * @param b blue, in [0, 1]
     * @throws IllegalArgumentException when a channel is out of range or not finite
     */
    public void setSky(float r, float g, float b) {
        Require.range("sky red", r, 0, 1);
        Require.range("sky green", g, 0, 1);
        Require.range("sky blue", b, 0, 1);
        skyR = r;
        skyG = g;
        skyB = b;
    }

    /** {@return red of the horizon and fog colour} */
    public float skyR() {
        return skyR;
    }

    /** {@return green of the horizon and fog colour} */
    public float skyG() {
        return skyG;
    }

    /** {@return blue of the horizon and fog colour} */
    public float skyB() {
        return skyB;
    }

    /** {@return the horizon and fog colour} Allocates (for editors and tests). */
    public Rgb sky() {
        return new Rgb(skyR, skyG, skyB);
    }

    /**
     * Sets the sky colour straight up (the library's sky runs from the horizon colour to it). No
     * allocation.
     *
     * @param zenith the zenith colour, not null
     */
    public void setSkyZenith(Rgb zenith) {
        Require.nonNull("skyZenith", zenith);
        zenithR = zenith.r();
        zenithG = zenith.g();
        zenithB = zenith.b();
    }

    /** {@return red of the zenith colour} */
    public float zenithR() {
        return zenithR;
    }

    /** {@return green of the zenith colour} */
    public float zenithG() {
        return zenithG;
    }

    /** {@return blue of the zenith colour} */
    public float zenithB() {
        return zenithB;
    }

    /** {@return the sky colour straight up} Allocates (for editors and tests). */
    public Rgb skyZenith() {
        return new Rgb(zenithR, zenithG, zenithB);
    }

    /**
     * {@return the distance where fog (aerial perspective: haze toward the {@link #sky()} colour)
     * begins, metres; the haze is {@code f * f} with {@code f = clamp((d - fogStart) / (fogEnd -
     * fogStart), 0, 1)}, for plants and ground alike (libGDX's default fog law with fogStart 0 and
     * fogEnd the camera's far distance)}
     */
    public float fogStart() {
        return fogStart;
    }

    /** {@return the distance of full fog, metres} */
    public float fogEnd() {
        return fogEnd;
    }

    /** {@return whether there is fog at all ({@link #setNoFog()} turns it off)} */
    public boolean hasFog() {
        return fogStart < NO_FOG;
    }

    /**
     * Sets the fog range. No allocation.
     *
     * @param start distance where fog begins, metres, &gt;= 0
     * @param end   distance of full fog, metres, &gt; start, finite
     * @throws IllegalArgumentException when the range is empty, starts below 0 or is not finite
     */
    public void setFog(float start, float end) {
        Require.nonNegative("fogStart", start);
        if (!(end > start) || !Float.isFinite(end)) {
            throw new IllegalArgumentException("fog end must be finite and > start, got " + start + ".." + end);
        }
        fogStart = start;
        fogEnd = end;
    }

    /**
     * Turns the fog off (a game without fog, or one whose own post-process fogs the plants with the
     * rest of its picture): nothing hazes toward the sky colour. {@link #setFog} turns it on again. No
     * allocation.
     */
    public void setNoFog() {
        fogStart = NO_FOG;
        fogEnd = 2 * NO_FOG;
    }

    /**
     * Copies every value of another lighting into this one. No allocation.
     *
     * @param other the lighting to copy, not null
     */
    public void set(Lighting other) {
        Require.nonNull("other", other);
        skyR = other.skyR;
        skyG = other.skyG;
        skyB = other.skyB;
        zenithR = other.zenithR;
        zenithG = other.zenithG;
        zenithB = other.zenithB;
        sunR = other.sunR;
        sunG = other.sunG;
        sunB = other.sunB;
        sunIntensity = other.sunIntensity;
        ambientR = other.ambientR;
        ambientG = other.ambientG;
        ambientB = other.ambientB;
        sunAzimuth = other.sunAzimuth;
        sunElevation = other.sunElevation;
        sunX = other.sunX;
        sunY = other.sunY;
        sunZ = other.sunZ;
        fogStart = other.fogStart;
        fogEnd = other.fogEnd;
        clouds = other.clouds;
    }

    /**
     * Sets how much of the sky fair-weather clouds cover ({@code <light clouds>}): drawn by the sky pass,
     * lit by the sun, thinning into the haze at the horizon. No allocation.
     *
     * @param cover in [0, 1]; 0 for a clear sky
     * @throws IllegalArgumentException when out of range
     */
    public void setClouds(float cover) {
        Require.range("clouds", cover, 0, 1);
        clouds = cover;
    }

    /** {@return how much of the sky clouds cover, in [0, 1]} */
    public float clouds() {
        return clouds;
    }

    private static void checkLight(String name, float r, float g, float b) {
        if (!(r >= 0 && r <= MAX_LIGHT && g >= 0 && g <= MAX_LIGHT && b >= 0 && b <= MAX_LIGHT)) {
            throw new IllegalArgumentException(name + " channels must be in [0, " + MAX_LIGHT + "], got " + r + ", "
                    + g + ", " + b);
        }
    }

    private static Rgb clamped(float r, float g, float b) {
        return new Rgb(Math.min(1f, r), Math.min(1f, g), Math.min(1f, b));
    }
}
