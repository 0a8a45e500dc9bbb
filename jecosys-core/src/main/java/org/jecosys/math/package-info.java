/**
 * Small shared foundations: the viewer ({@link org.jecosys.math.Camera}, with the convenient
 * {@link org.jecosys.math.ViewCamera} and the game-matrix {@link org.jecosys.math.MatrixCamera}) that
 * the force field culls and measures level-of-detail distances against (paper §3.1.1), its scene
 * definition {@link org.jecosys.math.CameraDef} and {@link org.jecosys.math.Waypoint}s, seeded
 * deterministic randomness ({@link org.jecosys.math.Rng}, {@link org.jecosys.math.Noise}), colours,
 * argument checks ({@link org.jecosys.math.Require}) and progress reporting.
 *
 * <p>Conventions used throughout JEcoSys: metres, seconds, kilograms and radians; Y is up and the
 * ground is the XZ plane; the same seed gives the same result on every JVM and for every thread
 * count. Depends on nothing of JEcoSys.
 */
package org.jecosys.math;
