package org.jecosys.field;

import org.joml.Vector2d;

/**
 * The aerodynamic drag law turning the field's wind velocity into the force on a plant component
 * (the external force F_E of paper §4.2.1): quadratic drag
 * <pre>
 *   F = 0.5 * rho * dragArea * |u| * u
 * </pre>
 * with rho = {@link #AIR_DENSITY} (kg/m^3), {@code dragArea} = drag coefficient times frontal area
 * of the species' component (m^2) and u the wind velocity (m/s); F in newtons, in the direction of
 * u. Pure functions: any thread, no allocation.
 */
public final class DragLaw {
    /** Density of air at sea level and 15 degrees C, kg/m^3. */
    public static final double AIR_DENSITY = 1.225;

    private DragLaw() {
    }

    /**
     * Writes the drag force (N; x = X, y = Z) of wind (ux, uz) m/s on a body of {@code dragArea}
     * m^2 (Cd * A, &gt;= 0) into dest. No allocation.
     *
     * @param dragArea drag coefficient times frontal area, m^2, &gt;= 0
     * @param ux       wind X, m/s
     * @param uz       wind Z, m/s
     * @param dest     where to write the force, newtons
     * @return {@code dest}
     */
    public static Vector2d force(double dragArea, double ux, double uz, Vector2d dest) {
        double k = 0.5 * AIR_DENSITY * dragArea * Math.sqrt(ux * ux + uz * uz);
        return dest.set(k * ux, k * uz);
    }

    /**
     * The factor {@code 0.5 rho dragArea |u|} such that F = factor * u.
     *
     * @param dragArea drag coefficient times frontal area, m^2, &gt;= 0
     * @param speed    wind speed |u|, m/s
     * @return the factor, kg/s
     */
    public static double factor(double dragArea, double speed) {
        return 0.5 * AIR_DENSITY * dragArea * speed;
    }
}
