package org.jecosys.terrain;

import java.util.List;
import org.jecosys.math.Progress;

/**
 * Places plants of several species on a terrain (paper §4.3). An extension point: the paper's
 * technique is {@link CompetitiveDistributor}; a user may supply another placement rule and pass it to
 * {@code World.build} (see docs/ARCHITECTURE.md, "Extension points").
 *
 * <p>Contract for implementations: the result depends only on the arguments (the seed included),
 * never on {@code workers}; the terrain's maps are not modified (work on {@link ResourceMap#copy()});
 * hand placements come first in the layout; a distribution that cannot be satisfied yields a warning
 * in {@link PlantLayout#warnings()}, not an exception. Call from one thread at a time per instance;
 * implementations may use up to {@code workers} worker threads internally. Allocates the layout.
 */
public interface TerrainDistributor {
    /**
     * Distributes plants.
     *
     * @param terrain       the terrain and its initial resources
     * @param speciesIds    the scene's species ids, in order; a plant's species index points here
     * @param distributions the distributions (each names a species in {@code speciesIds})
     * @param placements    plants placed by hand, inside the terrain (each names a species)
     * @param seed          seed of everything random (positions, azimuths, variant seeds)
     * @param workers       worker threads, at least 1; does not change the result
     * @param progress      told "distribution" progress on the calling thread
     * @return the plants, in placement order, with warnings
     * @throws IllegalArgumentException on null arguments, unknown species, a bad thread count or a
     *                                  hand placement outside the terrain
     */
    PlantLayout distribute(Terrain terrain, List<String> speciesIds, List<DistributionDef> distributions,
                           List<PlacementDef> placements, long seed, int workers, Progress progress);
}
