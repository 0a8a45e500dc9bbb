package org.jecosys.sim;

import java.util.List;
import org.jecosys.anim.AnimationDef;
import org.jecosys.field.ForceFieldDef;
import org.jecosys.math.Require;
import org.jecosys.plant.SpeciesDef;
import org.jecosys.terrain.DistributionDef;
import org.jecosys.terrain.PlacementDef;
import org.jecosys.terrain.TerrainDef;
import org.jecosys.wind.FlowDef;

/**
 * Everything a simulation is built from: a scene without its camera and presentation settings. A
 * game may build one in code; {@code SceneDef.simulationDef()} gives the one of a scene file.
 * Immutable; any thread.
 *
 * @param terrain       the terrain and resource maps
 * @param species       the species (their index is the species index used everywhere else)
 * @param distributions competitive distributions, each naming a species id
 * @param placements    plants placed by hand
 * @param flows         the wind flows active at start
 * @param field         the force field settings
 * @param animation     animation settings
 * @param seed          master seed (distribution, variation)
 */
public record SimulationDef(TerrainDef terrain, List<SpeciesDef> species, List<DistributionDef> distributions,
                            List<PlacementDef> placements, List<FlowDef> flows, ForceFieldDef field,
                            AnimationDef animation, long seed) {
    /**
     * Checks the components and copies the lists.
     *
     * @param terrain       not null
     * @param species       not null
     * @param distributions not null
     * @param placements    not null
     * @param flows         not null
     * @param field         not null
     * @param animation     not null
     * @param seed          master seed (any value)
     * @throws IllegalArgumentException when a component is null
     */
    public SimulationDef {
        Require.nonNull("terrain", terrain);
        species = List.copyOf(Require.nonNull("species", species));
        distributions = List.copyOf(Require.nonNull("distributions", distributions));
        placements = List.copyOf(Require.nonNull("placements", placements));
        flows = List.copyOf(Require.nonNull("flows", flows));
        Require.nonNull("field", field);
        Require.nonNull("animation", animation);
    }
}
