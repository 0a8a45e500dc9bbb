/**
 * The OpenGL 3.3 core renderer of JEcoSys scenes, through LWJGL 3: the lit terrain
 * ({@link org.jecosys.render.TerrainRenderer}), the plants drawn from the simulation's published
 * {@link org.jecosys.sim.Frame}s ({@link org.jecosys.render.PlantRenderer}: every pose table
 * uploaded once, one instanced draw per species and level of detail, triangles near and lines far,
 * dithered between levels; paper §4.1, §4.2.2 and Table 3), the force-field overlays of paper
 * Figures 2 and 3 ({@link org.jecosys.render.FieldOverlay}), gizmos for flows and agents and the
 * wind the plants feel, drawn in the 3D view ({@link org.jecosys.render.GizmoRenderer}), and the
 * whole frame
 * ({@link org.jecosys.render.SceneRenderer}, which puts back every GL state it changes, so it
 * composes with a game's own drawing). The GL-free parts that choose what is drawn
 * ({@link org.jecosys.render.PlantBatches}, which follows the frame's one decision) are tested
 * without a context; the per-component records the GPU resolves are read back and checked in tests.
 *
 * <p>Threads: everything that touches GL runs on the <em>render thread</em>, the one on which the
 * {@link org.jecosys.render.GlContext} was made or wrapped (a game's current context, a headless EGL
 * context or a window); it may differ from the simulation's stepping thread, and reads frames through
 * {@code Simulation.latestFrame()} (paper §5.1). Drawing a frame allocates nothing on the Java heap
 * in the steady state; GL objects are freed explicitly by {@code close()}, never by the garbage
 * collector. This module depends on no native libraries: the application chooses LWJGL's natives
 * for its platforms.
 */
package org.jecosys.render;
