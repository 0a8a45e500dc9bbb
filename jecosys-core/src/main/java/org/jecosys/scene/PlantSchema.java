package org.jecosys.scene;

import static org.jecosys.scene.AttrType.COLOUR;
import static org.jecosys.scene.AttrType.ID;
import static org.jecosys.scene.AttrType.PATH;
import static org.jecosys.scene.AttrType.INT_LIST;
import static org.jecosys.scene.AttrType.TEXT;
import static org.jecosys.scene.SceneSchema.INF;
import static org.jecosys.scene.SceneSchema.MAX_COMPONENTS;
import static org.jecosys.scene.SceneSchema.MAX_LODS;
import static org.jecosys.scene.SceneSchema.angle;
import static org.jecosys.scene.SceneSchema.enumeration;
import static org.jecosys.scene.SceneSchema.integer;
import static org.jecosys.scene.SceneSchema.num;
import static org.jecosys.scene.SceneSchema.words;

import java.util.List;
import org.jecosys.math.Waypoint;
import org.jecosys.plant.ComponentDef;
import org.jecosys.plant.ComponentShape;
import org.jecosys.plant.ComponentType;
import org.jecosys.plant.LodDef;
import org.jecosys.plant.Primitive;
import org.jecosys.plant.SpeciesDef;
import org.jecosys.plant.TrailDef;
import org.jecosys.plant.VariationDef;
import org.jecosys.terrain.DistributionDef;
import org.jecosys.terrain.PlacementDef;

/**
 * The plant part of the scene format ({@link SceneSchema}): {@code <species>} with its {@code <lod>},
 * {@code <variation>} and {@code <component>} children (paper section 4.1), {@code <distribution>}
 * (section 4.3) and {@code <plant>}. Immutable after class initialisation; any thread.
 */
final class PlantSchema {
    /** The {@code <species>} element. */
    static final ElementSpec SPECIES;
    /** The {@code <distribution>} element. */
    static final ElementSpec DISTRIBUTION;
    /** The {@code <plant>} element. */
    static final ElementSpec PLANT;

    private PlantSchema() {
    }

    private static ComponentDef c(Object d) {
        return (ComponentDef) d;
    }

    private static DistributionDef dist(Object d) {
        return (DistributionDef) d;
    }

