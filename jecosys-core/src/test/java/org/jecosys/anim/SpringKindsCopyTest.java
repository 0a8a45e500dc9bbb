package org.jecosys.anim;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

import org.junit.jupiter.api.Test;

/**
 * {@link SpringKinds#copy}: an open world's tiles each copy one prepared instance instead of building
 * and preparing their own. The copy must give what a fresh preparation gives, and preparing one must
 * not change the other.
 */
class SpringKindsCopyTest {
    private static SpringKinds kinds() {
        SpringKinds.Builder b = new SpringKinds.Builder();
        b.add(0.3, 0.5, 0.0005, 0.0025, 0.5, 0.05, 1.2, 16, 0b111);
        b.add(0.9, 0.45, 0.004, 0.005, 0.85, 0.01, 1.0, 12, 0b011);
        b.add(1.5, 0.25, 0.002, 0.0008, 0.012, 0.002, 0.6, 8, 0b001);
        return b.build();
    }

    private static float[] rows(SpringKinds k) {
        float[] all = new float[k.count() * SpringKinds.RESPONSE_VARIANTS * SpringKinds.STRIDE];
        for (int kind = 0; kind < k.count(); kind++) {
            for (int v = 0; v < SpringKinds.RESPONSE_VARIANTS; v++) {
                for (int i = 0; i < SpringKinds.STRIDE; i++) {
                    all[(kind * SpringKinds.RESPONSE_VARIANTS + v) * SpringKinds.STRIDE + i] = k.coefficient(kind, v, i);
                }
            }
        }
        return all;
    }

    @Test
    void aCopyHasTheCoefficientsAFreshPreparationGivesAndItsOwnPreparation() {
        SpringKinds template = kinds();
        template.prepare(1 / 60.0, 4, -1);
        SpringKinds copy = template.copy();
        SpringKinds fresh = kinds();
        fresh.prepare(1 / 60.0, 4, -1);
        assertArrayEquals(rows(fresh), rows(copy), "the copy's coefficients are a fresh preparation's");
        assertEquals(template.preparedStep(), copy.preparedStep());
        for (int k = 0; k < template.count(); k++) {
            assertEquals(fresh.restLean(k), copy.restLean(k));
            assertEquals(fresh.springClass(k), copy.springClass(k));
            assertEquals(fresh.bendLimit(k), copy.bendLimit(k));
        }
        // preparing the copy for another step leaves the template as it was, and the other way round
        float[] before = rows(template);
        copy.prepare(1 / 30.0, 2, 1);
        assertArrayEquals(before, rows(template), "preparing a copy changed its template");
        assertFalse(java.util.Arrays.equals(before, rows(copy)), "the copy was not prepared for its own step");
        SpringKinds other = kinds();
        other.prepare(1 / 30.0, 2, 1);
        assertArrayEquals(rows(other), rows(copy));
        template.prepare(1 / 144.0, 8, -1);
        assertArrayEquals(rows(other), rows(copy), "preparing the template changed its copy");
    }
}
