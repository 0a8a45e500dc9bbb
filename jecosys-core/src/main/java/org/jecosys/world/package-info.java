/**
 * The open world's placement foundation (issue 39): plants in square tiles around the views, on the
 * game's own ground. {@link org.jecosys.math.HeightFunction} is the ground (the library's
 * {@link org.jecosys.terrain.Heightfield}, the endless {@link org.jecosys.world.RollingTerrain}, or a
 * game's terrain), {@link org.jecosys.world.ResourceFunction} its water and nutrients, and
 * {@link org.jecosys.world.TilePlacer} the paper's competitive distribution (§4.3) cut into tiles that
 * are pure functions of (seed, tile coordinates, distributions, ground), seam-free and the same in any
 * visit order; a tile's plants come as the flat arrays of {@link org.jecosys.world.TilePlants}.
 *
 * <p>No GL and no simulation state: streaming tiles into a running simulation is the runtime's job.
 * Everything here is immutable or per call, safe on worker threads.
 */
package org.jecosys.world;