    static {
        ElementSpec lod = new ElementSpec("lod", "A level of detail (paper section 4.1, Table 3), in ascending "
                + "distance; the last has no maxDistance.")
                .attr(num("maxDistance", "metres", "Farthest viewer distance of this level; absent for the last.")
                        .rangeAbove(0, LodDef.MAX_DISTANCE).def(INF).get(d -> ((LodDef) d).maxDistance()))
                .attr(enumeration("primitive", words(Primitive.values(), Primitive::xmlName), "What it draws with.")
                        .def("triangles").get(d -> ((LodDef) d).primitive().xmlName()));
        ElementSpec variation = new ElementSpec("variation", "Per-instance variation (paper section 4.1); "
                + "fractions are relative.")
                .attr(integer("variants", "Pre-computed shape variants sharing pose tables.")
                        .range(1, VariationDef.MAX_VARIANTS).def(VariationDef.DEFAULT_VARIANTS)
                        .get(d -> ((VariationDef) d).variants()))
                .attr(num("length", "", "Relative length variation.").range(0, VariationDef.MAX_FRACTION).def(0.0)
                        .get(d -> ((VariationDef) d).length()))
                .attr(num("width", "", "Relative width variation.").range(0, VariationDef.MAX_FRACTION).def(0.0)
                        .get(d -> ((VariationDef) d).width()))
                .attr(num("curvature", "", "Relative curvature variation.").range(0, VariationDef.MAX_FRACTION).def(0.0)
                        .get(d -> ((VariationDef) d).curvature()))
                .attr(angle("tilt", "Extra tilt from vertical.").range(0, VariationDef.MAX_TILT_DEGREES).def(0.0)
                        .get(d -> ((VariationDef) d).tilt()))
                .attr(num("responseTime", "", "Relative variation of the response time from plant to plant "
                        + "(seeded): neighbours move alike but not in lockstep.").range(0, VariationDef.MAX_FRACTION)
                        .def(0.0).get(d -> ((VariationDef) d).responseTime()))
                .attr(num("stiffness", "", "Relative variation of the stiffness from plant to plant (seeded).")
                        .range(0, VariationDef.MAX_FRACTION).def(0.0).get(d -> ((VariationDef) d).stiffness()))
                .attr(num("hue", "degrees", "Colour only: standard deviation of the per-plant hue shift (seeded).")
                        .range(0, VariationDef.MAX_HUE_DEGREES).def(0.0).get(d -> ((VariationDef) d).hue()))
                .attr(num("value", "", "Colour only: standard deviation of the per-plant brightness factor "
                        + "(1 is the species colour; seeded).").range(0, VariationDef.MAX_VALUE).def(0.0)
                        .get(d -> ((VariationDef) d).value()))
                .attr(num("dryTips", "", "Colour only: how far the leaf tips turn straw-coloured (0 none, 1 fully).")
                        .range(0, 1).def(0.0).get(d -> ((VariationDef) d).dryTips()))
                .attr(num("size", "", "Relative spread of plant size between the size classes: the classes' factors "
                        + "on the length of every component on the ground (leaves, stalks; not what sits on them) lie "
                        + "evenly in [1 - size, 1 + size]; no effect with one class.")
                        .range(0, VariationDef.MAX_FRACTION).def(VariationDef.DEFAULT_SIZE)
                        .get(d -> ((VariationDef) d).size()))
                .attr(integer("sizeClasses", "Plant size classes the variants are split into, at most variants: a "
                        + "plant's leaves vary within its own class, so plants differ in height; 1 lets every "
                        + "plant use every variant.").range(1, VariationDef.MAX_VARIANTS)
                        .def(VariationDef.DEFAULT_SIZE_CLASSES).get(d -> ((VariationDef) d).sizeClasses()))
                .attr(angle("azimuth", "Largest seeded offset of each ground leaf (of a component with count above "
                        + "1) from the even golden-angle spread, so a tuft's leaves bunch and gap unevenly; 0 keeps "
                        + "the even spread.").range(0, VariationDef.MAX_AZIMUTH_DEGREES)
                        .def(VariationDef.DEFAULT_AZIMUTH).get(d -> ((VariationDef) d).azimuth()));
        ElementSpec component = new ElementSpec("component", "A component type: skeleton shape (paper section 4.1) "
                + "and dynamic-constraint spring (section 4.2, equations 4-5).")
                .attr(AttrSpec.of("id", ID, "", "Unique within the species.").required().get(d -> c(d).id()))
                .attr(enumeration("type", words(ComponentType.values(), ComponentType::xmlName), "What it is.")
                        .required().get(d -> c(d).type().xmlName()))
                .attr(enumeration("shape", words(ComponentShape.values(), ComponentShape::xmlName),
                        "How primitives are generated from the skeleton.").def(ComponentDef.DEFAULT_SHAPE.xmlName())
                        .get(d -> c(d).shape().xmlName()))
                .attr(integer("count", "How many a plant has.").range(1, ComponentDef.MAX_COUNT).def(ComponentDef.DEFAULT_COUNT)
                        .get(d -> c(d).count()))
                .attr(AttrSpec.of("attachTo", ID, "", "Id of the component that carries these (at its tip unless "
                        + "attachAt says otherwise); absent for the ground.").get(d -> c(d).attachTo()))
                .attr(num("attachAt", "", "Where along the carrier (attachTo) these sit, as a share of its skeleton: 1 "
                        + "its tip (petals, a head), less a point on the way up (leaves on a flower stalk), snapped to "
                        + "the nearest skeleton point above the base. Only with attachTo.")
                        .range(ComponentDef.MIN_ATTACH_AT, 1).def(1.0).get(d -> c(d).attachAt()))
                .attr(integer("segments", "Skeleton segments (points = segments + 1).").range(1, ComponentDef.MAX_SEGMENTS)
                        .required()
                        .get(d -> c(d).segments()))
                .attr(num("length", "metres", "Skeleton length.").range(ComponentDef.MIN_LENGTH, ComponentDef.MAX_LENGTH)
                        .required()
                        .get(d -> c(d).length()))
                .attr(num("baseWidth", "metres", "Width at the base.").range(ComponentDef.MIN_WIDTH, ComponentDef.MAX_WIDTH)
                        .required()
                        .get(d -> c(d).baseWidth()))
                .attr(num("tipWidth", "metres", "Width at the tip.").range(0, ComponentDef.MAX_WIDTH)
                        .def(ComponentDef.DEFAULT_TIP_WIDTH).get(d -> c(d).tipWidth()))
                .attr(angle("curvature", "Rest curvature over the whole length, before gravity.")
                        .range(-ComponentDef.MAX_CURVATURE_DEGREES, ComponentDef.MAX_CURVATURE_DEGREES)
                        .def(ComponentDef.DEFAULT_CURVATURE).get(d -> c(d).curvature()))
                .attr(angle("twist", "Twist around the skeleton over the whole length.")
                        .range(-ComponentDef.MAX_TWIST_DEGREES, ComponentDef.MAX_TWIST_DEGREES)
                        .def(ComponentDef.DEFAULT_TWIST).get(d -> c(d).twist()))
                .attr(angle("tilt", "Angle of the base from vertical.").range(0, ComponentDef.MAX_TILT_DEGREES)
                        .def(ComponentDef.DEFAULT_TILT).get(d -> c(d).tilt()))
                .attr(num("mass", "kg", "Mass.").range(ComponentDef.MIN_MASS, ComponentDef.MAX_MASS).required()
                        .get(d -> c(d).mass()))
                .attr(num("stiffness", "N/m", "Spring constant PC of equation 4.")
                        .range(ComponentDef.MIN_STIFFNESS, ComponentDef.MAX_STIFFNESS).required()
                        .get(d -> c(d).stiffness()))
                .attr(num("responseTime", "seconds", "Response time tau of the spring.")
                        .range(ComponentDef.MIN_RESPONSE_TIME, ComponentDef.MAX_RESPONSE_TIME)
                        .def(ComponentDef.DEFAULT_RESPONSE_TIME)
                        .get(d -> c(d).responseTime()))
                .attr(num("dragArea", "m^2", "Drag coefficient times area: force = 0.5 rho dragArea |u| u.")
                        .range(0, ComponentDef.MAX_DRAG_AREA).def(ComponentDef.DEFAULT_DRAG_AREA)
                        .get(d -> c(d).dragArea()))
                .attr(AttrSpec.of("colour", COLOUR, "", "Base colour.").def(ComponentDef.DEFAULT_COLOUR)
                        .get(d -> c(d).colour()))
                .attr(AttrSpec.of("texture", PATH, "", "Image drawn on the component (PNG, alpha cuts its outline), "
                        + "relative to the scene file, at most " + org.jecosys.plant.PlantTextures.MAX_SIDE + " pixels a "
                        + "side: along the skeleton for a strip (bottom row at the base, top row at the tip), centred "
                        + "for a fan; colour tints it (#ffffff: as drawn).").get(d -> c(d).texture()))
                .attr(AttrSpec.of("mesh", PATH, "", "A glTF 2.0 mesh (.gltf with its buffers beside it, or .glb), relative "
                        + "to the scene file: drawn instead of the strip or fan where the component uses all its "
                        + "segments in triangles (its strip and lines elsewhere). Triangles only, at most "
                        + org.jecosys.plant.MeshGeometry.MAX_VERTICES + " vertices; with a texture it needs TEXCOORD_0.")
                        .get(d -> c(d).mesh() == null ? null : c(d).mesh().path()))
                .attr(enumeration("meshMode", words(org.jecosys.plant.MeshMode.values(), org.jecosys.plant.MeshMode::xmlName),
                        "How the mesh follows the skeleton: bound (its height spans the skeleton, each vertex bends "
                        + "with it at its own height) or rigid (its origin rides the tip, +Y along the last segment).")
                        .def(org.jecosys.plant.MeshDef.DEFAULT_MODE.xmlName())
                        .get(d -> (c(d).mesh() == null ? org.jecosys.plant.MeshDef.DEFAULT_MODE : c(d).mesh().mode()).xmlName()))
                .attr(num("meshScale", "", "Scale of the mesh's coordinates (metres as modelled): a rigid mesh's "
                        + "size; a bound mesh's X and Z after its height was fitted to the length.")
                        .range(org.jecosys.plant.MeshDef.MIN_SCALE, org.jecosys.plant.MeshDef.MAX_SCALE)
                        .def(org.jecosys.plant.MeshDef.DEFAULT_SCALE)
                        .get(d -> c(d).mesh() == null ? org.jecosys.plant.MeshDef.DEFAULT_SCALE : c(d).mesh().scale()))
                .attr(AttrSpec.of("lodSegments", INT_LIST, "", "Per level of detail of the species, segments used "
                        + "there (0 = not drawn); one value per lod, each at most segments.").range(0, ComponentDef.MAX_SEGMENTS)
                        .items(1, MAX_LODS).required().get(d -> c(d).lodSegments()));
        ElementSpec species = new ElementSpec("species", "A plant species (paper section 4.1, Tables 1-3).")
                .attr(AttrSpec.of("id", ID, "", "Unique species id; distributions refer to it.").required()
                        .get(d -> ((SpeciesDef) d).id()))
                .attr(AttrSpec.of("name", TEXT, "", "Human-readable name.").def("")
                        .get(d -> ((SpeciesDef) d).name()))
                .attr(integer("poses", "Pose-table size K, from rest to maxBend.").range(2, SpeciesDef.MAX_POSES)
                        .def(SpeciesDef.DEFAULT_POSES).get(d -> ((SpeciesDef) d).poses()))
                .attr(angle("maxBend", "Bend of the last pose beyond the rest shape.")
                        .range(SpeciesDef.MIN_MAX_BEND_DEGREES, SpeciesDef.MAX_MAX_BEND_DEGREES)
                        .def(SpeciesDef.DEFAULT_MAX_BEND).get(d -> ((SpeciesDef) d).maxBend()))
                .attr(num("recovery", "seconds", "Trails: a push of the point flows (source, sink, vortex, blast; not the ambient wind) past flattenAt leaves the plant flattened, "
                        + "recovering over this time (74% left after it, 4% after five); 0 = no trails.")
                        .range(0, TrailDef.MAX_RECOVERY).def(0.0).get(d -> ((SpeciesDef) d).trail().recovery()))
                .attr(num("flattenAt", "", "Trails: the equilibrium bend, as a fraction of the bend limit, beyond "
                        + "which a push flattens the plant (with recovery > 0).")
                        .range(TrailDef.MIN_FLATTEN_AT, TrailDef.MAX_FLATTEN_AT).def(TrailDef.DEFAULT_FLATTEN_AT)
                        .get(d -> ((SpeciesDef) d).trail().flattenAt()))
                .child(lod, 1, MAX_LODS, d -> ((SpeciesDef) d).lods())
                .child(variation, 0, 1, d -> List.of(((SpeciesDef) d).variation()))
                .child(component, 1, MAX_COMPONENTS, d -> ((SpeciesDef) d).components());

        ElementSpec distribution = new ElementSpec("distribution", "A competitive distribution of one species "
                + "(paper section 4.3).")
                .attr(AttrSpec.of("species", ID, "", "Id of the species.").required().get(d -> dist(d).species()))
                .attr(integer("count", "Exact number of plants, or -1 to use density.")
                        .range(-1, DistributionDef.MAX_COUNT).def(DistributionDef.DEFAULT_COUNT)
                        .get(d -> dist(d).count()))
                .attr(num("density", "plants/m^2", "Plants per square metre where conditions hold (count -1).")
                        .range(0, DistributionDef.MAX_DENSITY).def(DistributionDef.DEFAULT_DENSITY)
                        .get(d -> dist(d).density()))
                .attr(num("minWater", "", "Lowest water level accepted.").range(0, 1)
                        .def(DistributionDef.DEFAULT_MIN_WATER)
                        .get(d -> dist(d).minWater()))
                .attr(num("maxWater", "", "Highest water level accepted.").range(0, 1)
                        .def(DistributionDef.DEFAULT_MAX_WATER)
                        .get(d -> dist(d).maxWater()))
                .attr(num("minNutrients", "", "Lowest nutrient level accepted.").range(0, 1)
                        .def(DistributionDef.DEFAULT_MIN_NUTRIENTS)
                        .get(d -> dist(d).minNutrients()))
                .attr(num("maxNutrients", "", "Highest nutrient level accepted.").range(0, 1)
                        .def(DistributionDef.DEFAULT_MAX_NUTRIENTS)
                        .get(d -> dist(d).maxNutrients()))
                .attr(angle("maxSlope", "Steepest ground accepted.").range(0, DistributionDef.MAX_SLOPE_DEGREES)
                        .def(DistributionDef.DEFAULT_MAX_SLOPE).get(d -> dist(d).maxSlope()))
                .attr(num("minAltitude", "metres", "Lowest terrain height accepted.")
                        .range(-DistributionDef.MAX_ALTITUDE, DistributionDef.MAX_ALTITUDE)
                        .def(DistributionDef.DEFAULT_MIN_ALTITUDE).get(d -> dist(d).minAltitude()))
                .attr(num("maxAltitude", "metres", "Highest terrain height accepted.")
                        .range(-DistributionDef.MAX_ALTITUDE, DistributionDef.MAX_ALTITUDE)
                        .def(DistributionDef.DEFAULT_MAX_ALTITUDE).get(d -> dist(d).maxAltitude()))
                .attr(num("footprint", "metres", "Radius of ground a plant takes.")
                        .range(DistributionDef.MIN_FOOTPRINT, DistributionDef.MAX_FOOTPRINT)
                        .def(DistributionDef.DEFAULT_FOOTPRINT).get(d -> dist(d).footprint()))
                .attr(num("waterUse", "", "Water level a plant consumes in its footprint.").range(0, 1)
                        .def(DistributionDef.DEFAULT_WATER_USE).get(d -> dist(d).waterUse()))
                .attr(num("nutrientUse", "", "Nutrient level a plant consumes in its footprint.").range(0, 1)
                        .def(DistributionDef.DEFAULT_NUTRIENT_USE).get(d -> dist(d).nutrientUse()))
                .attr(num("clumpSize", "metres", "Typical radius of a clump (patch) of this species.")
                        .range(DistributionDef.MIN_CLUMP_SIZE, DistributionDef.MAX_CLUMP_SIZE)
                        .def(DistributionDef.DEFAULT_CLUMP_SIZE).get(d -> dist(d).clumpSize()))
                .attr(num("clumpStrength", "", "How strongly plants gather into clumps: 0 spreads them evenly over "
                        + "the suitable ground, 1 places them only inside the clumps.").range(0, 1)
                        .def(DistributionDef.DEFAULT_CLUMP_STRENGTH).get(d -> dist(d).clumpStrength()))
                .attr(num("tuftSize", "metres", "Standard deviation of a tuft's plants around their shared centre "
                        + "(read only when tuftCount is above 1).")
                        .range(DistributionDef.MIN_TUFT_SIZE, DistributionDef.MAX_TUFT_SIZE)
                        .def(DistributionDef.DEFAULT_TUFT_SIZE).get(d -> dist(d).tuftSize()))
                .attr(integer("tuftCount", "Candidates drawn around each tuft centre: above 1 gathers plants into "
                        + "small groups (tussocks) inside the clumps; 1 draws every plant on its own.")
                        .range(1, DistributionDef.MAX_TUFT_COUNT).def(DistributionDef.DEFAULT_TUFT_COUNT)
                        .get(d -> dist(d).tuftCount()))
                .attr(integer("tuftBunches", "Bunches a tuft splits into (a bunchgrass's hollow crown): each of its "
                        + "plants joins one at random, and the bunches stand spaced about evenly on a ring of radius "
                        + "tuftRing round the tuft's centre, turned at random; 1 keeps one bunch at the centre.")
                        .range(1, DistributionDef.MAX_TUFT_BUNCHES).def(DistributionDef.DEFAULT_TUFT_BUNCHES)
                        .get(d -> dist(d).tuftBunches()))
                .attr(num("tuftRing", "metres", "Radius of the ring a tuft's bunches stand on (read only when "
                        + "tuftBunches and tuftCount are above 1).")
                        .range(0, DistributionDef.MAX_TUFT_SIZE).def(DistributionDef.DEFAULT_TUFT_RING)
                        .get(d -> dist(d).tuftRing()));
        ElementSpec plant = new ElementSpec("plant", "One plant placed by hand.")
                .attr(AttrSpec.of("species", ID, "", "Id of the species.").required()
                        .get(d -> ((PlacementDef) d).species()))
                .attr(num("x", "metres", "X.").range(-Waypoint.MAX_COORDINATE, Waypoint.MAX_COORDINATE).required()
                        .get(d -> ((PlacementDef) d).x()))
                .attr(num("z", "metres", "Z.").range(-Waypoint.MAX_COORDINATE, Waypoint.MAX_COORDINATE).required()
                        .get(d -> ((PlacementDef) d).z()))
                .attr(angle("azimuth", "Rest azimuth.")
                        .range(-PlacementDef.MAX_AZIMUTH_DEGREES, PlacementDef.MAX_AZIMUTH_DEGREES).def(0.0)
                        .get(d -> ((PlacementDef) d).azimuth()));
        SPECIES = species;
        DISTRIBUTION = distribution;
        PLANT = plant;
    }
}
