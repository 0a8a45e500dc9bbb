package org.jecosys.plant;

import java.util.List;
import org.jecosys.math.Require;
import org.jecosys.math.Rng;

/**
 * A species pre-computed for animation and drawing (paper §4.1): per component type and shape
 * variant a gravity-bent pose table, per level of detail the component meshes and the whole-plant
 * {@link LodMesh}, and the plant's <em>slots</em> (component instances).
 *
 * <h2>Slots</h2>
 * Component types are expanded in definition order, {@code count} slots each. A slot has a component
 * type, a parent slot (instance {@code j mod parentCount} of the type named by {@code attachTo}, or
 * -1 on the ground), an azimuth offset about Y within the plant (ground leaves follow the golden
 * angle {@code j * 2.39996}, other instances are spread evenly, {@code 2 pi j / count}), a base offset
 * in the ground plane (ground instances of a multi-instance type sit on a small phyllotaxis disc of
 * radius {@code 0.5 baseWidth sqrt(j + 0.5)}; attached ones sit at the parent's tip) and a variant
 * offset {@code j}: slot {@code s} of a plant of variant {@code v} uses shape variant
 * {@code (v + slotVariantOffset(s)) mod variants}, so the leaves of one tuft differ. Attached
 * components follow their parent's tip position but keep their own world-upright frame, so they
 * stay above the ground like their parent.
 *
 * <h2>Variants</h2>
 * {@code variation.variants()} variants; variant {@code v} of component type {@code c} is
 * {@link ComponentVariant#sample}{@code (variation, seed, v, c)}. A parent's gravity tip load in
 * variant {@code v} is the mass of its attached components in variant {@code v}, shared among its
 * instances. A plant picks its variant and rest azimuth from its own seed ({@link #variantFor},
 * {@link #restAzimuthFor}).
 *
 * <p>Immutable after {@link #build}; any thread; accessors and the per-plant functions do not
 * allocate.
 */
public final class SpeciesModel {
    private static final double GOLDEN_ANGLE = Math.PI * (3 - Math.sqrt(5));

    private final SpeciesDef def;
    private final long seed;
    private final ComponentModel[] components;
    private final LodMesh[] meshes;
    private final int[] slotComponent;
    private final int[] slotParent;
    private final double[] slotAzimuth;
    private final double[] slotBaseX;
    private final double[] slotBaseZ;
    private final int[] slotVariantOffset;
    private final long buildNanos;

    private SpeciesModel(SpeciesDef def, long seed, ComponentModel[] components, LodMesh[] meshes,
                         int[] slotComponent, int[] slotParent, double[] slotAzimuth, double[] slotBaseX,
                         double[] slotBaseZ, int[] slotVariantOffset, long buildNanos) {
        this.def = def;
        this.seed = seed;
        this.components = components;
        this.meshes = meshes;
        this.slotComponent = slotComponent;
        this.slotParent = slotParent;
        this.slotAzimuth = slotAzimuth;
        this.slotBaseX = slotBaseX;
        this.slotBaseZ = slotBaseZ;
        this.slotVariantOffset = slotVariantOffset;
        this.buildNanos = buildNanos;
    }

    /** {@link #build(SpeciesDef, long, double)} under Earth gravity. */
    public static SpeciesModel build(SpeciesDef def, long seed) {
        return build(def, seed, GravityBend.EARTH_GRAVITY);
    }

