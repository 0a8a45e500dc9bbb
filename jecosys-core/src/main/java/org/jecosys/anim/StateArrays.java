package org.jecosys.anim;

import org.jecosys.math.Require;

/**
 * The per-plant and per-component arrays an {@link AnimationState} is built from: the checks of its
 * constructor (counts, first components that do not decrease, kinds and response variants in range,
 * compliances), the copies it keeps of kinds, response variants and compliances, and the search from
 * a component to its plant over the first components ({@link AnimationState#plantOf}). The checks
 * run at build time and allocate; the search is for any thread and allocates nothing.
 */
final class StateArrays {
    private StateArrays() {
    }

    /**
     * Checks the counts of the plant and component arrays against each other: per plant one
     * {@code firstComponent} (plus the total at the end) and one X, Y and Z; the bend geometry and
     * {@code firstComponent[plants]} must match the components.
     *
     * @return the number of components, {@code componentKind.length}
     * @throws IllegalArgumentException when a count does not match
     */
    static int components(int plants, int[] firstComponent, float[] plantX, float[] plantY, float[] plantZ,
                          int[] componentKind, BendGeometry geometry) {
        if (firstComponent.length != plants + 1 || plantX.length != plants || plantY.length != plants
                || plantZ.length != plants) {
            throw new IllegalArgumentException("firstComponent must hold plants + 1 = " + (plants + 1)
                    + " values and plantX/Y/Z plants = " + plants);
        }
        int components = componentKind.length;
        if (geometry.componentCount() != components || firstComponent[plants] != components) {
            throw new IllegalArgumentException("the bend geometry and firstComponent[plants] must match the "
                    + components + " components");
        }
        return components;
    }

    /**
     * Checks that {@code firstComponent} does not decrease over the plants.
     *
     * @throws IllegalArgumentException at the first plant whose next first component is smaller
     */
    static void checkAscending(int[] firstComponent, int plants) {
        for (int p = 0; p < plants; p++) {
            if (firstComponent[p + 1] < firstComponent[p]) {
                throw new IllegalArgumentException("firstComponent must not decrease, at plant " + p);
            }
        }
    }

    /**
     * {@return per component its kind, checked to be one of the kinds}
     *
     * @throws IllegalArgumentException at the first kind out of range
     */
    static short[] kinds(SpringKinds kinds, int[] componentKind) {
        short[] kind = new short[componentKind.length];
        for (int c = 0; c < kind.length; c++) {
            kind[c] = (short) Require.elementRange("componentKind", c, componentKind[c], 0, kinds.count() - 1);
        }
        return kind;
    }

    /**
     * Checks and copies the plants' variation into {@code plantResponse} and {@code plantCompliance}
     * (one entry per plant): per plant its response variant, in [0, {@link SpringKinds#RESPONSE_VARIANTS}),
     * or {@link SpringKinds#NOMINAL_VARIANT} where {@code response} is null, and its compliance, in
     * [0.5, 10], or 1 where {@code compliance} is null. Plant by plant, its response before its compliance.
     *
     * @throws IllegalArgumentException when an array does not hold one value per plant or a value is out
     *                                  of range
     */
    static void variation(byte[] response, float[] compliance, byte[] plantResponse, float[] plantCompliance) {
        int plants = plantResponse.length;
        if ((response != null && response.length != plants) || (compliance != null && compliance.length != plants)) {
            throw new IllegalArgumentException("response and compliance must hold one value per plant (" + plants
                    + ")");
        }
        for (int p = 0; p < plants; p++) {
            plantResponse[p] = (byte) (response == null ? SpringKinds.NOMINAL_VARIANT
                    : Require.elementRange("response", p, response[p], 0, SpringKinds.RESPONSE_VARIANTS - 1));
            plantCompliance[p] = compliance == null ? 1f
                    : (float) Require.elementRange("compliance", p, compliance[p], 0.5, 10);
        }
    }

    /**
     * The plant of component c: the last of the {@code plants} plants whose first component is at
     * most c (binary search; not for per-frame use on every component). No allocation.
     */
    static int plantOf(int[] firstComponent, int plants, int c) {
        int lo = 0;
        int hi = plants - 1;
        while (lo < hi) {
            int mid = (lo + hi + 1) >>> 1;
            if (firstComponent[mid] <= c) {
                lo = mid;
            } else {
                hi = mid - 1;
            }
        }
        return lo;
    }
}
