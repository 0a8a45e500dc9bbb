package org.jecosys.anim;

import org.jecosys.math.Require;

/**
 * The constants that turn a component's deviation D into its outputs, and that mapping: per
 * component its rest lean {@code L = l (cos h, sin h)} (metres, world X and Z), the lean's size l, its
 * length, its pose scale {@code (K - 1) / maxBend} and its last pose coordinate {@code K - 1}. The
 * azimuth is the direction of {@code L + D}; the extra tip offset over the length is the sine of the
 * extra bend, mapped to a pose coordinate (paper §4.1-4.2; the derivation and the arc tangent
 * polynomial are in docs/model.md, "From deviation to pose").
 *
 * <p>A published {@code Frame} holds only D per component and computes pose coordinate and azimuth
 * through these on demand, with the arithmetic of {@link AnimationState#poseCoordinate} and
 * {@link AnimationState#azimuth}, bit for bit; a renderer uploads them once and does the same per
 * drawn component on the GPU.
 *
 * <p>Immutable after construction (which allocates); any thread may read it at once; the accessors
 * allocate nothing.
 */
public final class BendGeometry {
    final float[] leanX;
    final float[] leanZ;
    final float[] lean;
    final float[] length;
    final float[] scale;
    final float[] poseMax;

    /**
     * The geometry of components of the given kinds and rest headings. Build time; allocates.
     *
     * @param kinds         the component kinds
     * @param componentKind per component its kind, in [0, kinds.count())
     * @param restHeading   per component its rest heading h, radians (plant rest azimuth + slot azimuth)
     * @return the geometry
     * @throws IllegalArgumentException when the arrays differ in length or a kind is out of range
     */
    public static BendGeometry of(SpringKinds kinds, int[] componentKind, float[] restHeading) {
        Require.nonNull("kinds", kinds);
        if (componentKind.length != restHeading.length) {
            throw new IllegalArgumentException("componentKind and restHeading must have one value per component ("
                    + componentKind.length + " and " + restHeading.length + ")");
        }
        return new BendGeometry(kinds, componentKind, restHeading);
    }

    private BendGeometry(SpringKinds kinds, int[] componentKind, float[] restHeading) {
        int n = componentKind.length;
        leanX = new float[n];
        leanZ = new float[n];
        lean = new float[n];
        length = new float[n];
        scale = new float[n];
        poseMax = new float[n];
        for (int c = 0; c < n; c++) {
            int k = Require.elementRange("componentKind", c, componentKind[c], 0, kinds.count() - 1);
            double h = restHeading[c];
            leanX[c] = (float) (kinds.leanMag[k] * Math.cos(h));
            leanZ[c] = (float) (kinds.leanMag[k] * Math.sin(h));
            lean[c] = kinds.leanMag[k];
            length[c] = kinds.length[k];
            scale[c] = kinds.poseScale[k];
            poseMax[c] = kinds.poseMax[k];
        }
    }

    /** {@return the number of components} */
    public int componentCount() {
        return lean.length;
    }

    /**
     * {@return component c's rest lean, X part, metres}
     *
     * @param c component index
     */
    public float leanX(int c) {
        return leanX[c];
    }

    /**
     * {@return component c's rest lean, Z part, metres}
     *
     * @param c component index
     */
    public float leanZ(int c) {
        return leanZ[c];
    }

    /**
     * {@return component c's length, metres}
     *
     * @param c component index
     */
    public float length(int c) {
        return length[c];
    }

    /**
     * {@return component c's pose scale (K - 1) / maxBend, pose coordinates per radian of extra bend}
     *
     * @param c component index
     */
    public float poseScale(int c) {
        return scale[c];
    }

    /**
     * {@return component c's last pose coordinate K - 1}
     *
     * @param c component index
     */
    public float poseMax(int c) {
        return poseMax[c];
    }

    /**
     * {@return the pose coordinate of component c at deviation (dx, dz) metres, in [0, K - 1]}: the
     * arithmetic of {@link AnimationState#poseCoordinate}, bit for bit. No allocation.
     *
     * @param c  component index
     * @param dx deviation X, metres
     * @param dz deviation Z, metres
     */
    public float poseCoordinate(int c, float dx, float dz) {
        float tx = leanX[c] + dx;
        float tz = leanZ[c] + dz;
        float t = (float) Math.sqrt(tx * tx + tz * tz);
        float num = Math.max(0f, 2 * (leanX[c] * dx + leanZ[c] * dz) + dx * dx + dz * dz);
        float d = (t + lean[c]) * length[c];
        float u = Trig.poseArgument(num, (float) Math.sqrt(Math.max(0f, (d - num) * (d + num))));
        return Math.max(0f, Math.min(poseMax[c], Trig.poseAngle(u) * scale[c]));
    }

    /**
     * {@return the bend azimuth of component c at deviation (dx, dz) metres, radians in [-pi, pi]}:
     * the arithmetic of {@link AnimationState#azimuth}, bit for bit. No allocation.
     *
     * @param c  component index
     * @param dx deviation X, metres
     * @param dz deviation Z, metres
     */
    public float azimuth(int c, float dx, float dz) {
        float tx = leanX[c] + dx;
        float tz = leanZ[c] + dz;
        float t = (float) Math.sqrt(tx * tx + tz * tz);
        return Trig.azimuth(tz, Trig.azimuthArgument(tz, tx, t));
    }

    /**
     * Pose coordinates and azimuths of components {@code c0 .. c1-1} from their deviations into
     * {@code pose} and {@code azimuth} (indexed by component). No allocation.
     *
     * @param dev deviation per component, metres, packed ({@code SpringRuns.pack}: X's bits low, Z's high)
     */
    void outputs(int c0, int c1, long[] dev, float[] pose, float[] azimuth) {
        for (int c = c0; c < c1; c++) {
            float x = SpringRuns.unpackX(dev[c]);
            float z = SpringRuns.unpackZ(dev[c]);
            pose[c] = poseCoordinate(c, x, z);
            azimuth[c] = azimuth(c, x, z);
        }
    }

    /**
     * The deviation that shows component c at pose coordinate {@code pose} and bend azimuth
     * {@code azimuth} (the inverse of {@link #poseCoordinate} and {@link #azimuth}, to float
     * rounding): the tip at {@code T = (l + length sin(pose / scale)) (cos a, sin a)}, so
     * {@code D = T - L}. For tools and tests that pose components by hand. No allocation.
     *
     * @param c       component index
     * @param pose    pose coordinate, clamped to [0, K - 1]
     * @param azimuth bend azimuth, radians
     * @param out     receives D (X, Z), metres, at indices 0 and 1
     * @return out
     */
    public float[] deviationFor(int c, float pose, float azimuth, float[] out) {
        double bend = scale[c] > 0 ? Math.max(0f, Math.min(poseMax[c], pose)) / (double) scale[c] : 0;
        double t = lean[c] + length[c] * Math.sin(Math.min(bend, Math.PI / 2));
        out[0] = (float) (t * Math.cos(azimuth) - leanX[c]);
        out[1] = (float) (t * Math.sin(azimuth) - leanZ[c]);
        return out;
    }
}
