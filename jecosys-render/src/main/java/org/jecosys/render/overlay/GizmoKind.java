package org.jecosys.render.overlay;

/**
 * What a gizmo of {@link GizmoRenderer} shows, and its colour. The render module does not see the
 * wind package, so the application maps each flow (paper §3.2: uniform, source, sink, vortex, gust,
 * blast, rain, or a game's own flow) and each agent to one of these. Any thread; immutable.
 */
public enum GizmoKind {
    /** A uniform flow: an arrow along its direction. */
    UNIFORM(0.15f, 0.55f, 1.00f),
    /** A gusty uniform flow: an arrow with chevrons along its mean direction. */
    GUST(0.00f, 0.90f, 0.80f),
    /** A source: arrows pointing away from the centre. */
    SOURCE(1.00f, 0.55f, 0.00f),
    /** A sink: arrows pointing toward the centre. */
    SINK(0.60f, 0.30f, 1.00f),
    /** A vortex: arrows along a circle in its sense of rotation (the spin). */
    VORTEX(1.00f, 0.15f, 0.75f),
    /** A blast: short arrows pointing away from the centre. */
    BLAST(1.00f, 0.10f, 0.10f),
    /** A rain shower: its disc. */
    RAIN(0.55f, 0.80f, 1.00f),
    /** A game's own flow, whose formula the viewer does not know: the centre and radius only. */
    USER(0.85f, 0.85f, 0.85f),
    /** An agent (a flow a game or the user moves, e.g. a walker pushing plants): outward arrows. */
    AGENT(1.00f, 0.95f, 0.10f);

    private final float red;
    private final float green;
    private final float blue;

    GizmoKind(float red, float green, float blue) {
        this.red = red;
        this.green = green;
        this.blue = blue;
    }

    /** {@return the red component of the gizmo's colour when fully active, in [0, 1] (linear, as written to the framebuffer)} */
    public float red() {
        return red;
    }

    /** {@return the green component of the gizmo's colour when fully active, in [0, 1]} */
    public float green() {
        return green;
    }

    /** {@return the blue component of the gizmo's colour when fully active, in [0, 1]} */
    public float blue() {
        return blue;
    }
}
