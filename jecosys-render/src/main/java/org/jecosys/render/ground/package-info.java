/**
 * Internal to the renderer (not API; it may change without notice; a game uses
 * {@code org.jecosys.render}). The ground: the lit terrain mesh with its contact darkening under the plants ({@link org.jecosys.render.ground.TerrainRenderer}, {@link org.jecosys.render.ground.ContactOcclusion}) and the sky ({@link org.jecosys.render.ground.SkyRenderer}).
 * Render thread only, like everything that touches GL.
 */
package org.jecosys.render.ground;
