/**
 * Wind (paper §3.2): flows over the ground plane that the force field samples at each visible node.
 * {@link org.jecosys.wind.FlowDef} declares a flow of one of the {@link org.jecosys.wind.FlowKind}s:
 * Wejchert and Haumann's uniform, source, sink and vortex primitives (the paper's [11]), plus gusts,
 * blasts and rain; {@link org.jecosys.wind.ActivationDef} says when it acts (activated,
 * deactivated, or for a set duration) and {@link org.jecosys.wind.MotionDef} how its centre moves
 * (fixed, along a path, or carried by the other flows). {@link org.jecosys.wind.WindField} sums the
 * flows (linear superposition) and advances their clock.
 *
 * <p>Velocities are in m/s, strengths in m/s or m^2/s, positions in metres; a 2D velocity's
 * {@code y} is the world Z component. A game adds its own flow by implementing
 * {@link org.jecosys.wind.WindSource}, most simply by extending
 * {@link org.jecosys.wind.AbstractWindSource}. Flows belong to the simulation's stepping thread and
 * allocate nothing once built.
 */
package org.jecosys.wind;
