package org.jecosys.plant;

import java.util.List;
import org.jecosys.math.Require;
import org.jecosys.math.Rng;

/**
 * The build pipeline of {@link SpeciesModel#build(SpeciesDef, long, double)} (paper §4.1): its steps
 * are listed there, the slots and variants it lays out in {@link SpeciesModel}'s class comment.
 * Build time; allocates; any thread.
 */
final class SpeciesBuild {
    private static final double GOLDEN_ANGLE = Math.PI * (3 - Math.sqrt(5));
    /** Rng stream of the ground slots' azimuth offsets (variants use streams below 64 x 1024). */
    private static final long AZIMUTH_STREAM = 0xA5A5_0000_0000L;

    private SpeciesBuild() {
    }

    /** See {@link SpeciesModel#build(SpeciesDef, long, double)}. */
    static SpeciesModel build(SpeciesDef def, long seed, double gravity) {
        long t0 = System.nanoTime();
        Require.nonNull("def", def);
        Require.range("gravity", gravity, 0, 100);
        List<ComponentDef> cdefs = def.components();
        int[] parent = parentTypes(cdefs);
        checkNoCycle(cdefs, parent);
        ComponentVariant[][] variants = sampleVariants(def, seed, parent);
        double[][] lengths = variantLengths(cdefs, variants);
        double[][] masses = variantMasses(cdefs, variants);
        PoseTable[][] tables = restPoseTables(def, gravity, parent, variants, lengths, masses);
        ComponentModel[] models = componentModels(def, tables, lengths, masses, parent);
        SlotLayout slots = new SlotLayout(cdefs, parent, def.componentsPerPlant(), def.variation().azimuth(), seed);
        LodMesh[] meshes = plantMeshes(def, slots.component, slots.parent, models);
        return new SpeciesModel(def, seed, models, meshes, slots.component, slots.parent, slots.azimuth,
                slots.baseX, slots.baseZ, slots.variantOffset, System.nanoTime() - t0);
    }

    /**
     * Per component type, the index of the type its {@code attachTo} names (the last of that id), or
     * -1 for a type on the ground (no {@code attachTo}). Build time; allocates the result.
     */
    private static int[] parentTypes(List<ComponentDef> cdefs) {
        int nc = cdefs.size();
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
        return parent;
    }

    /**
     * The shape variants, indexed {@code [variant][component type]}: {@link ComponentVariant#sample}
     * {@code (variation, seed, v, c)}, the length and width factors of a type on the ground
     * ({@code parent[c] < 0}) times the variant's size-class factor ({@link VariationDef#sizeScale}): a
     * plant's size class sets how tall and stout its leaves and stalks grow (a stalk scaled in both bends
     * under its weight as the unscaled one does), while what sits on them (petals, heads) keeps its
     * size. Build time; allocates the result.
     */
    private static ComponentVariant[][] sampleVariants(SpeciesDef def, long seed, int[] parent) {
        VariationDef vd = def.variation();
        int nv = vd.variants();
        int nc = def.components().size();
        ComponentVariant[][] variants = new ComponentVariant[nv][nc];
        for (int v = 0; v < nv; v++) {
            for (int c = 0; c < nc; c++) {
                ComponentVariant cv = ComponentVariant.sample(vd, seed, v, c);
                if (vd.sizeClasses() > 1 && parent[c] < 0) {
                    double f = vd.sizeScale(v);
                    cv = new ComponentVariant(cv.lengthScale() * f, cv.widthScale() * f, cv.curvatureScale(),
                            cv.extraTilt());
                }
                variants[v][c] = cv;
            }
        }
        return variants;
    }

    /**
     * Length of each component type in each variant, metres, indexed {@code [type][variant]}: the
     * type's length times the variant's length scale. Build time; allocates the result.
     */
    private static double[][] variantLengths(List<ComponentDef> cdefs, ComponentVariant[][] variants) {
        double[][] lengths = new double[cdefs.size()][variants.length];
        for (int v = 0; v < variants.length; v++) {
            for (int c = 0; c < cdefs.size(); c++) {
                lengths[c][v] = cdefs.get(c).length() * variants[v][c].lengthScale();
            }
        }
        return lengths;
    }

    /**
     * Mass of each component type in each variant, kg, indexed {@code [type][variant]}: the type's
     * mass times the variant's length and width scales. Build time; allocates the result.
     */
    private static double[][] variantMasses(List<ComponentDef> cdefs, ComponentVariant[][] variants) {
        double[][] masses = new double[cdefs.size()][variants.length];
        for (int v = 0; v < variants.length; v++) {
            for (int c = 0; c < cdefs.size(); c++) {
                ComponentVariant cv = variants[v][c];
                masses[c][v] = cdefs.get(c).mass() * cv.lengthScale() * cv.widthScale();
            }
        }
        return masses;
    }

