package org.jecosys.anim;

/**
 * A read-only view of the component kinds (paper §4.2): each kind's constants and its cached
 * dynamic-constraint coefficients, as {@link AnimationView#kinds()} hands them out. Nothing here
 * changes the kinds; the simulation prepares them again at every step. Any thread between steps;
 * no method allocates.
 */
public interface KindsView {
    /**
     * {@return the kind of a species' component type in a shape variant (for kinds made by {@link SpringKinds#of})}
     *
     * @param species   species index, in the list given to {@link SpringKinds#of}
     * @param component component type index within the species
     * @param variant   shape variant, in [0, the species' variants)
     */
    int kindOf(int species, int component, int variant);

    /** {@return the number of kinds} */
    int count();

    /**
     * {@return the spring constant PC of kind k, N/m}
     *
     * @param k kind, in [0, count())
     */
    double stiffness(int k);

    /**
     * {@return the response time tau of kind k, seconds}
     *
     * @param k kind, in [0, count())
     */
    double responseTime(int k);

    /**
     * {@return the mass of kind k, kg (does not enter the motion; see the class comment)}
     *
     * @param k kind, in [0, count())
     */
    double mass(int k);

    /**
     * {@return the drag coefficient times area of kind k, m^2}
     *
     * @param k kind, in [0, count())
     */
    double dragArea(int k);

    /**
     * {@return the equilibrium deviation per unit {@code |u| u}: {@code 0.5 rho dragArea / PC}, m per (m/s)^2}
     *
     * @param k kind, in [0, count())
     */
    double gain(int k);

    /**
     * {@return the rest lean of kind k: horizontal tip offset of the rest pose, metres (at least 1e-4 length)}
     *
     * @param k kind, in [0, count())
     */
    float restLean(int k);

    /**
     * {@return the skeleton length of kind k, metres}
     *
     * @param k kind, in [0, count())
     */
    float length(int k);

    /**
     * {@return the bend of the last pose of kind k, radians}
     *
     * @param k kind, in [0, count())
     */
    float maxBend(int k);

    /**
     * {@return the last pose coordinate (K - 1) of kind k}
     *
     * @param k kind, in [0, count())
     */
    float poseMax(int k);

    /**
     * The spring class of kind k: the first kind with the same response time, gain and response-time
     * variation (the constants the step coefficients and the per-run rest point depend on), so kinds
     * of one class always have bit-identical coefficients. The shape variants of one component type
     * share their class.
     *
     * @param k kind, in [0, count())
     * @return the class's first kind, in [0, k]
     */
    int springClass(int k);

    /**
     * {@return a mask with bit l set when kind k is drawn (lodSegments &gt; 0) at level of detail l}
     *
     * @param k kind, in [0, count())
     */
    int lodMask(int k);

    /**
     * {@return the bend limit of kind k: {@code length sin(maxBend)}, metres, the tip offset of its last
     * pose with the length kept; the rest point of the spring stays below it (see the class comment)}
     *
     * @param k kind, in [0, count())
     */
    float bendLimit(int k);

    /**
     * {@return the relative response-time variation of kind k's species (0 for none)}
     *
     * @param k kind, in [0, count())
     */
    double responseVariation(int k);

    /**
     * {@return the response time of kind k in response variant v, seconds:
     * {@code tau (1 + f (v - NOMINAL_VARIANT) / NOMINAL_VARIANT)} with f its {@link #responseVariation}}
     *
     * @param k kind, in [0, count())
     * @param v response variant, in [0, RESPONSE_VARIANTS)
     */
    double responseTime(int k, int v);

    /** {@return the step length the coefficients were last prepared for, seconds (NaN before the first)} */
    double preparedStep();

    /**
     * Copies the cached coefficients of kind k in its nominal response variant, {@link SpringKinds#STRIDE} of
     * them in the order aDD, aDv, bD, cD, aVD, aVv, bV, cV (see {@link SpringKinds}; bD, cD, bV and cV
     * weigh rest points in metres), into {@code dest} from {@code offset}. Any thread while no
     * {@code prepare} runs; no allocation.
     *
     * @param k      kind, in [0, count())
     * @param dest   where to write, at least {@code offset + STRIDE} long
     * @param offset first index written
     * @return {@code dest}
     * @throws IllegalArgumentException when k is out of range or dest is too short
     */
    float[] coefficients(int k, float[] dest, int offset);

    /**
     * One cached coefficient of kind k (see {@link #coefficients(int, float[], int)}). No allocation.
     *
     * @param k kind, in [0, count())
     * @param i which, in [0, STRIDE): aDD, aDv, bD, cD, aVD, aVv, bV, cV
     * @return the coefficient (NaN-free after {@code prepare}; 0 before)
     */
    float coefficient(int k, int i);

    /**
     * One cached coefficient of kind k in response variant v (see {@link #coefficients(int, float[], int)}).
     * No allocation.
     *
     * @param k kind, in [0, count())
     * @param v response variant, in [0, RESPONSE_VARIANTS)
     * @param i which, in [0, STRIDE): aDD, aDv, bD, cD, aVD, aVv, bV, cV
     * @return the coefficient (0 before {@code prepare})
     */
    float coefficient(int k, int v, int i);
}
