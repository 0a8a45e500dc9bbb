/**
 * Plant models (paper §4.1): species definitions ({@link org.jecosys.plant.SpeciesDef},
 * {@link org.jecosys.plant.ComponentDef}, the paper's species in
 * {@link org.jecosys.plant.SpeciesLibrary}), the vector skeleton of each component bent by gravity
 * ({@link org.jecosys.plant.Skeleton}, {@link org.jecosys.plant.GravityBend}), the pre-computed
 * pose tables that animation chooses from ({@link org.jecosys.plant.PoseTable},
 * {@link org.jecosys.plant.PoseMapping}), and the levels of detail: per-level point subsets and
 * triangle or line meshes ({@link org.jecosys.plant.ComponentMesh},
 * {@link org.jecosys.plant.LodMesh}); the distance-based choice between them is made per frame by
 * {@code org.jecosys.sim.DrawDecision}.
 *
 * <p>Everything here is built once at scene load ({@link org.jecosys.plant.PlantModel},
 * {@link org.jecosys.plant.SpeciesModel}), allocating, and is immutable afterwards: any thread may
 * read it, and the per-frame accessors do not allocate. No OpenGL.
 */
package org.jecosys.plant;