    /**
     * The pose table of each component type in each variant, indexed {@code [type][variant]}: the
     * rest shape bent under {@code gravity} (m/s^2) by its own mass and its tip load
     * ({@link #tipMass}) with {@link GravityBend#solve}, widths scaled and curvature and tilt
     * varied by the variant, then {@link PoseTable#build}. Build time; allocates the tables and one
     * scratch array of rest angles.
     */
    private static PoseTable[][] restPoseTables(SpeciesDef def, double gravity, int[] parent,
                                                ComponentVariant[][] variants, double[][] lengths, double[][] masses) {
        List<ComponentDef> cdefs = def.components();
        PoseTable[][] tables = new PoseTable[cdefs.size()][variants.length];
        double[] angles = new double[32];
        for (int v = 0; v < variants.length; v++) {
            for (int c = 0; c < cdefs.size(); c++) {
                ComponentDef d = cdefs.get(c);
                ComponentVariant cv = variants[v][c];
                double length = lengths[c][v];
                double base = d.baseWidth() * cv.widthScale();
                double tip = d.tipWidth() * cv.widthScale();
                double curvature = Math.max(-Math.PI, Math.min(Math.PI, d.curvature() * cv.curvatureScale()));
                double tilt = Math.min(Math.PI / 2, d.tilt() + cv.extraTilt());
                GravityBend.solve(d.type(), d.segments(), length, base, tip, tilt, curvature, masses[c][v],
                        tipMass(cdefs, parent, masses, c, v), gravity, angles);
                tables[c][v] = PoseTable.build(angles, d.segments(), length, base, tip, d.twist(),
                        def.poses(), def.maxBend());
            }
        }
        return tables;
    }

    /**
     * The load at the tip of one instance of component type {@code c} in variant {@code v}, kg: the
     * masses (in variant v) of all instances of the types attached to it, each times the share of c's
     * skeleton where it sits (its snapped {@link ComponentDef#attachPoint}: the tip mass with the same
     * moment about c's base; exactly the mass at the tip), shared among c's instances. No allocation.
     */
    private static double tipMass(List<ComponentDef> cdefs, int[] parent, double[][] masses, int c, int v) {
        double tipMass = 0;
        for (int ch = 0; ch < parent.length; ch++) {
            if (parent[ch] == c) {
                int segments = cdefs.get(c).segments();
                int point = cdefs.get(ch).attachPoint(segments);
                double share = point == segments ? 1 : (double) point / segments;
                tipMass += masses[ch][v] * share * cdefs.get(ch).count() / cdefs.get(c).count();
            }
        }
        return tipMass;
    }

    /**
     * The component models: per type its pose tables, lengths and masses (per variant) and per level
     * of detail its point subset ({@link ComponentMesh#lodPoints}) and mesh ({@link ComponentMesh#build},
     * in the level's primitive). Build time; allocates.
     */
    private static ComponentModel[] componentModels(SpeciesDef def, PoseTable[][] tables, double[][] lengths,
                                                    double[][] masses, int[] parent) {
        List<ComponentDef> cdefs = def.components();
        int levels = def.lods().size();
        ComponentModel[] models = new ComponentModel[cdefs.size()];
        for (int c = 0; c < models.length; c++) {
            ComponentDef d = cdefs.get(c);
            int[][] pts = new int[levels][];
            ComponentMesh[] ms = new ComponentMesh[levels];
            for (int l = 0; l < levels; l++) {
                int n = d.lodSegments().get(l);
                pts[l] = ComponentMesh.lodPoints(d.shape(), d.segments(), n);
                Primitive primitive = def.lods().get(l).primitive();
                // a mesh from a file where the component is drawn whole in triangles; its strip or fan and
                // lines elsewhere
                // (a rigid one on an attached component rides the parent's point it sits on)
                boolean onParent = d.mesh() != null && d.mesh().mode() == MeshMode.RIGID && parent[c] >= 0;
                ms[l] = d.mesh() != null && n == d.segments() && primitive == Primitive.TRIANGLES
                        ? ComponentMesh.fromMesh(d.mesh(),
                                onParent ? d.attachPoint(cdefs.get(parent[c]).segments()) : d.segments(),
                                d.length(), onParent)
                        : ComponentMesh.build(d.shape(), d.tipWidth() == 0, d.segments(), n, primitive);
            }
            models[c] = new ComponentModel(d, tables[c], lengths[c], masses[c], pts, ms);
        }
        return models;
    }

