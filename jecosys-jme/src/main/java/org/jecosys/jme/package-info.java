/**
 * JEcoSys plants in a jMonkeyEngine 3 application (jME 3.7, jme3-lwjgl3, core or compatibility
 * profile with OpenGL 3.3): {@link org.jecosys.jme.PlantAppState} steps the simulation in its
 * {@code update(tpf)} and draws the plants in the main viewport with jME's camera
 * ({@link org.jecosys.jme.JmeCamera}); {@link org.jecosys.jme.SceneAssetLoader} and
 * {@link org.jecosys.jme.SceneKey} load scene files through jME's {@code AssetManager}, their images
 * from the scene's folder.
 *
 * <p>The adapter is thin: nothing of jME reaches the library's core or renderer. The renderer shares
 * jME's context, draws into the viewport's framebuffer and puts back every GL state it changes.
 * Threads: jME's render thread for everything jME calls; simulation commands from any thread. The
 * per-frame calls allocate nothing.
 */
package org.jecosys.jme;
