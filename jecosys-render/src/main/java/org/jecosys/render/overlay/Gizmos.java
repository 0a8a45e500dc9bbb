package org.jecosys.render.overlay;

import java.util.Arrays;
import org.jecosys.math.Require;

/**
 * The gizmos {@link GizmoRenderer} draws in one frame: per gizmo a {@link GizmoKind}, a centre on the
 * ground (metres), an influence radius and a core radius (metres), a direction (radians from +X
 * toward +Z, for uniform and gust flows), a spin (+1 or -1 for a vortex), the activation weight and
 * switch, and a highlight. Filled by the application every frame ({@link #clear()} then
 * {@link #add}); reused, so it allocates only when it grows past its capacity.
 *
 * <p>The spin is the sense of a vortex as the wind package defines it: +1 turns the way of
 * {@code y x (p - c)}, counter-clockwise seen from above with north (-Z) up; -1 the other way.
 * Render thread (or whichever single thread fills and draws it); not thread-safe.
 */
public final class Gizmos {
    /** No highlight. */
    public static final int NORMAL = 0;
    /** The pointer is over the gizmo. */
    public static final int HOVERED = 1;
    /** The gizmo is selected (or being dragged). */
    public static final int SELECTED = 2;

    private GizmoKind[] kind = new GizmoKind[16];
    private double[] x = new double[16];
    private double[] z = new double[16];
    private double[] radius = new double[16];
    private double[] core = new double[16];
    private double[] direction = new double[16];
    private int[] spin = new int[16];
    private double[] weight = new double[16];
    private boolean[] enabled = new boolean[16];
    private int[] highlight = new int[16];
    private int size;

    /** An empty list with room for 16 gizmos. Allocates. */
    public Gizmos() {
    }

    /** Removes every gizmo; keeps the storage. No allocation. */
    public void clear() {
        size = 0;
    }

    /** {@return the number of gizmos} */
    public int size() {
        return size;
    }

    /**
     * Adds a gizmo, enabled, fully active, without direction, spin or highlight (see the setters).
     * Allocates only when the list grows past its capacity.
     *
     * @param kind            what it shows, not null
     * @param x               centre X, metres, finite
     * @param z               centre Z, metres, finite
     * @param influenceRadius radius of the influence ring, metres, &gt; 0, or +Infinity for none
     * @param coreRadius      radius of the core ring, metres, &ge; 0 (0: none)
     * @return the gizmo's index, for the setters
     * @throws IllegalArgumentException when a value is out of range
     */
    public int add(GizmoKind kind, double x, double z, double influenceRadius, double coreRadius) {
        Require.nonNull("kind", kind);
        Require.finite("x", x);
        Require.finite("z", z);
        Require.positiveOrInfinite("influenceRadius", influenceRadius);
        Require.nonNegative("coreRadius", coreRadius);
        if (size == this.kind.length) {
            grow();
        }
        int i = size++;
        this.kind[i] = kind;
        this.x[i] = x;
        this.z[i] = z;
        this.radius[i] = influenceRadius;
        this.core[i] = coreRadius;
        this.direction[i] = 0;
        this.spin[i] = 0;
        this.weight[i] = 1;
        this.enabled[i] = true;
        this.highlight[i] = NORMAL;
        return i;
    }

    private void grow() {
        int n = kind.length * 2;
        kind = Arrays.copyOf(kind, n);
        x = Arrays.copyOf(x, n);
        z = Arrays.copyOf(z, n);
        radius = Arrays.copyOf(radius, n);
        core = Arrays.copyOf(core, n);
        direction = Arrays.copyOf(direction, n);
        spin = Arrays.copyOf(spin, n);
        weight = Arrays.copyOf(weight, n);
        enabled = Arrays.copyOf(enabled, n);
        highlight = Arrays.copyOf(highlight, n);
    }

    /**
     * Sets the direction a uniform or gust gizmo points. No allocation.
     *
     * @param i       gizmo index, in [0, size())
     * @param radians heading, 0 is +X, pi/2 is +Z (finite)
     */
    public void direction(int i, double radians) {
        direction[check(i)] = Require.finite("radians", radians);
    }

    /**
     * Sets the sense of rotation a vortex gizmo shows (see the class comment). No allocation.
     *
     * @param i    gizmo index, in [0, size())
     * @param spin +1, -1, or 0 for none
     */
    public void spin(int i, int spin) {
        this.spin[check(i)] = Integer.signum(spin);
    }

    /**
     * Sets the activation state the gizmo's colour shows: full colour when enabled and fully active,
     * fainter as the activation weight falls, grey when switched off. No allocation.
     *
     * @param i       gizmo index, in [0, size())
     * @param enabled the flow's switch
     * @param weight  activation weight now, clamped to [0, 1]
     */
    public void state(int i, boolean enabled, double weight) {
        this.enabled[check(i)] = enabled;
        this.weight[i] = Double.isNaN(weight) ? 0 : Math.max(0, Math.min(1, weight));
    }

    /**
     * Sets the highlight. No allocation.
     *
     * @param i         gizmo index, in [0, size())
     * @param highlight {@link #NORMAL}, {@link #HOVERED} or {@link #SELECTED}
     */
    public void highlight(int i, int highlight) {
        this.highlight[check(i)] = Require.range("highlight", highlight, NORMAL, SELECTED);
    }

    /**
     * {@return the kind of gizmo i}
     *
     * @param i gizmo index, in [0, size())
     */
    public GizmoKind kind(int i) {
        return kind[check(i)];
    }

    /**
     * {@return centre X of gizmo i, metres}
     *
     * @param i gizmo index, in [0, size())
     */
    public double x(int i) {
        return x[check(i)];
    }

    /**
     * {@return centre Z of gizmo i, metres}
     *
     * @param i gizmo index, in [0, size())
     */
    public double z(int i) {
        return z[check(i)];
    }

    /**
     * {@return influence radius of gizmo i, metres, or +Infinity}
     *
     * @param i gizmo index, in [0, size())
     */
    public double influenceRadius(int i) {
        return radius[check(i)];
    }

    /**
     * {@return core radius of gizmo i, metres (0: none)}
     *
     * @param i gizmo index, in [0, size())
     */
    public double coreRadius(int i) {
        return core[check(i)];
    }

    /**
     * {@return direction of gizmo i, radians from +X toward +Z}
     *
     * @param i gizmo index, in [0, size())
     */
    public double direction(int i) {
        return direction[check(i)];
    }

    /**
     * {@return spin of gizmo i: +1, -1 or 0}
     *
     * @param i gizmo index, in [0, size())
     */
    public int spin(int i) {
        return spin[check(i)];
    }

    /**
     * {@return whether gizmo i's flow is switched on}
     *
     * @param i gizmo index, in [0, size())
     */
    public boolean enabled(int i) {
        return enabled[check(i)];
    }

    /**
     * {@return the activation weight of gizmo i, in [0, 1]}
     *
     * @param i gizmo index, in [0, size())
     */
    public double weight(int i) {
        return weight[check(i)];
    }

    /**
     * {@return the highlight of gizmo i}
     *
     * @param i gizmo index, in [0, size())
     */
    public int highlight(int i) {
        return highlight[check(i)];
    }

    private int check(int i) {
        if (i < 0 || i >= size) {
            throw new IndexOutOfBoundsException("gizmo " + i + " of " + size);
        }
        return i;
    }
}
