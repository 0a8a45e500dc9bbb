package org.jecosys.plant;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class ComponentMeshTest {
    @Test
    void countRules() {
        for (int n = 1; n <= 12; n++) {
            assertEquals(2 * n, ComponentMesh.primitiveCount(ComponentShape.STRIP, false, n, Primitive.TRIANGLES));
            assertEquals(2 * n - 1, ComponentMesh.primitiveCount(ComponentShape.STRIP, true, n, Primitive.TRIANGLES));
            assertEquals(2 * n + 1, ComponentMesh.primitiveCount(ComponentShape.STRIP, false, n, Primitive.LINES));
            assertEquals(2 * n, ComponentMesh.primitiveCount(ComponentShape.STRIP, true, n, Primitive.LINES));
            assertEquals(n, ComponentMesh.primitiveCount(ComponentShape.FAN, false, n, Primitive.TRIANGLES));
            assertEquals(n, ComponentMesh.primitiveCount(ComponentShape.FAN, false, n, Primitive.LINES));
        }
        assertEquals(0, ComponentMesh.primitiveCount(ComponentShape.STRIP, false, 0, Primitive.TRIANGLES));
    }

    @Test
    void builtMeshesMatchTheRulesAndAreValid() {
        for (ComponentShape shape : ComponentShape.values()) {
            for (boolean pointed : new boolean[] {false, true}) {
                for (Primitive prim : Primitive.values()) {
                    for (int segs = 1; segs <= 12; segs++) {
                        for (int n = 0; n <= segs; n++) {
                            ComponentMesh m = ComponentMesh.build(shape, pointed, segs, n, prim);
                            assertEquals(ComponentMesh.primitiveCount(shape, pointed, n, prim), m.primitiveCount());
                            int per = prim == Primitive.TRIANGLES ? 3 : 2;
                            for (int i = 0; i < m.indexCount(); i++) {
                                int v = m.index(i);
                                assertTrue(v >= 0 && v < m.vertexCount());
                                int p = m.vertexPoint(v);
                                assertTrue(p >= 0 && p <= segs);
                            }
                            if (shape == ComponentShape.STRIP || n >= 3) {
                                for (int f = 0; f < m.primitiveCount(); f++) {
                                    assertNotEquals(m.index(f * per), m.index(f * per + 1), "degenerate primitive");
                                    if (per == 3) {
                                        assertNotEquals(m.index(f * 3 + 1), m.index(f * 3 + 2), "degenerate triangle");
                                    }
                                }
                            }
                        }
                    }
                }
            }
        }
    }

    @Test
    void lodPointsKeepBaseAndTip() {
        assertArrayEquals(new int[] {0, 2, 3, 5}, ComponentMesh.lodPoints(ComponentShape.STRIP, 5, 3));
        assertArrayEquals(new int[] {0, 1, 2, 3, 4, 5}, ComponentMesh.lodPoints(ComponentShape.STRIP, 5, 5));
        assertArrayEquals(new int[] {0, 10}, ComponentMesh.lodPoints(ComponentShape.FAN, 10, 6));
        assertEquals(0, ComponentMesh.lodPoints(ComponentShape.STRIP, 5, 0).length);
    }

    @Test
    void pointedStripEndsInOneTipVertex() {
        ComponentMesh m = ComponentMesh.build(ComponentShape.STRIP, true, 4, 4, Primitive.TRIANGLES);
        int tip = m.vertexCount() - 1;
        assertEquals(4, m.vertexPoint(tip));
        assertEquals(0f, m.vertexA(tip), 0f);
        assertEquals(9, m.vertexCount());
    }
}
