/**
 * Plant animation (paper §4.2): the dynamic-constraint spring of eq. 5 that moves each component's
 * deviation toward the equilibrium its wind force sets (§4.2.1), and the fast animation algorithm
 * that turns the deviation into a pose-table coordinate and a bend azimuth (§4.2.2). The mode is
 * static, random or constraint (paper Table 7, {@link org.jecosys.anim.AnimationMode}).
 *
 * <p>{@link org.jecosys.anim.SpringKinds} holds the constants of every component kind and the
 * cached step coefficients; {@link org.jecosys.anim.AnimationState} holds the state of every
 * component in flat arrays and updates it, driven by an {@link org.jecosys.anim.AnimationStep};
 * {@link org.jecosys.anim.AnimationView} is its read-only face. The update allocates nothing and
 * its result does not depend on the frame rate or on how plants are split among worker threads
 * (§5.1): the simulation's workers animate disjoint ranges of plants, the stepping thread prepares
 * the coefficients between steps.
 */
package org.jecosys.anim;
