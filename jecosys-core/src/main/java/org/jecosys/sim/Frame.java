package org.jecosys.sim;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.FloatBuffer;
import org.jecosys.anim.BendGeometry;
import org.jecosys.field.ForceFieldDef;
import org.jecosys.math.Require;

/**
 * One complete, published frame of animation output (paper §4.2.2's "displacement angle" per
 * component), read by the renderer or a game. Per component the frame holds its deviation D (the
 * horizontal offset of its tip from rest, world X and Z, metres: {@link #renderStates()}), and from
 * it, through the world's {@link BendGeometry}, gives the continuous pose coordinate {@code k + w}
 * into its pose table (pose k blended toward k + 1 by w) and the bend azimuth, the world heading of
 * the component's bending plane: the pose table's local +X axis maps to world (cos a, 0, sin a). With
 * no wind a component shows pose 0 at its rest heading. Per plant: whether it was on a visible node
 * and the level of detail it was animated at.
 *
 * <p>Frames are written by the simulation's threads and published whole by triple buffering
 * ({@link FrameExchange}); a reader sees a frame only after it is complete, and the frame does not
 * change until that reader asks for the next one. Accessors allocate nothing.
 */
public final class Frame {
    /** Bytes per component of {@link #renderStates()}: the deviation D, X and Z, two floats. */
    public static final int RENDER_STATE_BYTES = 8;

    static {
        org.jecosys.sim.internal.FrameWriter.grant(new org.jecosys.sim.internal.FrameWriter.Access() {
            @Override
            public void set(Frame f, int c, float poseCoord, float azimuth) {
                f.set(c, poseCoord, azimuth);
            }

            @Override
            public void setDeviation(Frame f, int c, float dx, float dz) {
                f.setDeviation(c, dx, dz);
            }

            @Override
            public void setDraw(Frame f, int p, int level, int keep) {
                f.setDraw(p, level, keep);
            }

            @Override
            public void setThinning(Frame f, double start, double end, double minFraction) {
                f.setThinning(start, end, minFraction);
            }
        });
    }

    private final BendGeometry geometry;
    /** Per component, interleaved little-endian floats (deviation X, Z, metres), for the GPU. */
    final FloatBuffer renderStates;
    /** The same bytes as {@link #renderStates}, one long per component (the step's bulk copy). */
    final java.nio.LongBuffer renderStateLongs;
    private final ByteBuffer renderStatesView;
    /** {@link #set}'s deviation, so that it allocates nothing. */
    private final float[] posed = new float[2];
    final boolean[] plantVisible;
    final byte[] plantLevel;
    final byte[] drawLevel;
    final int[] drawKeep;
    long number;
    double time;
    int componentsAnimated;
    long fieldNanos;
    long animationNanos;
    private double thinStart = ForceFieldDef.DEFAULT_THIN_START;
    private double thinEnd = ForceFieldDef.DEFAULT_THIN_END;
    private double thinMinFraction = ForceFieldDef.DEFAULT_THIN_MIN_FRACTION;
    /** Whether {@link #drawLevel} holds a decision for a camera recorded below. */
    private boolean decided;
    /** The camera the decision was made for: its view-projection (column-major) and eye, metres. */
    private final float[] decisionViewProjection = new float[16];
    private double decisionEyeX;
    private double decisionEyeY;
    private double decisionEyeZ;
    /** Per species, the first of its edges in {@link #lodEdges}; one more entry ends the last. */
    private int[] lodEdgeStart = new int[1];
    /** The level-of-detail edges the decision used, metres, every species after the other. */
    private double[] lodEdges = new double[0];
    private double lodTransition = DrawDecision.DEFAULT_TRANSITION;
    private double lodReference = org.jecosys.math.ViewLod.referenceScale(ForceFieldDef.DEFAULT_LOD_FOV_Y);

    /**
     * An empty frame sized for a world: every component at rest (D = 0: pose 0 at its rest heading),
     * no plant visible. Allocates.
     *
     * @param plants   plants of the world, &gt;= 0
     * @param geometry the bend geometry of the world's components ({@link World#bendGeometry()},
     *                 {@code Simulation.bendGeometry()})
     */
    public Frame(int plants, BendGeometry geometry) {
        this.geometry = Require.nonNull("geometry", geometry);
        int components = geometry.componentCount();
        ByteBuffer states = ByteBuffer.allocateDirect(Math.max(RENDER_STATE_BYTES, components * RENDER_STATE_BYTES))
                .order(ByteOrder.LITTLE_ENDIAN);
        renderStates = states.asFloatBuffer();
        renderStateLongs = states.asLongBuffer();
        renderStatesView = states.asReadOnlyBuffer().order(ByteOrder.LITTLE_ENDIAN);
        plantVisible = new boolean[plants];
        plantLevel = new byte[plants];
        drawLevel = new byte[plants];
        java.util.Arrays.fill(drawLevel, (byte) -1);
        drawKeep = new int[plants];
    }

