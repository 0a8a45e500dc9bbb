package org.jecosys.wind;

import org.jecosys.math.Rng;
import org.joml.Vector2d;

/**
 * Rain over a disc (centre c, radius R = influenceRadius, which must be finite): short seeded
 * impulses, each seen on the ground as a small radial burst where a drop (or a burst of drops)
 * lands. The plane is cut into square cells of side s = noiseScale (m) anchored at the centre;
 * time is cut into slots of {@link #IMPULSE_DURATION} seconds, staggered per cell by a seeded
 * phase. In each slot a cell holds one impulse with probability
 * {@code P = min(1, noiseFrequency * s^2 * IMPULSE_DURATION)} (noiseFrequency = impulses per
 * second per m^2), at a seeded point d of the cell, counted only when |d - c| &lt;= R.
 * An impulse at phase q in [0, 1) of its slot adds
 * <pre>
 *   (1 - q)^2 (a / 2 pi) (p - d) / max(|p - d|, core)^2   for |p - d| &lt;= s, else 0
 * </pre>
 * with a = strength (m^2/s). A point sums the impulses of its cell and the 8 neighbours.
 * Deterministic for a seed. Single owner thread; no allocation after construction.
 */
public final class RainFlow extends FlowBase {
    /** Length of one impulse, seconds. */
    public static final double IMPULSE_DURATION = 0.2;

    private final double k;
    private final double cell;
    private final double probability;
    private final double radius;
    private final long seed;

    /**
     * A rain flow from its def (kind RAIN). Allocates.
     *
     * @param def a RAIN flow: impulse strength (m^2/s), disc radius ({@code influenceRadius}, metres),
     *            drop spacing ({@code noiseScale}, metres), rate ({@code noiseFrequency}, per s per m^2), seed
     * @throws IllegalArgumentException when {@code def.influenceRadius()} is infinite
     */
    public RainFlow(FlowDef def) {
        super(def);
        if (def.kind() != FlowKind.RAIN) {
            throw new IllegalArgumentException("def.kind must be RAIN, got " + def.kind());
        }
        if (def.influenceRadius() == Double.POSITIVE_INFINITY) {
            throw new IllegalArgumentException("influenceRadius of rain flow '" + def.id()
                    + "' must be finite (it is the radius of the rain disc), got Infinity");
        }
        k = def.strength() / (2 * Math.PI);
        cell = def.noiseScale();
        radius = def.influenceRadius();
        probability = Math.min(1, def.noiseFrequency() * cell * cell * IMPULSE_DURATION);
        seed = def.seed();
    }

    @Override
    void unweighted(double x, double z, double time, Vector2d dest) {
        double px = x - cx;
        double pz = z - cz;
        double reach = radius + cell;
        double sumX = 0;
        double sumZ = 0;
        if (px * px + pz * pz <= reach * reach) {
            long ci = (long) Math.floor(px / cell);
            long cj = (long) Math.floor(pz / cell);
            double core2 = coreRadius * coreRadius;
            double cell2 = cell * cell;
            for (long i = ci - 1; i <= ci + 1; i++) {
                for (long j = cj - 1; j <= cj + 1; j++) {
                    long hc = Rng.mix(seed ^ Rng.mix(i * 0x9E3779B97F4A7C15L ^ Rng.mix(j)));
                    double slotTime = time / IMPULSE_DURATION + unit(hc);
                    double slot = Math.floor(slotTime);
                    double q = slotTime - slot;
                    long h = Rng.mix(hc ^ Rng.mix((long) slot));
                    if (unit(h) >= probability) {
                        continue;
                    }
                    long h2 = Rng.mix(h);
                    long h3 = Rng.mix(h2);
                    double dxC = (i + unit(h2)) * cell;
                    double dzC = (j + unit(h3)) * cell;
                    if (dxC * dxC + dzC * dzC > radius * radius) {
                        continue;
                    }
                    double dx = px - dxC;
                    double dz = pz - dzC;
                    double r2 = dx * dx + dz * dz;
                    if (r2 > cell2) {
                        continue;
                    }
                    double e = 1 - q;
                    double f = k * e * e / Math.max(r2, core2);
                    sumX += f * dx;
                    sumZ += f * dz;
                }
            }
        }
        dest.set(sumX, sumZ);
    }

    private static double unit(long h) {
        return (h >>> 11) * 0x1.0p-53;
    }
}
