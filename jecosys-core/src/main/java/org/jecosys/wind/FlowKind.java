package org.jecosys.wind;

/**
 * The kinds of flow a scene may declare (Wejchert &amp; Haumann's primitives, the paper's [11],
 * §3.2, plus gusts, blasts and rain). The XML element of each kind is {@link #xmlName()}.
 */
public enum FlowKind {
    /** Constant velocity U over the ground: strength is the speed (m/s), direction its heading. */
    UNIFORM("uniform"),
    /** u = (a / 2 pi) (p - c) / r^2 with a = strength &gt; 0 (m^2/s). */
    SOURCE("source"),
    /** A source with a = -strength (strength &gt; 0, m^2/s): flow toward the centre. */
    SINK("sink"),
    /** u = (Gamma / 2 pi) y x (p - c) / r^2 with Gamma = strength (m^2/s); positive turns counter-clockwise seen from above, negative clockwise. */
    VORTEX("vortex"),
    /** Turbulent wind: a mean speed (strength, m/s) along direction, modulated by seeded noise in space and time. */
    GUST("gust"),
    /** A short radial pulse, for explosions: a source of strength (m^2/s) that fades over its duration. */
    BLAST("blast"),
    /** Rain over a disc (influenceRadius): short seeded downward impulses seen as small radial bursts. */
    RAIN("rain");

    private final String xmlName;

    FlowKind(String xmlName) {
        this.xmlName = xmlName;
    }

    /** {@return the element name used in scene files, e.g. {@code "vortex"}} */
    public String xmlName() {
        return xmlName;
    }
}