    /** {@return the frame number, counting published frames from 1; 0 before the first step} */
    public long number() {
        return number;
    }

    /** {@return the simulation time of the frame, seconds} */
    public double time() {
        return time;
    }

    /** {@return the number of components} */
    public int componentCount() {
        return geometry.componentCount();
    }

    /** {@return the bend geometry the frame computes its poses and azimuths with} */
    public BendGeometry geometry() {
        return geometry;
    }

    /** {@return the number of plants} */
    public int plantCount() {
        return plantVisible.length;
    }

    /**
     * {@return the continuous pose coordinate of component c, in [0, poses - 1]}, computed from its
     * deviation ({@link BendGeometry#poseCoordinate}; the animation's own value bit for bit). No
     * allocation.
     *
     * @param c component index, in [0, componentCount())
     */
    public float poseCoord(int c) {
        return geometry.poseCoordinate(c, renderStates.get(2 * c), renderStates.get(2 * c + 1));
    }

    /**
     * {@return the world heading a of component c's bending plane, radians in [-pi, pi]: local +X goes
     * to (cos a, 0, sin a)}, computed from its deviation ({@link BendGeometry#azimuth}). No allocation.
     *
     * @param c component index, in [0, componentCount())
     */
    public float bendAzimuth(int c) {
        return geometry.azimuth(c, renderStates.get(2 * c), renderStates.get(2 * c + 1));
    }

    /**
     * {@return component c's deviation D, X part, metres}
     *
     * @param c component index, in [0, componentCount())
     */
    public float deviationX(int c) {
        return renderStates.get(2 * c);
    }

    /**
     * {@return component c's deviation D, Z part, metres}
     *
     * @param c component index, in [0, componentCount())
     */
    public float deviationZ(int c) {
        return renderStates.get(2 * c + 1);
    }

    /**
     * {@return whether plant p was on a visible force-field node in this frame}
     *
     * @param p plant index, in [0, plantCount())
     */
    public boolean plantVisible(int p) {
        return plantVisible[p];
    }

    /**
     * {@return the level of detail plant p was animated at (0 = nearest)}
     *
     * @param p plant index, in [0, plantCount())
     */
    public int plantLevel(int p) {
        return plantLevel[p];
    }

    /** {@return the number of components updated by the animation in the last step of this frame} */
    public int componentsAnimated() {
        return componentsAnimated;
    }

    /** {@return the time the force-field update took in the last step, nanoseconds} */
    public long fieldNanos() {
        return fieldNanos;
    }

    /**
     * {@return the time the animation update took in the last step, nanoseconds: from the start of its
     * first chunk to the end of its last, so it does not include the force-field update, which the
     * stepping thread runs before it helps the workers (with one thread, the two run one after the
     * other; with several, side by side)}
     */
    public long animationNanos() {
        return animationNanos;
    }

    /**
     * Poses component c at pose coordinate {@code poseCoord} and bend azimuth {@code azimuth}: sets
     * the deviation that gives them ({@link BendGeometry#deviationFor}; read back, they agree to float
     * rounding). The simulation writes its frames itself; tools and tests that build frames without
     * the animation engine reach this through {@code org.jecosys.sim.internal.FrameWriter} (not API).
     * Only on a frame the caller owns (never one read through {@link FrameExchange}); one thread. No
     * allocation.
     *
     * @param c          component index
     * @param poseCoord  pose coordinate k + w, in [0, poses - 1] of the component's pose table
     * @param azimuth    world heading of the bending plane, radians
     */
    void set(int c, float poseCoord, float azimuth) {
        geometry.deviationFor(c, poseCoord, azimuth, posed);
        setDeviation(c, posed[0], posed[1]);
    }

    /**
     * Sets component c's deviation D (metres, world X and Z), as {@link #set}. No allocation.
     *
     * @param c  component index
     * @param dx deviation X, metres
     * @param dz deviation Z, metres
     */
    void setDeviation(int c, float dx, float dz) {
        renderStates.put(2 * c, dx).put(2 * c + 1, dz);
    }

