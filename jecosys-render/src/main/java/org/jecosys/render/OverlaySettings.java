package org.jecosys.render;

/**
 * Which force-field overlays {@link SceneRenderer} draws over the picture, once a field is given
 * ({@link SceneRenderer#setField}): the quadtree's nodes (paper Figure 2) and the wind per effective
 * node (Figure 3). Both hidden by default; a scene's {@code <render showField showWind>} sets them
 * ({@link RenderSettings#of(org.jecosys.scene.RenderDef)}). Held by a {@link RenderSettings}
 * ({@link RenderSettings#overlays()}) and read every frame. Render thread only, as its settings;
 * no allocation.
 */
public final class OverlaySettings {
    private boolean showField;
    private boolean showWind;

    /** Both overlays hidden; {@link RenderSettings} makes its own. */
    OverlaySettings() {
    }

    /** {@return whether the force-field quadtree overlay (paper Figure 2) is drawn} */
    public boolean showField() {
        return showField;
    }

    /**
     * Shows or hides the quadtree overlay. No allocation.
     *
     * @param show true to draw it
     */
    public void setShowField(boolean show) {
        this.showField = show;
    }

    /** {@return whether the wind vectors per effective node (paper Figure 3) are drawn} */
    public boolean showWind() {
        return showWind;
    }

    /**
     * Shows or hides the wind vectors. No allocation.
     *
     * @param show true to draw them
     */
    public void setShowWind(boolean show) {
        this.showWind = show;
    }
}
