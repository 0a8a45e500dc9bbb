/**
 * Internal to the renderer (not API; it may change without notice; a game uses
 * {@code org.jecosys.render}): access to the parts a {@link org.jecosys.render.SceneRenderer}
 * composes, for the application's benchmark and the tests. Not exported by the module.
 */
package org.jecosys.render.internal;
