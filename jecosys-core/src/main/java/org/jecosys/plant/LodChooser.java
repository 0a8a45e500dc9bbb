package org.jecosys.plant;

import java.util.List;
import org.jecosys.math.Require;

/**
 * Chooses a species' level of detail from the viewer distance (paper §4.1 and Table 3), with a
 * transition band so levels never pop. Level {@code L} covers distances
 * [{@code maxDistance(L-1)}, {@code maxDistance(L)}). In the last {@code bandWidth} metres before
 * each edge the <em>fade</em> toward level {@code L + 1} rises linearly from 0 to 1; at the edge the
 * next level takes over with fade 0, so the blend is continuous in distance. The
 * {@linkplain #coordinate LOD coordinate} {@code L + fade} carries both; a renderer dithers
 * instances between the two levels with {@link #ditheredLevel} (or cross-fades them).
 *
 * <p>Immutable; any thread; {@link #level}, {@link #fade}, {@link #coordinate} and
 * {@link #ditheredLevel} do not allocate (per-frame safe).
 */
public final class LodChooser {
    /** Default transition band width, metres. */
    public static final double DEFAULT_BAND = 1.0;

    private final double[] edges;
    private final double band;

    /**
     * A chooser for explicit levels. Build time; allocates.
     *
     * @param lods      the species' levels (ascending maxDistance, the last unbounded), at least one
     * @param bandWidth transition band width, metres, in [0, smallest gap between edges (from 0)]
     */
    public LodChooser(List<LodDef> lods, double bandWidth) {
        Require.nonNull("lods", lods);
        if (lods.isEmpty()) {
            throw new IllegalArgumentException("lods must not be empty");
        }
        edges = new double[lods.size() - 1];
        double prev = 0;
        double minGap = Double.POSITIVE_INFINITY;
        for (int i = 0; i < edges.length; i++) {
            edges[i] = Require.positive("lods[" + i + "].maxDistance", lods.get(i).maxDistance());
            if (edges[i] <= prev) {
                throw new IllegalArgumentException("lods maxDistance must ascend, got " + edges[i] + " after " + prev);
            }
            minGap = Math.min(minGap, edges[i] - prev);
            prev = edges[i];
        }
        band = Require.range("bandWidth", bandWidth, 0, minGap == Double.POSITIVE_INFINITY ? 1e9 : minGap);
    }

    /**
     * A chooser for {@code species}' levels. Allocates.
     *
     * @param species   the species whose {@link SpeciesDef#lods()} are used
     * @param bandWidth transition band width, metres (see the constructor)
     * @return a new chooser
     */
    public static LodChooser of(SpeciesDef species, double bandWidth) {
        return new LodChooser(Require.nonNull("species", species).lods(), bandWidth);
    }

    /** {@return the number of levels, at least 1} */
    public int levels() {
        return edges.length + 1;
    }

    /** {@return the transition band width, metres} */
    public double bandWidth() {
        return band;
    }

    /**
     * The level whose band holds {@code distance}.
     *
     * @param distance viewer distance, metres; negative and NaN count as 0
     * @return the level, in [0, levels())
     */
    public int level(double distance) {
        int l = 0;
        while (l < edges.length && distance >= edges[l]) {
            l++;
        }
        return l;
    }

    /**
     * Fade toward level {@code level(distance) + 1}.
     *
     * @param distance viewer distance, metres
     * @return in [0, 1); 0 in the last level, outside the band and when the band width is 0
     */
    public double fade(double distance) {
        int l = level(distance);
        if (l >= edges.length || band <= 0) {
            return 0;
        }
        double start = edges[l] - band;
        if (distance <= start) {
            return 0;
        }
        return Math.min((distance - start) / band, Math.nextDown(1.0));
    }

    /**
     * The LOD coordinate {@code level(distance) + fade(distance)}.
     *
     * @param distance viewer distance, metres
     * @return continuous and non-decreasing in distance, in [0, levels())
     */
    public double coordinate(double distance) {
        return level(distance) + fade(distance);
    }

    /**
     * The level an instance draws when dithering: {@code floor(c) + 1} when the fade exceeds the
     * instance's stable hash, else {@code floor(c)}.
     *
     * @param coordinate a value of {@link #coordinate}
     * @param hash01     the instance's stable pseudo-random value in [0, 1)
     * @return the level to draw
     */
    public static int ditheredLevel(double coordinate, double hash01) {
        int l = (int) Math.floor(coordinate);
        return (coordinate - l) > hash01 ? l + 1 : l;
    }
}
