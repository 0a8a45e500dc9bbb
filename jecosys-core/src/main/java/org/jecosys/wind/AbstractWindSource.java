package org.jecosys.wind;

import org.jecosys.math.Require;
import org.joml.Vector2d;

/**
 * The easy way to write a user {@link WindSource} (paper §3.2, §5.1's "framework interfaces"): it
 * holds the id, the enabled switch, a movable centre, an influence radius and an activation window
 * ({@link ActivationDef}), and applies them the way the built-in flows do; a subclass only gives its
 * formula at full strength, {@link #flow}. For example, a fan blowing along +X within 6 m:
 * <pre>{@code
 * final class Fan extends AbstractWindSource {
 *     Fan(double x, double z) {
 *         super("fan", x, z, 6, ActivationDef.ALWAYS);
 *     }
 *
 *     protected void flow(double x, double z, double time, Vector2d dest) {
 *         dest.set(4, 0); // 4 m/s along +X
 *     }
 * }
 * sim.addFlow(new Fan(0, 10));
 * }</pre>
 *
 * <p>{@link #velocity} returns 0 when the flow is disabled or outside its activation window, 0
 * beyond the influence radius (measured from the centre), and otherwise {@link #flow} times the
 * activation weight. The built-in flows extend it too (each applies its radius in its own formula).
 * Threads and allocation: see {@link WindSource}; nothing here allocates after construction, and
 * {@link #flow} must not allocate either.
 */
public abstract class AbstractWindSource implements WindSource {
    private final String id;
    private final ActivationDef activation;
    private final double influenceRadius;
    /** The influence radius squared, metres^2 (the built-in flows' formulas read it). */
    final double influenceRadius2;
    /** Whether {@link #velocity} returns 0 beyond the influence radius (the built-in flows do it themselves). */
    private final boolean clip;
    private boolean enabled;
    /** The centre, metres: the built-in flows' formulas read it, their paths and the wind's advection move it. */
    double cx;
    double cz;

    /**
     * An enabled flow centred on the origin, unbounded, always active. Allocates nothing else.
     *
     * @param id unique within the wind field, not empty
     * @throws IllegalArgumentException when the id is null or empty
     */
    protected AbstractWindSource(String id) {
        this(id, 0, 0, Double.POSITIVE_INFINITY, ActivationDef.ALWAYS);
    }

    /**
     * An enabled flow.
     *
     * @param id              unique within the wind field, not empty
     * @param x               centre X, metres, finite
     * @param z               centre Z, metres, finite
     * @param influenceRadius beyond this distance from the centre the flow is 0, metres, &gt; 0, or
     *                        +Infinity
     * @param activation      when it acts (weight ramps; {@link ActivationDef#ALWAYS} for always)
     * @throws IllegalArgumentException on a null or empty id, a non-finite centre, a radius &le; 0 or
     *                                  a null activation
     */
    protected AbstractWindSource(String id, double x, double z, double influenceRadius, ActivationDef activation) {
        this.id = Require.nonNull("id", id);
        if (id.isEmpty()) {
            throw new IllegalArgumentException("id must not be empty");
        }
        this.cx = Require.finite("x", x);
        this.cz = Require.finite("z", z);
        this.influenceRadius = Require.positiveOrInfinite("influenceRadius", influenceRadius);
        this.influenceRadius2 = influenceRadius == Double.POSITIVE_INFINITY ? Double.POSITIVE_INFINITY
                : influenceRadius * influenceRadius;
        this.activation = Require.nonNull("activation", activation);
        this.clip = true;
        this.enabled = true;
    }

    /**
     * A built-in flow ({@link FlowBase}) of a checked definition, centred at (x, z) (its path's start
     * when it has one), enabled as defined, its influence radius applied by its own formula.
     */
    AbstractWindSource(FlowDef def, double x, double z) {
        this.id = def.id();
        this.cx = x;
        this.cz = z;
        this.influenceRadius = def.influenceRadius();
        this.influenceRadius2 = influenceRadius == Double.POSITIVE_INFINITY ? Double.POSITIVE_INFINITY
                : influenceRadius * influenceRadius;
        this.activation = def.activation();
        this.clip = false;
        this.enabled = def.enabled();
    }

    /**
     * The flow's own velocity at full strength at ground point (x, z), m/s, written into dest
     * (x = X, y = Z). Called by {@link #velocity} only inside the influence radius and while the
     * weight is above 0. Owner thread; must be finite and must not allocate.
     *
     * @param x    ground X, metres
     * @param z    ground Z, metres
     * @param time simulation time, seconds
     * @param dest where to write (its previous content is undefined)
     */
    protected abstract void flow(double x, double z, double time, Vector2d dest);

    @Override
    public final String id() {
        return id;
    }

    /**
     * The activation window given at construction.
     *
     * @return the activation, not null
     */
    public final ActivationDef activation() {
        return activation;
    }

    @Override
    public final boolean isEnabled() {
        return enabled;
    }

    @Override
    public final void setEnabled(boolean enabled) {
        this.enabled = enabled;
    }

    @Override
    public final double centreX() {
        return cx;
    }

    @Override
    public final double centreZ() {
        return cz;
    }

    @Override
    public final void setCentre(double x, double z) {
        cx = Require.finite("x", x);
        cz = Require.finite("z", z);
    }

    @Override
    public final double influenceRadius() {
        return influenceRadius;
    }

    @Override
    public final double weight(double time) {
        return enabled ? activation.weight(time) : 0;
    }

    @Override
    public final boolean expired(double time) {
        return activation.expired(time);
    }

    @Override
    public final Vector2d velocity(double x, double z, double time, Vector2d dest) {
        double w = weight(time);
        if (w == 0) {
            return dest.set(0, 0);
        }
        if (clip) {
            double dx = x - cx;
            double dz = z - cz;
            if (dx * dx + dz * dz > influenceRadius2) {
                return dest.set(0, 0);
            }
        }
        flow(x, z, time, dest);
        return dest.set(dest.x * w, dest.y * w);
    }
}
