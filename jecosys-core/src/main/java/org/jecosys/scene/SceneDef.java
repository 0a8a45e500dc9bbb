package org.jecosys.scene;

import java.util.HashSet;
import java.util.List;
import java.util.Set;
import org.jecosys.anim.AnimationDef;
import org.jecosys.field.ForceFieldDef;
import org.jecosys.math.CameraDef;
import org.jecosys.math.Require;
import org.jecosys.plant.SpeciesDef;
import org.jecosys.sim.SimulationDef;
import org.jecosys.terrain.DistributionDef;
import org.jecosys.terrain.PlacementDef;
import org.jecosys.terrain.TerrainDef;
import org.jecosys.wind.FlowDef;

/**
 * A whole scene, as read from a {@code <scene version="1">} file or built in code. Immutable;
 * any thread. Two scenes with equal content are {@code equals}.
 *
 * @param version       format version; only {@link #FORMAT_VERSION} exists
 * @param name          human-readable name
 * @param seed          master seed of the scene
 * @param terrain       the terrain and its resource maps
 * @param species       the species, ids unique
 * @param distributions the competitive distributions (paper §4.3), each naming a species
 * @param placements    plants placed by hand
 * @param flows         the wind flows (paper §3.2), ids unique
 * @param field         the force field (paper §3.1)
 * @param camera        the viewer's start pose and path
 * @param animation     animation settings (paper §4.2)
 * @param render        presentation settings
 */
public record SceneDef(int version, String name, long seed, TerrainDef terrain, List<SpeciesDef> species,
                       List<DistributionDef> distributions, List<PlacementDef> placements, List<FlowDef> flows,
                       ForceFieldDef field, CameraDef camera, AnimationDef animation, RenderDef render,
                       org.jecosys.world.WorldDef world) {
    /** The one scene-format version this build reads and writes. */
    public static final int FORMAT_VERSION = 1;

    /**
     * Checks the components and copies the lists.
     *
     * @param version       must be {@link #FORMAT_VERSION}
     * @param name          human-readable name, not null
     * @param seed          master seed (any value)
     * @param terrain       not null
     * @param species       species with unique ids
     * @param distributions each naming one of {@code species}
     * @param placements    each naming one of {@code species}
     * @param flows         flows with unique ids
     * @param field         not null
     * @param camera        not null
     * @param animation     not null
     * @param render        not null
     * @param world         the open world ({@code <world>}), or null for a scene of one square
     * @throws IllegalArgumentException on another version, a null component, a duplicate id or an
     *                                  undefined species
     */
    public SceneDef {
        if (version != FORMAT_VERSION) {
            throw new IllegalArgumentException("version must be " + FORMAT_VERSION + ", got " + version);
        }
        Require.nonNull("name", name);
        Require.nonNull("terrain", terrain);
        species = List.copyOf(Require.nonNull("species", species));
        distributions = List.copyOf(Require.nonNull("distributions", distributions));
        placements = List.copyOf(Require.nonNull("placements", placements));
        flows = List.copyOf(Require.nonNull("flows", flows));
        Require.nonNull("field", field);
        Require.nonNull("camera", camera);
        Require.nonNull("animation", animation);
        Require.nonNull("render", render);
        Set<String> ids = new HashSet<>();
        for (SpeciesDef s : species) {
            if (!ids.add(s.id())) {
                throw new IllegalArgumentException("duplicate species id '" + s.id() + "'");
            }
        }
        for (DistributionDef d : distributions) {
            if (!ids.contains(d.species())) {
                throw new IllegalArgumentException("distribution names undefined species '" + d.species() + "'");
            }
        }
        for (PlacementDef p : placements) {
            if (!ids.contains(p.species())) {
                throw new IllegalArgumentException("plant names undefined species '" + p.species() + "'");
            }
        }
        Set<String> flowIds = new HashSet<>();
        for (FlowDef f : flows) {
            if (!flowIds.add(f.id())) {
                throw new IllegalArgumentException("duplicate flow id '" + f.id() + "'");
            }
        }
    }

    /**
     * A scene of one square (no {@code <world>}).
     *
     * @param version       must be {@link #FORMAT_VERSION}
     * @param name          human-readable name, not null
     * @param seed          master seed (any value)
     * @param terrain       not null
     * @param species       species with unique ids
     * @param distributions each naming one of {@code species}
     * @param placements    each naming one of {@code species}
     * @param flows         flows with unique ids
     * @param field         not null
     * @param camera        not null
     * @param animation     not null
     * @param render        not null
     * @throws IllegalArgumentException as the canonical constructor
     */
    public SceneDef(int version, String name, long seed, TerrainDef terrain, List<SpeciesDef> species,
                    List<DistributionDef> distributions, List<PlacementDef> placements, List<FlowDef> flows,
                    ForceFieldDef field, CameraDef camera, AnimationDef animation, RenderDef render) {
        this(version, name, seed, terrain, species, distributions, placements, flows, field, camera, animation, render,
                null);
    }

    /** {@return whether this scene is an open world (it has a {@code <world>})} */
    public boolean isOpenWorld() {
        return world != null;
    }

    /** {@return what a simulation of this scene is built from (everything but camera and render)} Allocates. */
    public SimulationDef simulationDef() {
        return new SimulationDef(terrain, species, distributions, placements, flows, field, animation, seed);
    }

    /**
     * The species with this id.
     *
     * @param id a species id
     * @return the species
     * @throws IllegalArgumentException when no species has this id
     */
    public SpeciesDef speciesById(String id) {
        for (SpeciesDef s : species) {
            if (s.id().equals(id)) {
                return s;
            }
        }
        throw new IllegalArgumentException("no species '" + id + "'");
    }
}
