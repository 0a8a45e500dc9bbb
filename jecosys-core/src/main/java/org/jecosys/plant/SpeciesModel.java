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
 * radius {@code 0.5 baseWidth sqrt(j + 0.5)}; attached ones sit on a point of the parent, its tip by
 * default: {@link #slotAttachPoint}) and a variant
 * offset {@code j}: slot {@code s} of a plant of variant {@code v} uses shape variant
 * {@code (v + slotVariantOffset(s)) mod variants}, so the leaves of one tuft differ (with size classes,
 * cyclically within the plant's class: {@link VariationDef#slotVariant}); a variation's
 * {@link VariationDef#azimuth()} moves each ground instance of a multi-instance type off the even
 * spread by a seeded offset. Attached
 * components follow the position of their parent's attach point but keep their own world-upright frame, so they
 * stay above the ground like their parent.
 *
 * <h2>Variants</h2>
 * {@code variation.variants()} variants; variant {@code v} of component type {@code c} is
 * {@link ComponentVariant#sample}{@code (variation, seed, v, c)}. A parent's gravity tip load in
 * variant {@code v} is the mass of its attached components in variant {@code v}, each weighted by its
 * {@link ComponentDef#attachAt} (the tip mass with the same moment about the base), shared among its
 * instances. A plant picks its variant and rest azimuth from its own seed ({@link #variantFor},
 * {@link #restAzimuthFor}).
 *
 * <p>Immutable after {@link #build}; any thread; accessors and the per-plant functions do not
 * allocate.
 */
public final class SpeciesModel {
    private final SpeciesDef def;
    private final long seed;
    private final PlantComponent[] components;
    private final LodMesh[] meshes;
    private final int[] slotComponent;
    private final int[] slotParent;
    private final double[] slotAzimuth;
    private final double[] slotBaseX;
    private final double[] slotBaseZ;
    private final int[] slotVariantOffset;
    private final long buildNanos;
    /** Per slot, the widest half width of its part ({@link #slotWidestHalfWidth}); made at the first call. */
    private volatile float[] widestHalf;

    /** Takes the arrays as they are (no copy): {@link SpeciesBuild} and {@link #withComponents} only. */
    SpeciesModel(SpeciesDef def, long seed, PlantComponent[] components, LodMesh[] meshes,
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

    /**
     * {@link #build(SpeciesDef, long, double)} under Earth gravity ({@link GravityBend#EARTH_GRAVITY}).
     *
     * @param def  the species
     * @param seed variation seed
     * @return the built species (allocates)
     */
    public static SpeciesModel build(SpeciesDef def, long seed) {
        return build(def, seed, GravityBend.EARTH_GRAVITY);
    }

    /**
     * Pre-computes every pose table, variant and mesh of a species. Build time (scene load);
     * allocates; any thread; deterministic for {@code (def, seed, gravity)}.
     *
     * <p>The steps, in order ({@link SpeciesBuild}): link each component type to its parent type,
     * sample the shape variants and their lengths and masses, solve the gravity-bent rest pose of every
     * (type, variant) into its pose table, build the per-level component meshes, lay out the slots and
     * concatenate the whole-plant meshes.
     *
     * @param def     the species
     * @param seed    variation seed
     * @param gravity gravitational acceleration for the rest shapes, m/s^2, in [0, 100]; 0 leaves every
     *                component straight plus its own curvature
     * @return the built species
     * @throws IllegalArgumentException when def is null, gravity is out of range or the components'
     *                                  attachTo links form a cycle
     */
    public static SpeciesModel build(SpeciesDef def, long seed, double gravity) {
        return SpeciesBuild.build(def, seed, gravity);
    }

    /** {@return the definition this model was built from} */
    public SpeciesDef def() {
        return def;
    }

    /** {@return the variation seed this model was built with} */
    public long seed() {
        return seed;
    }

    /** {@return the wall time of {@link #build}, nanoseconds} */
    public long buildNanos() {
        return buildNanos;
    }

    /** {@return the number of component types} */
    public int componentCount() {
        return components.length;
    }

    /**
     * {@return component type {@code c}, in definition order: its built-in {@link ComponentModel}, or
     * the component a {@link ComponentFactory} supplied ({@link #withComponents})}
     *
     * @param c component type index, in [0, componentCount())
     */
    public PlantComponent component(int c) {
        return components[c];
    }

    /**
     * This species with the component types named in {@code factories} (for this species' id)
     * supplied by their {@link ComponentFactory} instead (an extension point, see
     * docs/ARCHITECTURE.md, "Extension points"; paper §4.1, §5.1): each factory gets the species'
     * def and the component it replaces, and its result is
     * checked against the species' layout. The whole-plant meshes are rebuilt from the components'
     * meshes; slots, variants and seeds are unchanged. Returns this model when no factory names this
     * species. Build time; allocates; any thread.
     *
     * @param factories the user components
     * @return the species model with those components
     * @throws IllegalArgumentException when a factory names a component this species does not have,
     *                                  returns null, or returns a component that does not match:
     *                                  another def, not one pose table per variant with the species'
     *                                  pose count and {@code segments + 1} points, not one mesh per
     *                                  level with the level's primitive, or a length, mass, stiffness,
     *                                  response time or drag area out of {@link ComponentDef}'s ranges
     */
    public SpeciesModel withComponents(ComponentFactories factories) {
        Require.nonNull("factories", factories);
        List<ComponentDef> cdefs = def.components();
        for (String id : factories.componentIds(def.id())) {
            boolean known = false;
            for (ComponentDef d : cdefs) {
                known |= d.id().equals(id);
            }
            if (!known) {
                List<String> ids = new java.util.ArrayList<>();
                for (ComponentDef d : cdefs) {
                    ids.add(d.id());
                }
                throw new IllegalArgumentException("species '" + def.id() + "' has no component '" + id
                        + "' to replace; its components: " + String.join(", ", ids));
            }
        }
        // a copy typed PlantComponent[] (the built model's array is a ComponentModel[] at run time)
        PlantComponent[] cs = java.util.Arrays.copyOf(components, components.length, PlantComponent[].class);
        boolean changed = false;
        for (int c = 0; c < cs.length; c++) {
            ComponentFactory f = factories.get(def.id(), cdefs.get(c).id());
            if (f != null) {
                cs[c] = checkComponent(f.create(def, components[c]), cdefs.get(c));
                changed = true;
            }
        }
        if (!changed) {
            return this;
        }
        LodMesh[] lm = new LodMesh[def.lods().size()];
        ComponentMesh[] meshOfComponent = new ComponentMesh[cs.length];
        for (int l = 0; l < lm.length; l++) {
            for (int c = 0; c < cs.length; c++) {
                meshOfComponent[c] = cs[c].mesh(l);
            }
            lm[l] = LodMesh.concat(def.lods().get(l).primitive(), slotComponent.length, slotComponent, slotParent,
                    meshOfComponent);
        }
        return new SpeciesModel(def, seed, cs, lm, slotComponent, slotParent, slotAzimuth, slotBaseX, slotBaseZ,
                slotVariantOffset, buildNanos);
    }

    /** Checks a user component against component type cd of this species; returns it. */
    private PlantComponent checkComponent(PlantComponent pc, ComponentDef cd) {
        String what = "the component factory for '" + def.id() + "/" + cd.id() + "'";
        if (pc == null) {
            throw new IllegalArgumentException(what + " returned null");
        }
        if (!cd.equals(pc.def())) {
            throw new IllegalArgumentException(what + " returned a component whose def() is not the species' "
                    + "def of that component (forward def() to the built-in component)");
        }
        if (pc.variants() != variants()) {
            throw new IllegalArgumentException(what + " returned " + pc.variants() + " variants, the species has "
                    + variants());
        }
        for (int v = 0; v < variants(); v++) {
            PoseTable t = pc.poseTable(v);
            if (t == null || t.poses() != def.poses() || t.points() != cd.segments() + 1) {
                throw new IllegalArgumentException(what + ": pose table " + v + " must have the species' "
                        + def.poses() + " poses and segments + 1 = " + (cd.segments() + 1) + " points");
            }
            // a variant scales the def's length and width by the largest variation times the largest
            // size-class factor at most, its mass by both
            double lo = ComponentVariant.MIN_LENGTH_SCALE * (1 - 1e-9);
            double hi = ComponentVariant.MAX_LENGTH_SCALE * (1 + 1e-9);
            Require.range(what + ": length(" + v + ")", pc.length(v), ComponentDef.MIN_LENGTH * lo,
                    ComponentDef.MAX_LENGTH * hi);
            Require.range(what + ": mass(" + v + ")", pc.mass(v), ComponentDef.MIN_MASS * lo * lo,
                    ComponentDef.MAX_MASS * hi * hi);
        }
        Require.range(what + ": stiffness()", pc.stiffness(), 1e-9, 1e6);
        Require.range(what + ": responseTime()", pc.responseTime(), 1e-3, 10);
        Require.range(what + ": dragArea()", pc.dragArea(), 0, 10);
        if (pc.levels() != def.lods().size()) {
            throw new IllegalArgumentException(what + " returned " + pc.levels() + " levels, the species has "
                    + def.lods().size());
        }
        for (int l = 0; l < def.lods().size(); l++) {
            ComponentMesh m = pc.mesh(l);
            if (m == null || m.primitive() != def.lods().get(l).primitive()) {
                throw new IllegalArgumentException(what + ": mesh(" + l + ") must be drawn with "
                        + def.lods().get(l).primitive());
            }
        }
        return pc;
    }

    /** {@return the number of shape variants, in [1, 64]} */
    public int variants() {
        return def.variation().variants();
    }

    /** {@return the number of levels of detail} */
    public int levels() {
        return meshes.length;
    }

    /**
     * {@return the whole-plant mesh at a level}
     *
     * @param level level of detail, in [0, levels())
     */
    public LodMesh mesh(int level) {
        return meshes[level];
    }

    /**
     * {@return the primitives (triangles or lines, see {@link LodMesh#primitive}) of one plant at a level}
     *
     * @param level level of detail, in [0, levels())
     */
    public int primitiveCount(int level) {
        return meshes[level].primitiveCount();
    }

    /** {@return the number of component instances (slots) per plant} */
    public int slotCount() {
        return slotComponent.length;
    }

    /**
     * {@return the component type of a slot}
     *
     * @param slot slot index, in [0, slotCount())
     */
    public int slotComponent(int slot) {
        return slotComponent[slot];
    }

    /**
     * {@return the parent slot that carries a slot, or -1 on the ground}
     *
     * @param slot slot index, in [0, slotCount())
     */
    public int slotParent(int slot) {
        return slotParent[slot];
    }

    /**
     * {@return the skeleton point of its parent slot that an attached slot's base sits on (the parent's
     * tip, its segment count, unless the component's {@link ComponentDef#attachAt} is below 1), or -1 on
     * the ground} Any thread; no allocation.
     *
     * @param slot slot index, in [0, slotCount())
     */
    public int slotAttachPoint(int slot) {
        int parent = slotParent[slot];
        return parent < 0 ? -1 : components[slotComponent[slot]].def().attachPoint(
                components[slotComponent[parent]].def().segments());
    }

    /**
     * {@return the azimuth of a slot about Y relative to the plant's rest azimuth, radians}
     *
     * @param slot slot index, in [0, slotCount())
     */
    public double slotAzimuth(int slot) {
        return slotAzimuth[slot];
    }

    /**
     * {@return the base X offset of a ground slot in the plant's (unrotated) frame, metres; 0 if attached}
     *
     * @param slot slot index, in [0, slotCount())
     */
    public double slotBaseX(int slot) {
        return slotBaseX[slot];
    }

    /**
     * {@return the base Z offset of a ground slot in the plant's (unrotated) frame, metres; 0 if attached}
     *
     * @param slot slot index, in [0, slotCount())
     */
    public double slotBaseZ(int slot) {
        return slotBaseZ[slot];
    }

    /**
     * {@return the variant offset of a slot (its instance index within its type)}
     *
     * @param slot slot index, in [0, slotCount())
     */
    public int slotVariantOffset(int slot) {
        return slotVariantOffset[slot];
    }

    /**
     * {@return the shape variant a slot uses: {@link VariationDef#slotVariant}{@code (plantVariant,
     * slotVariantOffset(slot))}, i.e. {@code (plantVariant + slotVariantOffset(slot)) mod variants()} with
     * one size class, else cyclically within the plant's size class} No allocation.
     *
     * @param slot         slot index, in [0, slotCount())
     * @param plantVariant the plant's variant, in [0, variants())
     */
    public int slotVariant(int slot, int plantVariant) {
        return def.variation().slotVariant(plantVariant, slotVariantOffset[slot]);
    }

    /**
     * {@return the pose table drawn for a slot in a plant of a given variant}
     *
     * @param slot         slot index, in [0, slotCount())
     * @param plantVariant the plant's variant, in [0, variants())
     */
    public PoseTable slotPoseTable(int slot, int plantVariant) {
        return components[slotComponent[slot]].poseTable(slotVariant(slot, plantVariant));
    }

    /**
     * The widest half width of a slot's part, metres: the longest width vector (a pose-table point's
     * second triple, from its axis to its edge) over every shape variant of the plant, every pose and
     * every point. Renderers read it to tell parts always thinner than a pixel from the others. Worked out
     * for every slot at the first call and kept (the model is immutable), so the renderers of many tiles
     * or contexts that share this model scan its pose tables once. Any thread; allocates at the first
     * call only.
     *
     * @param slot slot index, in [0, slotCount())
     * @return metres, 0 or more
     */
    public float slotWidestHalfWidth(int slot) {
        float[] w = widestHalf;
        if (w == null) {
            w = new float[slotComponent.length];
            for (int s = 0; s < w.length; s++) {
                double most = 0;
                for (int variant = 0; variant < variants(); variant++) {
                    PoseTable t = slotPoseTable(s, variant);
                    int floats = t.poses() * t.points() * PoseTable.STRIDE;
                    for (int o = 0; o < floats; o += PoseTable.STRIDE) {
                        double x = t.get(o + 3);
                        double y = t.get(o + 4);
                        double z = t.get(o + 5);
                        most = Math.max(most, Math.sqrt(x * x + y * y + z * z));
                    }
                }
                w[s] = (float) most;
            }
            widestHalf = w; // a race computes the same values twice, nothing worse
        }
        return w[slot];
    }

    /**
     * The shape variant of a plant with seed {@code plantSeed}. Pure.
     *
     * @param plantSeed the plant's variant seed ({@code PlantLayout.variantSeed})
     * @return uniform in [0, variants())
     */
    public int variantFor(long plantSeed) {
        return (int) Math.floorMod(Rng.mix(plantSeed ^ 0x5DEECE66DL), (long) variants());
    }

    /**
     * The rest azimuth of a plant with seed {@code plantSeed}. Pure.
     *
     * @param plantSeed the plant's variant seed
     * @return radians, in [0, 2 pi)
     */
    public static double restAzimuthFor(long plantSeed) {
        return (Rng.mix(plantSeed + 0x2545F4914F6CDD1DL) >>> 11) * 0x1.0p-53 * 2 * Math.PI;
    }
}
