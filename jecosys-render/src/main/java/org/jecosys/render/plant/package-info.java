/**
 * Internal to the renderer (not API; it may change without notice; a game uses
 * {@code org.jecosys.render}). The plant passes: which plants are drawn at which level in which instanced draw ({@link org.jecosys.render.plant.PlantBatches}, GL-free), what is uploaded once ({@link org.jecosys.render.plant.PlantMeshes}), the per-component resolve pass on the GPU ({@link org.jecosys.render.plant.ComponentResolver}, by compute shader or transform feedback: {@link org.jecosys.render.ResolvePath}), the draw programs' variants and the look of the plants (paper §4.1, §4.2.2, Table 3).
 * Render thread only, like everything that touches GL.
 */
package org.jecosys.render.plant;
