/**
 * Internal to the renderer (not API; it may change without notice; a game uses
 * {@code org.jecosys.render}). The GL object wrappers (buffers, textures, programs, vertex arrays, framebuffers), each a small {@code AutoCloseable} counted by a {@link org.jecosys.render.gl.GlTracker}; the state discipline that makes the renderers good guests ({@link org.jecosys.render.gl.GlStateGuard}); pixel reads and PNG writing; allocation-free integer queries.
 * Render thread only, like everything that touches GL.
 */
package org.jecosys.render.gl;
