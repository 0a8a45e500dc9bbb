/**
 * JEcoSys plants in a libGDX game (libGDX 1.13, LWJGL 3 backend, OpenGL 3.3 or a compatibility
 * profile that offers it): {@link org.jecosys.gdx.PlantLayer} steps the simulation in the game's
 * {@code render()} and draws the plants between its {@code ModelBatch} and {@code SpriteBatch} with
 * its {@code Camera} ({@link org.jecosys.gdx.GdxCamera}); {@link org.jecosys.gdx.PlantLayerLoader}
 * loads scene files through libGDX's {@code AssetManager}, reading and building on its loader thread
 * and making GL objects on the render thread; {@link org.jecosys.gdx.GdxScenes} reads a scene from a
 * {@code FileHandle}, its images from the scene's siblings.
 *
 * <p>The adapter is thin: nothing of libGDX reaches the library's core or renderer. The renderer
 * shares libGDX's context, draws into whatever framebuffer and viewport are bound and puts back
 * every GL state it changes. Threads: GL work on libGDX's render thread; simulation commands from
 * any thread. The per-frame calls allocate nothing.
 */
package org.jecosys.gdx;
