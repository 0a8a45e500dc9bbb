package org.jecosys.sim;

/**
 * Where each species' levels of detail end, copied from a {@link DrawDecision.Edges} once per decision
 * (a step, a view) so that the per-plant loop of {@link DrawDecision} reads arrays, not an interface: per species its level count, its edges
 * (metres) and the transition band it uses (the decision's, at most the smallest gap between its
 * edges); and per level its plain window, the squared equivalent distances where the level is drawn
 * whole and alone, which let the decision skip a plant's square root and dither arithmetic, or a
 * whole chunk's distances ({@link RangeDecision#plainLevels}). Sized for the world's species; {@link #fill}
 * allocates only when a species has more levels than before. One thread fills it, then any read it.
 */
final class LevelBands {
    /** Relative margin of the plain windows, far above the roundings of a square and its root. */
    static final double PLAIN_MARGIN = 1e-9;

    final int[] levels;
    double[][] edges;
    final double[] band;
    /**
     * Per species, per level l, the squared equivalent distances {@code [plain[2l], plain[2l + 1]]}
     * where level l is drawn whole and alone (packed window 255): past the level's first edge by a
     * margin, short of its last edge (less the transition band) by a margin, so that the decision may
     * skip the square root and the window's arithmetic there with the very result they give.
     */
    double[][] plain;

    LevelBands(int species) {
        levels = new int[species];
        edges = new double[species][0];
        band = new double[species];
        plain = new double[species][0];
    }

    /** Copies the edges of {@code e} and each species' band for a decision band {@code b}, metres. */
    LevelBands fill(DrawDecision.Edges e, double b) {
        for (int s = 0; s < levels.length; s++) {
            int n = e.levels(s);
            levels[s] = n;
            if (edges[s].length < n - 1) {
                edges[s] = new double[n - 1];
            }
            for (int l = 0; l < n - 1; l++) {
                edges[s][l] = e.edge(s, l);
            }
            band[s] = Math.min(b, minGap(e, s, n));
            if (plain[s].length < 2 * n) {
                plain[s] = new double[2 * n];
            }
            for (int l = 0; l < n; l++) {
                plain[s][2 * l] = l == 0 ? Double.NEGATIVE_INFINITY : above2(edges[s][l - 1]);
                plain[s][2 * l + 1] = l == n - 1 ? Double.POSITIVE_INFINITY
                        : below2(band[s] > 0 ? edges[s][l] - band[s] : edges[s][l]);
            }
        }
        return this;
    }

    /** The smallest gap between consecutive edges of species s (from 0), metres. */
    static double minGap(DrawDecision.Edges edges, int s, int levels) {
        double gap = Double.POSITIVE_INFINITY;
        double prev = 0;
        for (int l = 0; l < levels - 1; l++) {
            double e = edges.edge(s, l);
            gap = Math.min(gap, e - prev);
            prev = e;
        }
        return gap;
    }

    /** A square that a squared distance reaches only when the distance is surely at least {@code e} (e &gt;= 0). */
    static double above2(double e) {
        return e * e * (1 + PLAIN_MARGIN);
    }

    /** A square that a squared distance stays below only when the distance is surely below {@code e}; -1 for e &lt;= 0. */
    static double below2(double e) {
        return e > 0 ? e * e * (1 - PLAIN_MARGIN) : -1;
    }
}
