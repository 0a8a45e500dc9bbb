package org.jecosys.anim;

/**
 * The bend outputs of {@link AnimationState}: a component's pose coordinate and bend azimuth as a
 * pure function of its deviation D and its constants (see "Bend" in {@link AnimationState}), in the
 * vectorisable output loops and in the scalar form of the accessors. Static methods over the
 * caller's flat arrays, all indexed by component, so the loops read the arrays directly with no extra
 * indirection. Any thread that owns the range written; no allocation.
 */
final class BendOutputs {
    /** Components per block of the output loops. */
    private static final int BLOCK = 1024;

    private BendOutputs() {
    }

    /**
     * Pose coordinate and azimuth of components {@code c0 .. c1-1} from their deviations into
     * {@code pose} and {@code azimuth} (indexed by component), in blocks of {@value #BLOCK}. Each block
     * runs five short branch-free loops over arrays indexed by c only (C2 unrolls and vectorises loops
     * only below a body size, which one fused loop exceeds); intermediates live in the destination
     * arrays. The same arithmetic as {@link #poseCoordinate} and {@link #azimuth}, so a component's
     * outputs depend on its D alone.
     *
     * @param devX    deviation X per component, metres
     * @param devZ    deviation Z per component, metres
     * @param leanX   rest lean X per component, metres
     * @param leanZ   rest lean Z per component, metres
     * @param lean    rest lean magnitude per component, metres
     * @param len     length per component, metres
     * @param scale   pose scale per component ((K - 1) / maxBend)
     * @param poseMax largest pose coordinate per component (K - 1)
     */
    static void outputs(int c0, int c1, float[] devX, float[] devZ, float[] leanX, float[] leanZ, float[] lean,
                        float[] len, float[] scale, float[] poseMax, float[] pose, float[] azimuth) {
        for (int b = c0; b < c1; b += BLOCK) {
            int e = Math.min(c1, b + BLOCK);
            outputArguments(b, e, devX, devZ, leanX, leanZ, lean, len, pose, azimuth);
            poses(b, e, scale, poseMax, pose);
            azimuths(b, e, devZ, leanZ, azimuth);
        }
    }

    /** pose[c] := atan argument of the extra bend; azimuth[c] := atan argument of the half-angle azimuth. */
    private static void outputArguments(int c0, int c1, float[] devX, float[] devZ, float[] leanX, float[] leanZ,
                                        float[] lean, float[] len, float[] pose, float[] azimuth) {
        for (int c = c0; c < c1; c++) { // |T|
            float tx = leanX[c] + devX[c];
            float tz = leanZ[c] + devZ[c];
            azimuth[c] = (float) Math.sqrt(tx * tx + tz * tz);
        }
        for (int c = c0; c < c1; c++) { // num = (|T| + l) e: the extra tip offset e times |T| + l
            float x = devX[c];
            float z = devZ[c];
            pose[c] = Math.max(0f, 2 * (leanX[c] * x + leanZ[c] * z) + x * x + z * z);
        }
        for (int c = c0; c < c1; c++) { // extra bend: asin(e / length) = atan2(num, sqrt(d^2 - num^2))
            float num = pose[c];
            float d = (azimuth[c] + lean[c]) * len[c];
            pose[c] = Trig.poseArgument(num, (float) Math.sqrt(Math.max(0f, (d - num) * (d + num))));
        }
        for (int c = c0; c < c1; c++) { // azimuth: half angle about the z axis
            azimuth[c] = Trig.azimuthArgument(leanZ[c] + devZ[c], leanX[c] + devX[c], azimuth[c]);
        }
    }

    private static void poses(int c0, int c1, float[] scale, float[] max, float[] pose) {
        for (int c = c0; c < c1; c++) {
            pose[c] = Math.max(0f, Math.min(max[c], Trig.poseAngle(pose[c]) * scale[c]));
        }
    }

    private static void azimuths(int c0, int c1, float[] devZ, float[] leanZ, float[] azimuth) {
        for (int c = c0; c < c1; c++) {
            azimuth[c] = Trig.azimuth(leanZ[c] + devZ[c], azimuth[c]);
        }
    }

    /**
     * Pose coordinate of component c, in [0, K - 1] (scalar, the same operations as {@link #outputs},
     * hence the same bits). Arrays as {@link #outputs}.
     */
    static float poseCoordinate(int c, float[] devX, float[] devZ, float[] leanX, float[] leanZ, float[] lean,
                                float[] len, float[] scale, float[] poseMax) {
        return poseCoordinate(c, devX[c], devZ[c], leanX, leanZ, lean, len, scale, poseMax);
    }

    /** {@link #poseCoordinate(int, float[], float[], float[], float[], float[], float[], float[], float[])} at D = (x, z). */
    static float poseCoordinate(int c, float x, float z, float[] leanX, float[] leanZ, float[] lean, float[] len,
                                float[] scale, float[] poseMax) {
        float tx = leanX[c] + x;
        float tz = leanZ[c] + z;
        float t = (float) Math.sqrt(tx * tx + tz * tz);
        float num = Math.max(0f, 2 * (leanX[c] * x + leanZ[c] * z) + x * x + z * z);
        float d = (t + lean[c]) * len[c];
        float u = Trig.poseArgument(num, (float) Math.sqrt(Math.max(0f, (d - num) * (d + num))));
        return Math.max(0f, Math.min(poseMax[c], Trig.poseAngle(u) * scale[c]));
    }

    /**
     * Bend azimuth of component c, radians in [-pi, pi] (scalar, the same operations as
     * {@link #outputs}). Arrays as {@link #outputs}.
     */
    static float azimuth(int c, float[] devX, float[] devZ, float[] leanX, float[] leanZ) {
        return azimuth(c, devX[c], devZ[c], leanX, leanZ);
    }

    /** {@link #azimuth(int, float[], float[], float[], float[])} at D = (x, z). */
    static float azimuth(int c, float x, float z, float[] leanX, float[] leanZ) {
        float tx = leanX[c] + x;
        float tz = leanZ[c] + z;
        float t = (float) Math.sqrt(tx * tx + tz * tz);
        return Trig.azimuth(tz, Trig.azimuthArgument(tz, tx, t));
    }
}
