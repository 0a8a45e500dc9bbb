/**
 * Scene files: the XML scene format, version 1 (paper §5.1: "the system's parameter input is done by
 * using a XML based language"). {@link org.jecosys.scene.SceneFiles} loads, validates and saves
 * them, {@link org.jecosys.scene.SceneDef} is a whole scene in memory, and
 * {@link org.jecosys.scene.Scenes} builds a {@link org.jecosys.sim.Simulation} from a file. The
 * format is described by {@code scenes/jecosys-scene.xsd} (shipped in the jar), which
 * {@link org.jecosys.scene.SchemaXsd} generates from the loader's own rules.
 *
 * <p>Units in scene files: metres, seconds, kilograms, newtons; angles in degrees (radians in the
 * {@code *Def} records). A file that is not valid yields a
 * {@link org.jecosys.scene.SceneLoadException} listing every problem with its line and column;
 * nothing of it is returned. Loading allocates and may run on any thread.
 */
package org.jecosys.scene;