    /**
     * {@return the level of detail plant p is drawn at, or -1 when it is not drawn: the frame's one
     * visibility and level decision ({@link DrawDecision}), which the renderer follows as it is}
     *
     * @param p plant index
     */
    public int drawLevel(int p) {
        return drawLevel[p];
    }

    /**
     * {@return the screen-door dither windows plant p is drawn with: bits 0-15 the packed window of
     * {@link #drawLevel} ({@code 256 lo + hi}: fragments with {@code lo <= bayer < hi}, /255, are
     * kept), bits 16-31 that of the next level when the plant is in the transition band before its
     * level's end (0: not drawn at the next level); see {@link DrawDecision#keep(int, int, double)}}
     *
     * @param p plant index
     */
    public int drawKeep(int p) {
        return drawKeep[p];
    }

    /** {@return where the decision's distance thinning began for this frame, metres (see {@link DrawDecision#thinKept})} */
    public double thinStart() {
        return thinStart;
    }

    /** {@return where the decision's distance thinning reached its least share for this frame, metres} */
    public double thinEnd() {
        return thinEnd;
    }

    /**
     * {@return the least share of far plants this frame's decision kept, in (0, 1] (1: no thinning);
     * a renderer may widen the kept plants' thin parts to make up for the others}
     */
    public double thinMinFraction() {
        return thinMinFraction;
    }

    /**
     * Records the distance thinning the frame's decision used (the simulation does it as it publishes
     * the frame; {@code DrawDecision.decideAll} too; tools and tests that build frames themselves use
     * {@code FrameWriter}).
     * Only on a frame the caller owns. No allocation.
     *
     * @param start       where thinning begins, metres
     * @param end         where it reaches its least share, metres
     * @param minFraction the least share, in (0, 1] (1: none)
     */
    void setThinning(double start, double end, double minFraction) {
        thinStart = start;
        thinEnd = end;
        thinMinFraction = minFraction;
    }

    /**
     * Sets plant p's drawing decision (see {@link #drawLevel}, {@link #drawKeep}): for tools and
     * tests that build frames without the animation engine ({@code FrameWriter}), like {@link #set}. Only on a frame the
     * caller owns. No allocation.
     *
     * @param p     plant index
     * @param level level of detail to draw it at, or -1 for not drawn
     * @param keep  packed dither windows, as {@link #drawKeep} returns them ({@code 255}: level
     *              {@code level} alone, every fragment kept)
     */
    void setDraw(int p, int level, int keep) {
        drawLevel[p] = (byte) level;
        drawKeep[p] = keep;
    }

    /**
     * The compact render state of every component, {@link #RENDER_STATE_BYTES} bytes each, for upload
     * to the GPU as it is: at byte {@code 8 c} the deviation X of component c and at {@code 8 c + 4}
     * its deviation Z (metres), little-endian floats; a renderer maps them to pose and azimuth with the
     * {@link BendGeometry} it uploaded once, as {@link #poseCoord} and {@link #bendAzimuth} do. The
     * simulation's workers write it as they animate: it is current for every plant (a plant out of
     * view keeps its last state), so a view other than the one the step followed can draw any plant. A read-only view, direct (off the Java heap); its position and limit are not
     * used. No allocation.
     *
     * @return the read-only view, {@code 8 * componentCount()} bytes
     */
    public ByteBuffer renderStates() {
        return renderStatesView;
    }

    /**
     * Records what the frame's decision was made with: the camera (its view-projection and eye), the
     * level-of-detail edges of every species with the LOD scale applied, the transition band and the
     * LOD lens ({@link org.jecosys.math.ViewLod#referenceScale}), so that a renderer can decide for another
     * camera the same way ({@link ViewDecision}). Stepping thread, on the back frame; allocates only the
     * first time (or when the species' levels grow).
     */
    void recordDecision(org.joml.Matrix4f viewProjection, double ex, double ey, double ez, DrawDecision d,
                        double reference) {
        decided = true;
        viewProjection.get(decisionViewProjection);
        decisionEyeX = ex;
        decisionEyeY = ey;
        decisionEyeZ = ez;
        int species = d.speciesCount();
        int n = 0;
        for (int s = 0; s < species; s++) {
            n += d.levels(s) - 1;
        }
        if (lodEdgeStart.length != species + 1 || lodEdges.length != n) {
            lodEdgeStart = new int[species + 1];
            lodEdges = new double[n];
        }
        int at = 0;
        for (int s = 0; s < species; s++) {
            lodEdgeStart[s] = at;
            for (int l = 0, e = d.levels(s) - 1; l < e; l++) {
                lodEdges[at++] = d.edge(s, l);
            }
        }
        lodEdgeStart[species] = at;
        lodTransition = d.transition();
        lodReference = reference;
    }

