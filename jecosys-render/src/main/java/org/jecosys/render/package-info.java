/**
 * The OpenGL renderer of JEcoSys scenes through LWJGL 3 (OpenGL 3.3 core, a faster resolve pass on
 * 4.3): what a game or tool uses. {@link org.jecosys.render.GlContext} wraps the host's current context
 * (or makes a headless or windowed one); {@link org.jecosys.render.SceneRenderer} draws the plants of a
 * simulation's published {@link org.jecosys.sim.Frame}s (every pose table uploaded once, one instanced
 * draw per species and level of detail, triangles near and lines far, dithered between levels; paper
 * §4.1, §4.2.2 and Table 3), optionally with the library's terrain and sky, into whatever framebuffer
 * and viewport are bound, for any camera: the frame's own decision for the camera its step followed,
 * a decision of its own for any other (split screen, minimaps, shadow passes, camera cuts);
 * {@link org.jecosys.render.RenderSettings} holds the look ({@code RenderSettings.of(scene)}), and
 * {@link org.jecosys.render.LwjglVersion} the LWJGL versions it runs on (3.3.3 and later).
 *
 * <p>The renderer is a good guest: its constructor, {@code render} and {@code close} leave every GL
 * state of the host as they found it, and {@code render} sets every state it depends on first. The
 * sub-packages are <em>internal</em>, public only so that this module's packages and the desktop viewer
 * can share them; a game does not need them and they may change without notice: {@code render.gl} (the
 * GL object wrappers and the state discipline), {@code render.plant} (the plant passes),
 * {@code render.ground} (terrain, sky, contact darkening) and {@code render.overlay} (force-field
 * overlays and the viewer's gizmos). They use nothing of this package but its context and settings
 * types, and {@code render.gl} uses no other.
 *
 * <p>Threads: everything that touches GL runs on the <em>render thread</em>, the one on which the
 * {@link org.jecosys.render.GlContext} was made or wrapped; it may differ from the simulation's
 * stepping thread, and reads frames through {@code Simulation.latestFrame()} (paper §5.1). Drawing a
 * frame allocates nothing on the Java heap in the steady state; GL objects are freed explicitly by
 * {@code close()}, never by the garbage collector. This module depends on no native libraries: the
 * application chooses LWJGL's natives for its platforms.
 */
package org.jecosys.render;
