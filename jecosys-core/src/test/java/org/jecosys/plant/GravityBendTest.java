package org.jecosys.plant;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class GravityBendTest {
    private static final double EPS = 1e-12;

    private static double tipX(double[] angles, int n, double length) {
        double[] xy = new double[2 * (n + 1)];
        Skeleton.points(angles, n, length / n, xy);
        return xy[2 * n];
    }

    private static double[] solve(double width, double mass, double tipMass, double gravity) {
        double[] a = new double[8];
        GravityBend.solve(ComponentType.LEAF, 8, 0.4, width, 0.5 * width, 0.3, 0.2, mass, tipMass, gravity, a);
        return a;
    }

    @Test
    void noGravityLeavesRestShape() {
        double[] a = new double[6];
        GravityBend.solve(ComponentType.LEAF, 6, 0.5, 0.005, 0.001, 0.0, 0.0, 1e-3, 0, 0.0, a);
        for (int i = 0; i < 6; i++) {
            assertEquals(0.0, a[i], EPS, "straight, vertical");
        }
        double[] b = new double[6];
        GravityBend.solve(ComponentType.LEAF, 6, 0.5, 0.005, 0.001, 0.2, 0.6, 1e-3, 0, 0.0, b);
        double[] rest = new double[6];
        Skeleton.restAngles(6, 0.2, 0.6, rest);
        for (int i = 0; i < 6; i++) {
            assertEquals(rest[i], b[i], EPS, "own curvature only");
        }
    }

    @Test
    void negligibleMassLeavesRestShape() {
        double[] a = solve(0.005, 1e-12, 0, 9.81);
        double[] rest = new double[8];
        Skeleton.restAngles(8, 0.3, 0.2, rest);
        for (int i = 0; i < 8; i++) {
            assertEquals(rest[i], a[i], 1e-6);
        }
    }

    @Test
    void heavierBendsMore() {
        double light = tipX(solve(0.005, 2e-4, 0, 9.81), 8, 0.4);
        double heavy = tipX(solve(0.005, 8e-4, 0, 9.81), 8, 0.4);
        double heavier = tipX(solve(0.005, 8e-4, 1e-3, 9.81), 8, 0.4);
        assertTrue(heavy > light + 1e-3, "heavy " + heavy + " light " + light);
        assertTrue(heavier > heavy + 1e-3, "tip load " + heavier + " vs " + heavy);
    }

    @Test
    void thinnerBendsMore() {
        double wide = tipX(solve(0.010, 5e-4, 0, 9.81), 8, 0.4);
        double thin = tipX(solve(0.004, 5e-4, 0, 9.81), 8, 0.4);
        assertTrue(thin > wide + 1e-3, "thin " + thin + " wide " + wide);
    }

    @Test
    void stiffnessGrowsWithWidth() {
        for (ComponentType t : ComponentType.values()) {
            assertTrue(GravityBend.jointStiffness(t, 0.01, 0.05) > GravityBend.jointStiffness(t, 0.005, 0.05));
        }
    }

    @Test
    void gravityBendsTowardTheLean() {
        double[] rest = new double[8];
        Skeleton.restAngles(8, 0.3, 0.2, rest);
        assertTrue(tipX(solve(0.005, 5e-4, 0, 9.81), 8, 0.4) > tipX(rest, 8, 0.4));
    }

    @Test
    void verySoftChainHangsAtHorizontalButNotBelow() {
        double[] a = new double[10];
        GravityBend.solve(ComponentType.LEAF, 10, 2.0, 1e-6, 0, 0.5, 1.0, 5.0, 5.0, 9.81, a);
        for (int i = 0; i < 10; i++) {
            assertTrue(a[i] <= Skeleton.MAX_ANGLE && a[i] >= -Skeleton.MAX_ANGLE);
        }
        assertTrue(a[9] > 1.5, "soft chain droops to horizontal: " + a[9]);
    }

    @Test
    void rejectsBadArguments() {
        double[] a = new double[4];
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> GravityBend.solve(ComponentType.LEAF, 4, -1, 0.01, 0, 0, 0, 1e-3, 0, 9.81, a));
        assertTrue(e.getMessage().contains("length"));
        assertThrows(IllegalArgumentException.class,
                () -> GravityBend.solve(ComponentType.LEAF, 4, 1, 0.01, 0, 0, 0, 1e-3, 0, -1, a));
        assertThrows(IllegalArgumentException.class,
                () -> GravityBend.solve(ComponentType.LEAF, 8, 1, 0.01, 0, 0, 0, 1e-3, 0, 9.81, a));
    }
}
