package org.jecosys.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.jecosys.render.gl.GlProgram;

/** How shader sources are put together before the driver sees them: includes and variants' defines (no GL). */
class GlProgramSourceTest {
    @Test
    void definesGoRightAfterTheVersionLineAndIncludesAreExpanded() {
        String plain = GlProgram.source("plant_line.vert");
        String variant = GlProgram.variantSource("plant_line.vert", "DITHER", "FLOWERS");
        assertTrue(plain.startsWith("#version 330 core\n"));
        assertFalse(plain.contains("\n#include"), "includes expanded");
        assertTrue(plain.contains("vec3 rotY(vec3 v, float c, float s)"), "plant_common.glsl is in");
        assertTrue(variant.startsWith("#version 330 core\n#define DITHER\n#define FLOWERS\n"), variant.substring(0, 60));
        assertEquals(plain, variant.replace("#define DITHER\n#define FLOWERS\n", ""), "nothing else changes");
        assertEquals(plain, GlProgram.variantSource("plant_line.vert"), "no defines: the plain source");
    }

    @Test
    void aDefineMustBeAnIdentifier() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> GlProgram.variant(null, "plant.vert", "plant.frag", "DITHER 1"));
        assertTrue(e.getMessage().contains("'DITHER 1'"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> GlProgram.variant(null, "plant.vert", "plant.frag", "9X"));
    }
}
