/**
 * The LOD force field (paper §3, §3.1): the ground is divided by a {@link org.jecosys.field.Quadtree}
 * whose leaves split where plants are dense (§3.1.1); each update culls the nodes against the
 * camera's frustum and, by distance, lets an ancestor stand for its subtree, so distant and sparse
 * regions take few wind evaluations. The flows of a {@link org.jecosys.wind.WindField} are evaluated
 * once per effective node, at the centre of gravity of its plants (§3.2), and every visible plant
 * shares its node's wind velocity; {@link org.jecosys.field.DragLaw} turns that velocity into the
 * force on a component.
 *
 * <p>{@link org.jecosys.field.ForceField} is the interface the simulation drives and
 * {@link org.jecosys.field.QuadtreeForceField} the paper's implementation; a game may supply its
 * own through a {@link org.jecosys.field.ForceFieldFactory}. {@link org.jecosys.field.FieldCounters}
 * and {@link org.jecosys.field.FieldDebugView} report what the last update did (paper Figures 2 and
 * 3). A field is owned by one thread, the simulation's stepping thread; its update and queries
 * allocate nothing.
 */
package org.jecosys.field;
