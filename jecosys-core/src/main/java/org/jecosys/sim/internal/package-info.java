/**
 * Internal to the simulation (not API; it may change without notice; not exported by the module):
 * writers of a {@link org.jecosys.sim.Frame} and a {@link org.jecosys.sim.DrawDecision} for tools
 * and tests that build them without the animation engine. A game only reads frames.
 */
package org.jecosys.sim.internal;