    /**
     * Pre-computes every pose table, variant and mesh of a species. Build time (scene load);
     * allocates; any thread; deterministic for {@code (def, seed, gravity)}.
     *
     * @param def     the species
     * @param seed    variation seed
     * @param gravity gravitational acceleration for the rest shapes, m/s^2, in [0, 100]; 0 leaves every
     *                component straight plus its own curvature
     */
    public static SpeciesModel build(SpeciesDef def, long seed, double gravity) {
        long t0 = System.nanoTime();
        Require.nonNull("def", def);
        Require.range("gravity", gravity, 0, 100);
        List<ComponentDef> cdefs = def.components();
        int nc = cdefs.size();
        int nv = def.variation().variants();
        int levels = def.lods().size();
        int[] parent = new int[nc];
        for (int c = 0; c < nc; c++) {
            parent[c] = -1;
            String a = cdefs.get(c).attachTo();
            for (int p = 0; a != null && p < nc; p++) {
                if (cdefs.get(p).id().equals(a)) {
                    parent[c] = p;
                }
            }
        }
        checkNoCycle(cdefs, parent);
        ComponentVariant[][] var = new ComponentVariant[nv][nc];
        for (int v = 0; v < nv; v++) {
            for (int c = 0; c < nc; c++) {
                var[v][c] = ComponentVariant.sample(def.variation(), seed, v, c);
            }
        }
        PoseTable[][] tables = new PoseTable[nc][nv];
        double[][] lengths = new double[nc][nv];
        double[][] masses = new double[nc][nv];
        for (int v = 0; v < nv; v++) {
            for (int c = 0; c < nc; c++) {
                ComponentVariant cv = var[v][c];
                masses[c][v] = cdefs.get(c).mass() * cv.lengthScale() * cv.widthScale();
            }
        }
        double[] angles = new double[32];
        for (int v = 0; v < nv; v++) {
            for (int c = 0; c < nc; c++) {
                ComponentDef d = cdefs.get(c);
                ComponentVariant cv = var[v][c];
                double tipMass = 0;
                for (int ch = 0; ch < nc; ch++) {
                    if (parent[ch] == c) {
                        tipMass += masses[ch][v] * cdefs.get(ch).count() / d.count();
                    }
                }
                double length = d.length() * cv.lengthScale();
                double base = d.baseWidth() * cv.widthScale();
                double tip = d.tipWidth() * cv.widthScale();
                double curvature = Math.max(-Math.PI, Math.min(Math.PI, d.curvature() * cv.curvatureScale()));
                double tilt = Math.min(Math.PI / 2, d.tilt() + cv.extraTilt());
                GravityBend.solve(d.type(), d.segments(), length, base, tip, tilt, curvature, masses[c][v],
                        tipMass, gravity, angles);
                tables[c][v] = PoseTable.build(angles, d.segments(), length, base, tip, d.twist(),
                        def.poses(), def.maxBend());
                lengths[c][v] = length;
            }
        }
        ComponentModel[] models = new ComponentModel[nc];
        ComponentMesh[][] meshByLevel = new ComponentMesh[levels][nc];
        for (int c = 0; c < nc; c++) {
            ComponentDef d = cdefs.get(c);
            int[][] pts = new int[levels][];
            ComponentMesh[] ms = new ComponentMesh[levels];
            for (int l = 0; l < levels; l++) {
                int n = d.lodSegments().get(l);
                pts[l] = ComponentMesh.lodPoints(d.shape(), d.segments(), n);
                ms[l] = ComponentMesh.build(d.shape(), d.tipWidth() == 0, d.segments(), n, def.lods().get(l).primitive());
                meshByLevel[l][c] = ms[l];
            }
            models[c] = new ComponentModel(d, tables[c], lengths[c], masses[c], pts, ms);
        }
        int slots = def.componentsPerPlant();
        int[] sc = new int[slots];
        int[] sp = new int[slots];
        double[] sa = new double[slots];
        double[] sx = new double[slots];
        double[] sz = new double[slots];
        int[] so = new int[slots];
        int[] firstSlot = new int[nc];
        int s = 0;
        for (int c = 0; c < nc; c++) {
            firstSlot[c] = s;
            s += cdefs.get(c).count();
        }
        for (int c = 0; c < nc; c++) {
            ComponentDef d = cdefs.get(c);
            for (int j = 0; j < d.count(); j++) {
                int slot = firstSlot[c] + j;
                sc[slot] = c;
                so[slot] = j;
                if (parent[c] >= 0) {
                    sp[slot] = firstSlot[parent[c]] + j % cdefs.get(parent[c]).count();
                    sa[slot] = 2 * Math.PI * j / d.count();
                } else {
                    sp[slot] = -1;
                    boolean leaf = d.type() == ComponentType.LEAF;
                    sa[slot] = leaf ? (j * GOLDEN_ANGLE) % (2 * Math.PI) : 2 * Math.PI * j / d.count();
                    if (d.count() > 1) {
                        double r = 0.5 * d.baseWidth() * Math.sqrt(j + 0.5);
                        sx[slot] = r * Math.cos(sa[slot]);
                        sz[slot] = r * Math.sin(sa[slot]);
                    }
                }
            }
        }
        LodMesh[] lm = new LodMesh[levels];
        for (int l = 0; l < levels; l++) {
            lm[l] = LodMesh.concat(def.lods().get(l).primitive(), slots, sc, meshByLevel[l]);
        }
        return new SpeciesModel(def, seed, models, lm, sc, sp, sa, sx, sz, so, System.nanoTime() - t0);
    }