    /**
     * Per level of detail the whole-plant mesh: the meshes of the slots' component types at that
     * level, concatenated in slot order ({@link LodMesh#concat}). Build time; allocates.
     */
    private static LodMesh[] plantMeshes(SpeciesDef def, int[] slotComponent, int[] slotParent, ComponentModel[] models) {
        LodMesh[] meshes = new LodMesh[def.lods().size()];
        for (int l = 0; l < meshes.length; l++) {
            ComponentMesh[] meshOfComponent = new ComponentMesh[models.length];
            for (int c = 0; c < models.length; c++) {
                meshOfComponent[c] = models[c].mesh(l);
            }
            meshes[l] = LodMesh.concat(def.lods().get(l).primitive(), slotComponent.length, slotComponent, slotParent,
                    meshOfComponent);
        }
        return meshes;
    }

    /**
     * The slots of one plant (see the class comment), component types expanded in definition order:
     * per slot its component type, parent slot (-1 on the ground), azimuth about Y (radians), base
     * offset in the ground plane (metres; 0 for attached slots) and variant offset. Build time;
     * allocates its arrays, which the model then keeps.
     */
    private static final class SlotLayout {
        final int[] component;
        final int[] parent;
        final double[] azimuth;
        final double[] baseX;
        final double[] baseZ;
        final int[] variantOffset;

        /** Largest azimuth offset of a ground instance, radians (0: the even spread). */
        private final double jitter;
        /** Draws the azimuth offsets, slot by slot; null without them. */
        private final Rng rng;

        /**
         * @param cdefs      the component types
         * @param parentType per type its parent type, or -1 ({@link #parentTypes})
         * @param slots      component instances per plant (the sum of the types' counts)
         * @param jitter     largest azimuth offset of a ground instance, radians ({@link VariationDef#azimuth()})
         * @param seed       the species' variation seed
         */
        SlotLayout(List<ComponentDef> cdefs, int[] parentType, int slots, double jitter, long seed) {
            this.jitter = jitter;
            this.rng = jitter > 0 ? Rng.forStream(seed, AZIMUTH_STREAM) : null;
            component = new int[slots];
            parent = new int[slots];
            azimuth = new double[slots];
            baseX = new double[slots];
            baseZ = new double[slots];
            variantOffset = new int[slots];
            int[] firstSlot = firstSlots(cdefs);
            for (int c = 0; c < cdefs.size(); c++) {
                ComponentDef d = cdefs.get(c);
                for (int j = 0; j < d.count(); j++) {
                    int slot = firstSlot[c] + j;
                    component[slot] = c;
                    variantOffset[slot] = j;
                    int pt = parentType[c];
                    if (pt >= 0) { // at the tip of instance j mod count of the parent type, spread evenly
                        parent[slot] = firstSlot[pt] + j % cdefs.get(pt).count();
                        azimuth[slot] = 2 * Math.PI * j / d.count();
                    } else {
                        placeOnGround(slot, d, j);
                    }
                }
            }
        }

        /** Per component type the first of its slots. */
        private static int[] firstSlots(List<ComponentDef> cdefs) {
            int[] firstSlot = new int[cdefs.size()];
            int s = 0;
            for (int c = 0; c < cdefs.size(); c++) {
                firstSlot[c] = s;
                s += cdefs.get(c).count();
            }
            return firstSlot;
        }

        /**
         * Ground instance {@code j} of type {@code d} in {@code slot}: leaves at the golden angle
         * {@code j * 2.39996}, other types spread evenly ({@code 2 pi j / count}); a multi-instance
         * type sits on a phyllotaxis disc, radius {@code 0.5 baseWidth sqrt(j + 0.5)} metres. With a
         * jitter, a multi-instance type's azimuth moves by a seeded offset uniform in [-jitter,
         * jitter] (wrapped into [0, 2 pi)), before its disc position is taken.
         */
        private void placeOnGround(int slot, ComponentDef d, int j) {
            parent[slot] = -1;
            boolean leaf = d.type() == ComponentType.LEAF;
            azimuth[slot] = leaf ? (j * GOLDEN_ANGLE) % (2 * Math.PI) : 2 * Math.PI * j / d.count();
            if (d.count() > 1 && rng != null) {
                double a = (azimuth[slot] + jitter * rng.nextDouble(-1, 1)) % (2 * Math.PI);
                azimuth[slot] = a < 0 ? a + 2 * Math.PI : a;
            }
            if (d.count() > 1) {
                double r = 0.5 * d.baseWidth() * Math.sqrt(j + 0.5);
                baseX[slot] = r * Math.cos(azimuth[slot]);
                baseZ[slot] = r * Math.sin(azimuth[slot]);
            }
        }
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
}
