/**
 * Internal to the renderer (not API; it may change without notice; a game uses
 * {@code org.jecosys.render}). Overlays: the force field's nodes and wind of paper Figures 2 and 3 ({@link org.jecosys.render.overlay.FieldOverlay}) and the viewer's gizmos for flows and agents ({@link org.jecosys.render.overlay.GizmoRenderer}).
 * Render thread only, like everything that touches GL.
 */
package org.jecosys.render.overlay;