    private static void checkNoCycle(List<ComponentDef> cdefs, int[] parent) {
        for (int c = 0; c < parent.length; c++) {
            int p = parent[c];
            for (int steps = 0; p >= 0; steps++) {
                if (steps > parent.length) {
                    throw new IllegalArgumentException("components attachTo form a cycle through '"
                            + cdefs.get(c).id() + "'");
                }
                p = parent[p];
            }
        }
    }

    /** The definition. */
    public SpeciesDef def() {
        return def;
    }

    /** The variation seed this model was built with. */
    public long seed() {
        return seed;
    }

    /** Wall time of {@link #build}, nanoseconds. */
    public long buildNanos() {
        return buildNanos;
    }

    /** Component types. */
    public int componentCount() {
        return components.length;
    }

    /** Component type {@code c} in definition order. */
    public ComponentModel component(int c) {
        return components[c];
    }

    /** Shape variants. */
    public int variants() {
        return def.variation().variants();
    }

    /** Levels of detail. */
    public int levels() {
        return meshes.length;
    }

    /** The whole-plant mesh at {@code level}. */
    public LodMesh mesh(int level) {
        return meshes[level];
    }

    /** Primitives (triangles or lines, see {@link LodMesh#primitive}) of one plant at {@code level}. */
    public int primitiveCount(int level) {
        return meshes[level].primitiveCount();
    }

    /** Component instances per plant. */
    public int slotCount() {
        return slotComponent.length;
    }

    /** Component type of {@code slot}. */
    public int slotComponent(int slot) {
        return slotComponent[slot];
    }

    /** Parent slot whose tip carries {@code slot}, or -1 on the ground. */
    public int slotParent(int slot) {
        return slotParent[slot];
    }

    /** Azimuth of {@code slot} about Y relative to the plant's rest azimuth, radians. */
    public double slotAzimuth(int slot) {
        return slotAzimuth[slot];
    }

    /** Base X offset of a ground slot in the plant's (unrotated) frame, metres; 0 if attached. */
    public double slotBaseX(int slot) {
        return slotBaseX[slot];
    }

    /** Base Z offset of a ground slot in the plant's (unrotated) frame, metres; 0 if attached. */
    public double slotBaseZ(int slot) {
        return slotBaseZ[slot];
    }

    /** Variant offset of {@code slot} (its instance index within its type). */
    public int slotVariantOffset(int slot) {
        return slotVariantOffset[slot];
    }

    /** Shape variant used by {@code slot} in a plant of variant {@code plantVariant}. */
    public int slotVariant(int slot, int plantVariant) {
        return (plantVariant + slotVariantOffset[slot]) % variants();
    }

    /** The pose table drawn for {@code slot} in a plant of variant {@code plantVariant}. */
    public PoseTable slotPoseTable(int slot, int plantVariant) {
        return components[slotComponent[slot]].poseTable(slotVariant(slot, plantVariant));
    }

    /** The shape variant of a plant with seed {@code plantSeed}: uniform in [0, variants). Pure. */
    public int variantFor(long plantSeed) {
        return (int) Math.floorMod(Rng.mix(plantSeed ^ 0x5DEECE66DL), (long) variants());
    }

    /** The rest azimuth of a plant with seed {@code plantSeed}, radians in [0, 2 pi). Pure. */
    public static double restAzimuthFor(long plantSeed) {
        return (Rng.mix(plantSeed + 0x2545F4914F6CDD1DL) >>> 11) * 0x1.0p-53 * 2 * Math.PI;
    }
}
