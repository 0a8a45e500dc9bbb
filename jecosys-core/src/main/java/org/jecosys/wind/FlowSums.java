package org.jecosys.wind;

import org.joml.Vector2d;

/**
 * The sums a {@link WindField} reports over the flows of some kinds: the GUST flows' eddy speed and
 * the velocity their gusts travel at ({@link WindField#eddySpeed}, {@link WindField#gustTravel}), and
 * the flows that flatten ({@link WindField#flattens}): how many act now and their push at a ground
 * point ({@link WindField#flatteningCount}, {@link WindField#flatteningVelocity}). Each reads the
 * field's first {@code count} flows in their order at the field's time, as the field's own loops did
 * (the same sums, bit for bit). Static helpers, no state; owner thread; no allocation.
 */
final class FlowSums {
    private FlowSums() {
    }

    /** {@link WindField#eddySpeed}: the sum over GUST flows of their eddy speed at {@code time}, m/s. */
    static double eddySpeed(WindSource[] flows, int count, double time) {
        double s = 0;
        for (int i = 0; i < count; i++) {
            if (flows[i] instanceof GustFlow g) {
                s += g.eddySpeed(time);
            }
        }
        return s;
    }

    /**
     * {@link WindField#gustTravel}: the weighted mean of the active GUST flows' travel velocities at
     * {@code time} (m/s; x = X, y = Z), or zero; written into dest, which also serves each flow's travel.
     */
    static Vector2d gustTravel(WindSource[] flows, int count, double time, Vector2d dest) {
        double sx = 0;
        double sz = 0;
        double sw = 0;
        for (int i = 0; i < count; i++) {
            if (flows[i] instanceof GustFlow g) {
                double w = g.weight(time);
                if (w > 0) {
                    g.travel(dest);
                    sx += w * dest.x;
                    sz += w * dest.y;
                    sw += w;
                }
            }
        }
        return sw > 0 ? dest.set(sx / sw, sz / sw) : dest.set(0, 0);
    }

    /** {@link WindField#flatteningCount}: the flows that flatten and act at {@code time} (weight &gt; 0). */
    static int flatteningCount(WindSource[] flows, int count, double time) {
        int n = 0;
        for (int i = 0; i < count; i++) {
            if (WindField.flattens(flows[i].kind()) && flows[i].weight(time) > 0) {
                n++;
            }
        }
        return n;
    }

    /**
     * {@link WindField#flatteningVelocity}: the sum of the velocities (m/s; x = X, y = Z) of the flows that
     * flatten at ground point (x, z), metres, at {@code time}, each written into {@code tmp} first; the
     * sum into dest.
     */
    static Vector2d flatteningVelocity(WindSource[] flows, int count, double time, double x, double z,
                                       Vector2d tmp, Vector2d dest) {
        double sx = 0;
        double sz = 0;
        Vector2d t = tmp;
        for (int i = 0; i < count; i++) {
            WindSource f = flows[i];
            if (!WindField.flattens(f.kind())) {
                continue;
            }
            if (f instanceof FlowBase b) {
                b.velocity(x, z, time, t);
            } else {
                f.velocity(x, z, time, t);
            }
            sx += t.x;
            sz += t.y;
        }
        return dest.set(sx, sz);
    }
}
