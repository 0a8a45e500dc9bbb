package org.jecosys.field;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.jecosys.math.Rng;
import org.junit.jupiter.api.Test;

class QuadtreeTest {

    static Quadtree randomTree(int n, int maxObjects, int maxDepth, long seed) {
        Quadtree t = new Quadtree(-50, -30, 70, 90, maxObjects, maxDepth, n);
        Rng rng = new Rng(seed);
        for (int i = 0; i < n; i++) {
            // a clustered distribution: half uniform, half around a hot spot
            double x = i % 2 == 0 ? rng.nextDouble(-50, 70) : 10 + rng.nextGaussian() * 3;
            double z = i % 2 == 0 ? rng.nextDouble(-30, 90) : 20 + rng.nextGaussian() * 3;
            t.insert(x, z);
        }
        return t;
    }

    static void checkInvariants(Quadtree t) {
        int[] seen = new int[t.plantCount()];
        int leaves = 0;
        for (int n = 0; n < t.nodeCount(); n++) {
            int fc = t.firstChild(n);
            if (fc < 0) {
                leaves++;
                int c = 0;
                double sx = 0;
                for (int p = t.firstPlant(n); p >= 0; p = t.nextPlant(p)) {
                    seen[p]++;
                    c++;
                    sx += t.plantX(p);
                    assertEquals(n, t.leafOf(p), "leafOf");
                    assertTrue(t.plantX(p) >= t.minX(n) && t.plantX(p) <= t.maxX(n), "plant inside its leaf (x)");
                    assertTrue(t.plantZ(p) >= t.minZ(n) && t.plantZ(p) <= t.maxZ(n), "plant inside its leaf (z)");
                }
                assertEquals(c, t.plantsIn(n));
                assertEquals(0, t.height(n));
                if (c > 0) {
                    assertEquals(sx / c, t.centroidX(n), 1e-6);
                }
                if (t.depth(n) < t.maxDepth()) {
                    assertTrue(c <= t.maxObjectsPerNode(), "capacity above max depth: " + c);
                }
            } else {
                double area = (double) (t.maxX(n) - t.minX(n)) * (t.maxZ(n) - t.minZ(n));
                int sum = 0;
                int h = 0;
                for (int k = 0; k < 4; k++) {
                    int ch = fc + k;
                    assertEquals(n, t.parent(ch));
                    assertEquals(t.depth(n) + 1, t.depth(ch));
                    double ca = (double) (t.maxX(ch) - t.minX(ch)) * (t.maxZ(ch) - t.minZ(ch));
                    assertEquals(area / 4, ca, area * 1e-6, "child covers a quarter of its parent");
                    assertTrue(t.minX(ch) >= t.minX(n) && t.maxX(ch) <= t.maxX(n));
                    assertTrue(t.minZ(ch) >= t.minZ(n) && t.maxZ(ch) <= t.maxZ(n));
                    sum += t.plantsIn(ch);
                    h = Math.max(h, t.height(ch) + 1);
                }
                assertEquals(t.plantsIn(n), sum, "subtree counts");
                assertEquals(h, t.height(n), "height");
                assertEquals(-1, t.firstPlant(n), "internal nodes hold no plants");
            }
        }
        assertEquals(leaves, t.leafCount());
        for (int p = 0; p < seen.length; p++) {
            assertEquals(1, seen[p], "plant " + p + " in exactly one leaf");
        }
    }

    @Test
    void invariantsHoldAfterBuild() {
        Quadtree t = randomTree(20_000, 8, 10, 1);
        checkInvariants(t);
        assertTrue(t.nodeCount() > 100);
        assertEquals(0, t.depth(0));
        assertEquals(-1, t.parent(0));
    }

    @Test
    void maxDepthBoundsTheTreeAndOverfullLeavesSitThere() {
        Quadtree t = new Quadtree(0, 0, 10, 10, 2, 5, 0);
        for (int i = 0; i < 50; i++) {
            t.insert(3.3, 3.3);
        }
        checkInvariants(t);
        int leaf = t.leafOf(0);
        assertEquals(5, t.depth(leaf));
        assertEquals(50, t.plantsIn(leaf));
        for (int n = 0; n < t.nodeCount(); n++) {
            assertTrue(t.depth(n) <= 5);
        }
    }

    @Test
    void insertingAfterTheBuildGivesTheSameTreeAsBuildingWithIt() {
        int n = 5000;
        Quadtree all = randomTree(n, 4, 9, 7);
        Quadtree part = new Quadtree(-50, -30, 70, 90, 4, 9, n / 2);
        Quadtree growing = new Quadtree(-50, -30, 70, 90, 4, 9, 0);
        for (int i = 0; i < n; i++) {
            if (i < n / 2) {
                part.insert(all.plantX(i), all.plantZ(i));
            }
            growing.insert(all.plantX(i), all.plantZ(i));
        }
        for (int i = n / 2; i < n; i++) {
            part.insert(all.plantX(i), all.plantZ(i));
        }
        for (Quadtree t : new Quadtree[] {part, growing}) {
            assertEquals(all.nodeCount(), t.nodeCount());
            assertEquals(all.leafCount(), t.leafCount());
            assertArrayEquals(java.util.Arrays.copyOf(all.leafOf, n), java.util.Arrays.copyOf(t.leafOf, n));
            for (int k = 0; k < all.nodeCount(); k++) {
                assertEquals(all.firstChild(k), t.firstChild(k));
                assertEquals(all.minX(k), t.minX(k));
                assertEquals(all.maxZ(k), t.maxZ(k));
                assertEquals(all.plantsIn(k), t.plantsIn(k));
            }
            checkInvariants(t);
        }
    }

    @Test
    void movedObjectsAreRelocated() {
        Quadtree t = randomTree(3000, 4, 8, 3);
        Rng rng = new Rng(11);
        for (int k = 0; k < 2000; k++) {
            int p = rng.nextInt(t.plantCount());
            t.move(p, t.plantX(p) + rng.nextGaussian() * 10, t.plantZ(p) + rng.nextGaussian() * 10);
        }
        t.move(0, 1e6, -1e6); // clamped into the bounds
        assertEquals(70, t.plantX(0), 0);
        assertEquals(-30, t.plantZ(0), 0);
        checkInvariants(t);
        assertEquals(3000, t.plantsIn(0));
    }

    @Test
    void rejectsPlantsOutsideTheBoundsAndBadSettings() {
        Quadtree t = new Quadtree(0, 0, 10, 10, 2, 5, 0);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> t.insert(11, 5));
        assertTrue(e.getMessage().startsWith("x must be in"));
        assertThrows(IllegalArgumentException.class, () -> new Quadtree(0, 0, 0, 10, 2, 5, 0));
        assertThrows(IllegalArgumentException.class, () -> new Quadtree(0, 0, 10, 10, 0, 5, 0));
        assertThrows(IllegalArgumentException.class, () -> new Quadtree(0, 0, 10, 10, 1, 17, 0));
    }
}
