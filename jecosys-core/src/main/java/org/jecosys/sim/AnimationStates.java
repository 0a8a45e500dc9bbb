package org.jecosys.sim;

import java.util.List;
import org.jecosys.anim.AnimationState;
import org.jecosys.anim.BendGeometry;
import org.jecosys.anim.SpringKinds;
import org.jecosys.plant.LodDef;
import org.jecosys.math.Rng;
import org.jecosys.plant.SpeciesModel;
import org.jecosys.plant.VariationDef;

/** The {@link AnimationState} of a {@link World}: its plants and components laid out as the animation reads them. */
final class AnimationStates {
    private AnimationStates() {
    }

    /**
     * Per plant, whether its species leaves trails ({@code TrailDef#leavesTrails}); null when no species
     * does. Build time; allocates.
     */
    static boolean[] trailPlants(World world) {
        List<SpeciesModel> species = world.plants().species();
        boolean any = false;
        for (SpeciesModel s : species) {
            any |= s.def().trail().leavesTrails();
        }
        if (!any) {
            return null;
        }
        boolean[] trail = new boolean[world.plantCount()];
        for (int p = 0; p < trail.length; p++) {
            trail[p] = species.get(world.plantSpecies(p)).def().trail().leavesTrails();
        }
        return trail;
    }

    /** Per component of {@code world} its kind in {@code kinds}. Build time; allocates. */
    private static int[] kinds(World world, SpringKinds kinds, int[] first) {
        List<SpeciesModel> species = world.plants().species();
        int[] kind = new int[world.componentCount()];
        for (int p = 0; p < world.plantCount(); p++) {
            int sp = world.plantSpecies(p);
            SpeciesModel sm = species.get(sp);
            int v = world.plantVariant(p);
            for (int s = 0; s < sm.slotCount(); s++) {
                kind[first[p] + s] = kinds.kindOf(sp, sm.slotComponent(s), sm.slotVariant(s, v));
            }
        }
        return kind;
    }

    /**
     * The bend geometry of every component of {@code world} ({@link World#bendGeometry()}): its kind's
     * lean, length and pose scale, its rest heading the plant's rest azimuth plus its slot's azimuth.
     * Build time; allocates.
     */
    static BendGeometry geometry(World world) {
        SpringKinds kinds = SpringKinds.of(world.plants().species());
        int[] first = SimulationBuild.firstComponents(world);
        return geometry(world, kinds, first, kinds(world, kinds, first));
    }

    /** Like {@link #geometry(World)}, from the world's kinds and its components' kinds already worked out. */
    static BendGeometry geometry(World world, SpringKinds kinds, int[] first, int[] kind) {
        List<SpeciesModel> species = world.plants().species();
        float[] heading = new float[world.componentCount()];
        for (int p = 0; p < world.plantCount(); p++) {
            SpeciesModel sm = species.get(world.plantSpecies(p));
            for (int s = 0; s < sm.slotCount(); s++) {
                heading[first[p] + s] = (float) (world.plantRestAzimuth(p) + sm.slotAzimuth(s));
            }
        }
        return BendGeometry.of(kinds, kind, heading);
    }

    /**
     * Builds the state of every component of {@code world} at rest, with the trails of its species
     * ({@code TrailDef}), each plant with its seeded response
     * variant and compliance (its species' {@code VariationDef.responseTime} and {@code stiffness}:
     * a response variant uniform over {@link SpringKinds#RESPONSE_VARIANTS}, a stiffness factor
     * {@code 1 + f u} with u uniform in [-1, 1]). Build time; allocates; any thread.
     *
     * @param first  per plant its first component, and the component count at index plantCount
     * @param xs     plant base x, metres (likewise ys, zs)
     * @param seed   the scene's master seed
     */
    static AnimationState of(World world, SpringKinds kinds, int[] first, float[] xs, float[] ys, float[] zs,
                             long seed) {
        List<SpeciesModel> species = world.plants().species();
        double[][] edges = new double[species.size()][];
        for (int s = 0; s < species.size(); s++) {
            List<LodDef> lods = species.get(s).def().lods();
            edges[s] = new double[lods.size() - 1];
            for (int l = 0; l + 1 < lods.size(); l++) {
                edges[s][l] = lods.get(l).maxDistance();
            }
        }
        int plants = world.plantCount();
        int[] sp = new int[plants];
        int[] kind = kinds(world, kinds, first);
        byte[] response = new byte[plants];
        float[] compliance = new float[plants];
        for (int p = 0; p < plants; p++) {
            sp[p] = world.plantSpecies(p);
            SpeciesModel sm = species.get(sp[p]);
            VariationDef var = sm.def().variation();
            long h = Rng.mix(seed ^ Rng.mix(0x5EED_5EEDL + p));
            response[p] = (byte) (var.responseTime() > 0 ? Long.remainderUnsigned(h, SpringKinds.RESPONSE_VARIANTS)
                    : SpringKinds.NOMINAL_VARIANT);
            double u = (Rng.mix(h) >>> 11) * 0x1.0p-53 * 2 - 1;
            compliance[p] = (float) (1 / (1 + var.stiffness() * u));
        }
        AnimationState state = new AnimationState(kinds, edges, sp, first, xs, ys, zs, kind,
                world.bendGeometry(kinds, first, kind),
                response, compliance);
        double[] recovery = new double[species.size()];
        double[] flattenAt = new double[species.size()];
        for (int s = 0; s < species.size(); s++) {
            recovery[s] = species.get(s).def().trail().recovery();
            flattenAt[s] = species.get(s).def().trail().flattenAt();
        }
        state.useTrails(recovery, flattenAt);
        return state;
    }
}
