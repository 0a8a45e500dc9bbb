package org.jecosys.world;

import org.jecosys.math.HeightFunction;
import org.jecosys.math.Noise;
import org.jecosys.math.Require;

/**
 * Seeded, unbounded, gentle hills for an open-world scene: {@code amplitude} times a fractal sum
 * (fBm) of {@code octaves} layers of {@link Noise#value2 value noise}, the first with lattice cells of
 * {@code wavelength} metres, each next one at twice the frequency and half the amplitude. Heights lie
 * in [-amplitude, amplitude]; the steepest slope is about {@code 4 amplitude / wavelength} radians
 * (0.13 rad, 7 degrees, for the {@link #gentle} hills). Defined everywhere, with no period and no
 * edge.
 *
 * <p>Immutable and pure: any thread may call it concurrently; no allocation per call.
 *
 * @param seed       selects the hills
 * @param amplitude  largest height above or below 0, metres, in [0, 10000]
 * @param wavelength size of the largest hills (the first octave's lattice cell), metres, in [1, 1e6]
 * @param octaves    layers summed, in [1, 12]
 */
public record RollingTerrain(long seed, double amplitude, double wavelength, int octaves) implements HeightFunction {
    /** Amplitude ratio between successive octaves. */
    public static final double GAIN = 0.5;

    /**
     * Checks the components.
     *
     * @param seed       selects the hills
     * @param amplitude  largest height above or below 0, metres, in [0, 10000]
     * @param wavelength size of the largest hills, metres, in [1, 1e6]
     * @param octaves    layers summed, in [1, 12]
     * @throws IllegalArgumentException when a component is out of range
     */
    public RollingTerrain {
        Require.range("amplitude", amplitude, 0, 10_000);
        Require.range("wavelength", wavelength, 1, 1e6);
        Require.range("octaves", octaves, 1, 12);
    }

    /**
     * Gentle meadow hills: 3 m amplitude, 90 m wavelength, 4 octaves. Allocates.
     *
     * @param seed selects the hills
     * @return new hills
     */
    public static RollingTerrain gentle(long seed) {
        return new RollingTerrain(seed, 3, 90, 4);
    }

    @Override
    public double height(double x, double z) {
        return amplitude * Noise.fractal2(seed, x / wavelength, z / wavelength, octaves, GAIN);
    }
}
