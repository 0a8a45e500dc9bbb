/**
 * The terrain and the plant distribution (paper §4.3): a generated or image-based
 * {@link org.jecosys.terrain.Heightfield}, water and nutrient
 * {@link org.jecosys.terrain.ResourceMap}s, and the competitive distribution
 * ({@link org.jecosys.terrain.CompetitiveDistributor}) in which the plants of several species take
 * ground and consume resources, so one species grows where another left room. The result is a
 * {@link org.jecosys.terrain.PlantLayout}; {@link org.jecosys.terrain.TerrainMaps} draws the maps as
 * PNG pictures.
 *
 * <p>Scene-load time only: building allocates and may use worker threads, but every result depends
 * only on the definitions and the seed, never on the thread count. The built objects are immutable
 * and may be read from any thread. {@link org.jecosys.terrain.TerrainDistributor} is the extension
 * point for another placement rule.
 */
package org.jecosys.terrain;