    /**
     * {@return whether a step (or a tool) made this frame's draw decision: false for a frame no step has
     * written yet, whose plants stand at rest because nothing has run} Any thread reading the frame; no
     * allocation.
     */
    public boolean decided() {
        return decided;
    }

    /**
     * Whether this frame's decision ({@link #drawLevel}, {@link #drawKeep}) was made for exactly this
     * camera (the same view-projection matrix and eye): a renderer then draws it as it is, and decides
     * for itself otherwise ({@link ViewDecision}). Any thread reading the frame; no allocation.
     *
     * @param camera  the camera a view is drawn with
     * @param scratch a matrix to hold its view-projection (overwritten)
     * @return whether the decision is this camera's
     */
    public boolean decidedFor(org.jecosys.math.Camera camera, org.joml.Matrix4f scratch) {
        if (!decided || camera.x() != decisionEyeX || camera.y() != decisionEyeY || camera.z() != decisionEyeZ) {
            return false;
        }
        camera.viewProjection(scratch);
        float[] m = decisionViewProjection;
        return scratch.m00() == m[0] && scratch.m01() == m[1] && scratch.m02() == m[2] && scratch.m03() == m[3]
                && scratch.m10() == m[4] && scratch.m11() == m[5] && scratch.m12() == m[6] && scratch.m13() == m[7]
                && scratch.m20() == m[8] && scratch.m21() == m[9] && scratch.m22() == m[10] && scratch.m23() == m[11]
                && scratch.m30() == m[12] && scratch.m31() == m[13] && scratch.m32() == m[14] && scratch.m33() == m[15];
    }

    /**
     * {@return the number of level-of-detail edges recorded for species s (its levels minus one), 0
     * before any decision}
     *
     * @param s species index
     */
    public int lodEdgeCount(int s) {
        return s + 1 < lodEdgeStart.length ? lodEdgeStart[s + 1] - lodEdgeStart[s] : 0;
    }

    /**
     * {@return where level l of species s ended in this frame's decision, metres (the LOD scale applied)}
     *
     * @param s species index
     * @param l level, below {@link #lodEdgeCount}
     */
    public double lodEdge(int s, int l) {
        return lodEdges[lodEdgeStart[s] + l];
    }

    /** {@return the transition band of this frame's decision, metres} */
    public double lodTransition() {
        return lodTransition;
    }

    /** {@return the LOD lens of this frame's decision, as {@link org.jecosys.math.ViewLod#referenceScale} gives it} */
    public double lodReference() {
        return lodReference;
    }

    /** Copies everything from {@code src}, which must have the same sizes. No allocation. */
    void copyFrom(Frame src) {
        renderStates.put(0, src.renderStates, 0, 2 * componentCount());
        System.arraycopy(src.plantVisible, 0, plantVisible, 0, plantVisible.length);
        System.arraycopy(src.plantLevel, 0, plantLevel, 0, plantLevel.length);
        System.arraycopy(src.drawLevel, 0, drawLevel, 0, drawLevel.length);
        System.arraycopy(src.drawKeep, 0, drawKeep, 0, drawKeep.length);
        number = src.number;
        time = src.time;
        componentsAnimated = src.componentsAnimated;
        fieldNanos = src.fieldNanos;
        animationNanos = src.animationNanos;
        thinStart = src.thinStart;
        thinEnd = src.thinEnd;
        thinMinFraction = src.thinMinFraction;
        decided = src.decided;
        System.arraycopy(src.decisionViewProjection, 0, decisionViewProjection, 0, 16);
        decisionEyeX = src.decisionEyeX;
        decisionEyeY = src.decisionEyeY;
        decisionEyeZ = src.decisionEyeZ;
        if (lodEdgeStart.length != src.lodEdgeStart.length || lodEdges.length != src.lodEdges.length) {
            lodEdgeStart = src.lodEdgeStart.clone(); // the first copy of a reader only
            lodEdges = src.lodEdges.clone();
        } else {
            System.arraycopy(src.lodEdgeStart, 0, lodEdgeStart, 0, lodEdgeStart.length);
            System.arraycopy(src.lodEdges, 0, lodEdges, 0, lodEdges.length);
        }
        lodTransition = src.lodTransition;
        lodReference = src.lodReference;
    }
}
