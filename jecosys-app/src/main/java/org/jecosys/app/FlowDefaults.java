package org.jecosys.app;

import java.util.List;
import org.jecosys.terrain.Heightfield;
import org.jecosys.wind.FlowDef;
import org.jecosys.wind.FlowKind;
import org.jecosys.wind.WindSource;
import org.joml.Vector2d;

/**
 * Strength and radii for a flow added at the cursor, scaled to the scene so that its effect shows at
 * once (issue: flows added at the old defaults, strength 4 m^2/s and radius 3 m, made no visible
 * difference on the 80 m meadow; a source of 4 m^2/s blows 0.4 m/s at 1.5 m).
 *
 * <ul>
 * <li>influence radius: a tenth of the terrain's smaller side (8 m on the meadow, 0.4 m on the
 *     rose), at least 0.25 m; core radius an eighth of it;</li>
 * <li>strength: the one at which the flow blows {@link #targetSpeed} at half its influence radius,
 *     measured with the flow's own velocity formula (paper §3.2) so it stays right if the formula
 *     changes; that speed is 1.5 times the scene's own uniform and gust wind together, at least
 *     {@link #MIN_SPEED} m/s, so a new flow stands out against the breeze already blowing.</li>
 * </ul>
 * Values are rounded (radii to the centimetre, strengths to two significant digits) so a saved scene
 * reads them plainly. Pure; any thread; allocates.
 */
final class FlowDefaults {
    /** Lowest target speed at half the radius, m/s. */
    static final double MIN_SPEED = 4;

    private final double radius;
    private final double core;
    private final double speed;

    private FlowDefaults(double radius, double core, double speed) {
        this.radius = radius;
        this.core = core;
        this.speed = speed;
    }

    /**
     * The defaults for a terrain and the scene's flows.
     *
     * @param ground the terrain
     * @param flows  the scene's flows (their enabled uniform and gust strengths set the target speed)
     * @return the defaults
     */
    static FlowDefaults of(Heightfield ground, List<FlowDef> flows) {
        double r = Math.max(0.25, Decimals.round(0.1 * Math.min(ground.sizeX(), ground.sizeZ()), 2));
        double c = Math.max(0.01, Decimals.round(r / 8, 2));
        double wind = 0;
        for (FlowDef f : flows) {
            if (f.enabled() && (f.kind() == FlowKind.UNIFORM || f.kind() == FlowKind.GUST)) {
                wind += f.strength();
            }
        }
        double speed = Decimals.significant(Math.max(MIN_SPEED, 1.5 * wind), 2);
        return new FlowDefaults(r, c, speed);
    }

    /** {@return the influence radius, metres} */
    double radius() {
        return radius;
    }

    /** {@return the core radius, metres} */
    double coreRadius() {
        return core;
    }

    /** {@return the wind speed a new flow blows at half its influence radius, m/s} */
    double targetSpeed() {
        return speed;
    }

    /**
     * The strength at which a flow of {@code kind} with these radii blows {@link #targetSpeed()} at
     * half the radius ({@code radius}: the influence radius to use, metres): m/s for UNIFORM and GUST,
     * m^2/s for the others; two significant digits.
     *
     * @param kind   the flow's kind
     * @param radius the influence radius the flow will have, metres, &gt; 0
     * @return the strength, &gt; 0
     */
    double strength(FlowKind kind, double radius) {
        if (kind == FlowKind.UNIFORM || kind == FlowKind.GUST) {
            return speed;
        }
        // the flow's own formula at unit strength, half-way out (RAIN: its bursts are short; use the source law)
        FlowKind probe = kind == FlowKind.RAIN || kind == FlowKind.BLAST ? FlowKind.SOURCE : kind;
        double core = Math.min(this.core, radius / 4);
        FlowDef unit = FlowDef.builder("probe", probe).strength(1).coreRadius(core).influenceRadius(radius).build();
        Vector2d v = WindSource.of(unit).velocity(radius / 2, 0, 0, new Vector2d());
        double perUnit = v.length();
        if (!(perUnit > 0)) {
            return speed;
        }
        return Decimals.significant(speed / perUnit, 2);
    }
}
