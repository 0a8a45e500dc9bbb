package org.jecosys.anim;

import org.jecosys.math.Require;

/**
 * Per species, the distances where its levels of detail end (paper §4.1, Table 3), scaled by a
 * LOD bias, kept squared for the per-plant test. One owner thread; {@link #level} allocates nothing.
 */
final class LodBands {
    private final double[][] edges;
    private final double[][] edges2;
    private double scale = 1;

    /** @param edges per species, the ascending distances (metres) where its levels end; copied */
    LodBands(double[][] edges) {
        Require.nonNull("lodEdges", edges);
        this.edges = new double[edges.length][];
        this.edges2 = new double[edges.length][];
        for (int s = 0; s < edges.length; s++) {
            this.edges[s] = edges[s].clone();
            this.edges2[s] = new double[edges[s].length];
        }
        setScale(1);
    }

    int species() {
        return edges.length;
    }

    /** Scales every distance, in [0.01, 100] (2 keeps detail twice as far). */
    void setScale(double s) {
        Require.range("scale", s, 0.01, 100);
        scale = s;
        for (int sp = 0; sp < edges.length; sp++) {
            for (int i = 0; i < edges[sp].length; i++) {
                double d = edges[sp][i] * s;
                edges2[sp][i] = d * d;
            }
        }
    }

    double scale() {
        return scale;
    }

    /** Scaled edge l of species s, metres (where level l ends). */
    double edge(int species, int l) {
        return edges[species][l] * scale;
    }

    /** Replaces species s's unscaled edges (ascending, one fewer than its levels). */
    void setEdges(int species, double[] maxDistances) {
        Require.nonNull("maxDistances", maxDistances);
        if (maxDistances.length != edges[species].length) {
            throw new IllegalArgumentException("species " + species + " has " + (edges[species].length + 1)
                    + " levels, so " + edges[species].length + " distances, got " + maxDistances.length);
        }
        double prev = 0;
        for (int i = 0; i < maxDistances.length; i++) {
            Require.elementRange("maxDistances", i, maxDistances[i], Math.nextUp(prev), 1e6);
            prev = maxDistances[i];
        }
        edges[species] = maxDistances.clone();
        setScale(scale);
    }

    /** The level of a plant of {@code species} at squared distance {@code d2} from the eye (0 = nearest). */
    int level(int species, double d2) {
        double[] e = edges2[species];
        int l = 0;
        while (l < e.length && d2 >= e[l]) {
            l++;
        }
        return l;
    }
}
