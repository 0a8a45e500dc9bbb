package org.jecosys.scene;

import static org.jecosys.scene.AttrType.ANGLE;
import static org.jecosys.scene.AttrType.BOOL;
import static org.jecosys.scene.AttrType.DOUBLE;
import static org.jecosys.scene.AttrType.DOUBLE_LIST;
import static org.jecosys.scene.AttrType.ENUM;
import static org.jecosys.scene.AttrType.ID;
import static org.jecosys.scene.AttrType.INT;
import static org.jecosys.scene.AttrType.LONG;
import static org.jecosys.scene.AttrType.PATH;
import static org.jecosys.scene.AttrType.TEXT;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Function;
import org.jecosys.anim.AnimationDef;
import org.jecosys.anim.AnimationMode;
import org.jecosys.field.ForceFieldDef;
import org.jecosys.math.CameraDef;
import org.jecosys.math.Waypoint;
import org.jecosys.terrain.ResourceMapDef;
import org.jecosys.terrain.TerrainDef;
import org.jecosys.wind.ActivationDef;
import org.jecosys.wind.FlowDef;
import org.jecosys.wind.FlowKind;
import org.jecosys.wind.MotionDef;
import org.jecosys.world.WorldDef;

/**
 * The scene format, version 1, as one table: every element and attribute with its type, range,
 * default, units and documentation. The loader validates against it, the writer saves from it and
 * {@link SchemaXsd} generates {@code scenes/jecosys-scene.xsd} from it, so the three cannot drift.
 * Attribute names equal the Def record components they fill. Angles are degrees in files and
 * radians in Defs. Immutable after class initialisation; any thread.
 */
final class SceneSchema {
    /** Largest scene file accepted, bytes. */
    static final long MAX_FILE_BYTES = 8L * 1024 * 1024;
    static final int MAX_SPECIES = 64;
    static final int MAX_COMPONENTS = 32;
    static final int MAX_LODS = 8;
    static final int MAX_DISTRIBUTIONS = 256;
    static final int MAX_PLANTS = 10_000;
    static final int MAX_FLOWS = 256;
    static final int MAX_WAYPOINTS = 1024;
    static final double INF = Double.POSITIVE_INFINITY;

    static final ElementSpec ROOT;

    private SceneSchema() {
    }

    static AttrSpec num(String name, String units, String doc) {
        return AttrSpec.of(name, DOUBLE, units, doc);
    }

    static AttrSpec angle(String name, String doc) {
        return AttrSpec.of(name, ANGLE, "degrees", doc);
    }

    static AttrSpec integer(String name, String doc) {
        return AttrSpec.of(name, INT, "", doc);
    }

    static AttrSpec bool(String name, String doc) {
        return AttrSpec.of(name, BOOL, "", doc);
    }

    static AttrSpec seed(String doc, Function<Object, Object> g) {
        return AttrSpec.of("seed", LONG, "", doc).def(1L).get(g);
    }

    static <E extends Enum<E>> List<String> words(E[] constants, Function<E, String> xml) {
        List<String> out = new ArrayList<>();
        for (E e : constants) {
            out.add(xml.apply(e));
        }
        return out;
    }

    static AttrSpec enumeration(String name, List<String> words, String doc) {
        return AttrSpec.of(name, ENUM, "", doc).values(words);
    }

    private static ElementSpec resourceMap(String name, String what) {
        Function<Object, ResourceMapDef> pick = d -> (ResourceMapDef) d;
        return new ElementSpec(name, "The " + what + " map over the terrain (paper section 4.3); levels in [0, 1].")
                .attr(enumeration("source", words(ResourceMapDef.Source.values(), ResourceMapDef.Source::xmlName),
                        "How the map is made: uniform level, seeded noise, valleys (water gathers in low ground), "
                                + "or a greyscale image.").def("uniform")
                        .get(d -> pick.apply(d).source().xmlName()))
                .attr(integer("resolution", "Cells per side.").range(2, ResourceMapDef.MAX_RESOLUTION).def(64)
                        .get(d -> pick.apply(d).resolution()))
                .attr(num("amount", "", "Overall level multiplier.").range(0, 1).def(1.0)
                        .get(d -> pick.apply(d).amount()))
                .attr(num("scale", "metres", "Feature size of noise maps.")
                        .range(ResourceMapDef.MIN_SCALE, ResourceMapDef.MAX_SCALE).def(8.0)
                        .get(d -> pick.apply(d).scale()))
                .attr(AttrSpec.of("image", PATH, "", "Greyscale PNG, relative to the scene file; required exactly "
                        + "when source is image.").get(d -> pick.apply(d).image()));
    }

    private static ElementSpec path(String doc, double defaultSpeed, boolean defaultLoop, boolean withY,
                                    Function<Object, List<Waypoint>> waypoints,
                                    Function<Object, Object> speed, Function<Object, Object> loop) {
        ElementSpec wp = new ElementSpec("waypoint", "A point of the path.")
                .attr(num("x", "metres", "X.").range(-Waypoint.MAX_COORDINATE, Waypoint.MAX_COORDINATE).required()
                        .get(d -> ((Waypoint) d).x()))
                .attr(num("z", "metres", "Z.").range(-Waypoint.MAX_COORDINATE, Waypoint.MAX_COORDINATE).required()
                        .get(d -> ((Waypoint) d).z()));
        if (withY) {
            wp.attr(num("y", "metres", "Eye height above the terrain.").range(-Waypoint.MAX_HEIGHT, Waypoint.MAX_HEIGHT)
                    .def(1.7)
                    .get(d -> ((Waypoint) d).y()));
        }
        return new ElementSpec("path", doc)
                .attr(num("speed", "m/s", "Speed along the path.").range(CameraDef.MIN_PATH_SPEED, CameraDef.MAX_PATH_SPEED)
                        .def(defaultSpeed).get(speed))
                .attr(bool("loop", "Start again at the first waypoint after the last.").def(defaultLoop).get(loop))
                .child(wp, 2, MAX_WAYPOINTS, d -> waypoints.apply(d));
    }

    private static ElementSpec flow(FlowKind kind, String doc) {
        ElementSpec e = new ElementSpec(kind.xmlName(), doc)
                .attr(AttrSpec.of("id", ID, "", "Unique name of the flow.").required().get(d -> f(d).id()))
                .attr(bool("enabled", "Whether the flow starts enabled.").def(FlowDef.DEFAULT_ENABLED)
                        .get(d -> f(d).enabled()))
                .attr(num("x", "metres", "Centre X.").range(-Waypoint.MAX_COORDINATE, Waypoint.MAX_COORDINATE)
                        .def(FlowDef.DEFAULT_X).get(d -> f(d).x()))
                .attr(num("z", "metres", "Centre Z.").range(-Waypoint.MAX_COORDINATE, Waypoint.MAX_COORDINATE)
                        .def(FlowDef.DEFAULT_Z).get(d -> f(d).z()));
        String strengthDoc = switch (kind) {
            case UNIFORM -> "Wind speed, m/s.";
            case GUST -> "Mean wind speed, m/s.";
            case SOURCE -> "Source strength a in u = (a / 2 pi) (p - c) / r^2, m^2/s.";
            case SINK -> "Sink strength: a = -strength in u = (a / 2 pi) (p - c) / r^2, m^2/s.";
            case VORTEX -> "Circulation Gamma in u = (Gamma / 2 pi) y x (p - c) / r^2, m^2/s; positive turns "
                    + "counter-clockwise seen from above, negative clockwise.";
            case BLAST -> "Peak source strength of the pulse, m^2/s.";
            case RAIN -> "Strength of each drop's radial burst, m^2/s.";
        };
        e.attr(num("strength", (kind == FlowKind.UNIFORM || kind == FlowKind.GUST) ? "m/s" : "m^2/s", strengthDoc)
                .range(kind == FlowKind.VORTEX ? -FlowDef.MAX_STRENGTH : 0, FlowDef.MAX_STRENGTH).required()
                .get(d -> f(d).strength()));
        if (kind == FlowKind.UNIFORM || kind == FlowKind.GUST) {
            e.attr(angle("direction", "Heading of the wind: 0 is +X, 90 is +Z.")
                    .range(-FlowDef.MAX_DIRECTION_DEGREES, FlowDef.MAX_DIRECTION_DEGREES)
                    .def(FlowDef.DEFAULT_DIRECTION).get(d -> f(d).direction()));
        }
        e.attr(num("coreRadius", "metres", "Within this distance of the centre a singular flow tapers linearly to 0.")
                .range(FlowDef.MIN_CORE_RADIUS, FlowDef.MAX_CORE_RADIUS).def(FlowDef.DEFAULT_CORE_RADIUS)
                .get(d -> f(d).coreRadius()));
        AttrSpec influence = num("influenceRadius", "metres",
                "Beyond this distance from the centre the flow is 0; absent means unbounded.")
                .rangeAbove(0, FlowDef.MAX_INFLUENCE_RADIUS).def(FlowDef.DEFAULT_INFLUENCE_RADIUS)
                .get(d -> f(d).influenceRadius());
        if (kind == FlowKind.RAIN) {
            influence = num("influenceRadius", "metres", "Radius of the rain disc.")
                    .rangeAbove(0, FlowDef.MAX_INFLUENCE_RADIUS).required()
                    .get(d -> f(d).influenceRadius());
        }
        e.attr(influence);
        e.attr(num("start", "seconds", "Simulation time the flow begins.").range(0, ActivationDef.MAX_TIME)
                .def(ActivationDef.DEFAULT_START).get(d -> f(d).activation().start()));
        double defaultDuration = FlowDef.defaultDuration(kind);
        e.attr(num("duration", "seconds", kind == FlowKind.BLAST ? "Length of the pulse."
                        : "How long the flow lasts; absent means forever.")
                .rangeAbove(0, ActivationDef.MAX_TIME).def(defaultDuration).get(d -> f(d).activation().duration()));
        e.attr(num("rampIn", "seconds", "Time to reach full strength.").range(0, ActivationDef.MAX_TIME)
                .def(ActivationDef.DEFAULT_RAMP_IN)
                .get(d -> f(d).activation().rampIn()));
        e.attr(num("rampOut", "seconds", "Time to fade out before the end.").range(0, ActivationDef.MAX_TIME)
                .def(ActivationDef.DEFAULT_RAMP_OUT).get(d -> f(d).activation().rampOut()));
        e.attr(bool("advected", "Whether the centre moves with the other active flows (paper section 3.2); "
                + "not together with a path.").def(false).get(d -> f(d).motion().kind() == MotionDef.Kind.ADVECTED));
        if (kind == FlowKind.GUST || kind == FlowKind.RAIN) {
            e.attr(num("noiseScale", "metres", kind == FlowKind.GUST ? "Spatial size of gusts; the gust pattern travels with the mean wind."
                            : "Radius of one drop's burst.")
                    .range(FlowDef.MIN_NOISE_SCALE, FlowDef.MAX_NOISE_SCALE).def(FlowDef.DEFAULT_NOISE_SCALE)
                    .get(d -> f(d).noiseScale()));
            e.attr(num("noiseFrequency", kind == FlowKind.GUST ? "Hz" : "drops/(s m^2)",
                            kind == FlowKind.GUST ? "How fast the gust pattern changes as it travels (a fixed point sees gusts "
                                    + "about strength / noiseScale times per second)." : "Drops per second per square metre.")
                    .rangeAbove(0, FlowDef.MAX_NOISE_FREQUENCY).def(FlowDef.DEFAULT_NOISE_FREQUENCY)
                    .get(d -> f(d).noiseFrequency()));
            e.attr(AttrSpec.of("seed", LONG, "", "Seed of the noise or drops.").def(FlowDef.DEFAULT_SEED)
                    .get(d -> f(d).seed()));
        }
        if (kind == FlowKind.GUST) {
            e.attr(num("gustStrength", "", "Relative strength of the gusts along and across the mean wind "
                    + "(0.5: the speed varies by up to about half the mean).").range(0, FlowDef.MAX_GUST_STRENGTH)
                    .def(FlowDef.DEFAULT_GUST_STRENGTH).get(d -> f(d).gustStrength()));
            e.attr(num("turbulence", "", "Relative strength of small eddies a quarter of the gust size; 0 for "
                    + "none.").range(0, FlowDef.MAX_TURBULENCE).def(FlowDef.DEFAULT_TURBULENCE)
                    .get(d -> f(d).turbulence()));
            e.attr(num("gustStretch", "", "How many times longer a gust is across the wind than along it: 1 for "
                    + "round gusts; 3 to 5 for the bands of bent, bright blades that run over a field with the wind.")
                    .range(1, FlowDef.MAX_GUST_STRETCH).def(FlowDef.DEFAULT_GUST_STRETCH)
                    .get(d -> f(d).gustStretch()));
        }
        e.child(path("A scripted path the centre walks along.", MotionDef.DEFAULT_PATH_SPEED,
                        MotionDef.DEFAULT_PATH_LOOP, false,
                        d -> ((MotionDef) d).waypoints(), d -> ((MotionDef) d).speed(), d -> ((MotionDef) d).loop()),
                0, 1, d -> f(d).motion().kind() == MotionDef.Kind.PATH ? List.of(f(d).motion()) : List.of());
        return e;
    }

    private static FlowDef f(Object d) {
        return (FlowDef) d;
    }

    private static CameraDef cam(Object d) {
        return (CameraDef) d;
    }

    private static SceneDef scene(Object d) {
        return (SceneDef) d;
    }

    static {
        ElementSpec terrain = new ElementSpec("terrain", "The terrain: a heightfield centred on the origin "
                + "(paper section 4.3).")
                .attr(num("sizeX", "metres", "Extent along X.").range(TerrainDef.MIN_SIZE, TerrainDef.MAX_SIZE).required()
                        .get(d -> ((TerrainDef) d).sizeX()))
                .attr(num("sizeZ", "metres", "Extent along Z.").range(TerrainDef.MIN_SIZE, TerrainDef.MAX_SIZE).required()
                        .get(d -> ((TerrainDef) d).sizeZ()))
                .attr(integer("resolution", "Heightfield vertices per side.").range(2, TerrainDef.MAX_RESOLUTION).def(65)
                        .get(d -> ((TerrainDef) d).resolution()))
                .attr(num("heightScale", "metres", "Highest point above the lowest.").range(0, TerrainDef.MAX_HEIGHT_SCALE)
                        .def(0.0)
                        .get(d -> ((TerrainDef) d).heightScale()))
                .attr(num("roughness", "", "Fractal roughness of the generated relief.").range(0, 1).def(0.5)
                        .get(d -> ((TerrainDef) d).roughness()))
                .attr(seed("Seed of the generated relief.", d -> ((TerrainDef) d).seed()))
                .attr(AttrSpec.of("heightmap", PATH, "", "Greyscale PNG heightmap relative to the scene file; "
                        + "absent to generate the relief.").get(d -> ((TerrainDef) d).heightmap()))
                .child(resourceMap("water", "water"), 0, 1,
                        d -> List.of(((TerrainDef) d).water()))
                .child(resourceMap("nutrients", "nutrient"), 0, 1,
                        d -> List.of(((TerrainDef) d).nutrients()));

        ElementSpec world = new ElementSpec("world", "An open world: plants grow in square tiles within a radius of "
                + "the views, by the density-based distributions, on unbounded rolling hills; tiles behind are let "
                + "go. The simulation streams (the renderer and the viewer do not yet: they show the terrain's "
                + "square).")
                .attr(num("tileSize", "metres", "A tile's side.").range(WorldDef.MIN_TILE_SIZE, WorldDef.MAX_TILE_SIZE)
                        .def(WorldDef.DEFAULT_TILE_SIZE).get(d -> ((WorldDef) d).tileSize()))
                .attr(num("radius", "metres", "Reach of a view: tiles whose square comes this close are live; at "
                        + "most 64 tiles.").rangeAbove(0, WorldDef.MAX_RADIUS).def(WorldDef.DEFAULT_RADIUS)
                        .get(d -> ((WorldDef) d).radius()))
                .attr(num("reliefHeight", "metres", "The hills' largest height above or below 0.")
                        .range(0, WorldDef.MAX_RELIEF_HEIGHT).def(3.0).get(d -> ((WorldDef) d).reliefHeight()))
                .attr(num("reliefWavelength", "metres", "The size of the largest hills.")
                        .range(1, WorldDef.MAX_RELIEF_WAVELENGTH).def(90.0).get(d -> ((WorldDef) d).reliefWavelength()))
                .attr(integer("reliefOctaves", "Noise layers of the hills, each twice as fine and half as high.")
                        .range(1, 12).def(4).get(d -> ((WorldDef) d).reliefOctaves()))
                .attr(seed("Seed of the hills.", d -> ((WorldDef) d).reliefSeed()));

        ElementSpec species = PlantSchema.SPECIES;
        ElementSpec distribution = PlantSchema.DISTRIBUTION;
        ElementSpec plant = PlantSchema.PLANT;

        ElementSpec wind = new ElementSpec("wind", "The wind flows (paper section 3.2), in any order.");
        wind.choice = true;
        wind.maxChildren = MAX_FLOWS;
        wind.choiceItems = d -> scene(d).flows();
        for (FlowKind k : FlowKind.values()) {
            String doc = switch (k) {
                case UNIFORM -> "A uniform flow: constant velocity over the ground.";
                case SOURCE -> "A source: flow away from its centre, falling off as 1/r.";
                case SINK -> "A sink: flow toward its centre, falling off as 1/r.";
                case VORTEX -> "A vortex: flow around its centre, falling off as 1/r.";
                case GUST -> "Turbulent wind: a mean speed with seeded gusts and eddies that travel with it (frozen "
                        + "turbulence).";
                case BLAST -> "A short radial pulse, for explosions.";
                case RAIN -> "Rain over a disc: short seeded radial impulses.";
            };
            wind.choiceChild(flow(k, doc), d -> f(d).kind() == k);
        }

        ElementSpec field = new ElementSpec("field", "The LOD quadtree force field (paper section 3.1).")
                .attr(bool("enabled", "When false no flow is evaluated and plants get no force.").def(true)
                        .get(d -> ((ForceFieldDef) d).enabled()))
                .attr(integer("maxObjectsPerNode", "A leaf splits into four when it would hold more plants.")
                        .range(1, ForceFieldDef.MAX_OBJECTS_PER_NODE).def(ForceFieldDef.DEFAULT_MAX_OBJECTS_PER_NODE)
                        .get(d -> ((ForceFieldDef) d).maxObjectsPerNode()))
                .attr(integer("maxDepth", "Deepest node level (root is 0).").range(0, ForceFieldDef.MAX_DEPTH)
                        .def(ForceFieldDef.DEFAULT_MAX_DEPTH)
                        .get(d -> ((ForceFieldDef) d).maxDepth()))
                .attr(AttrSpec.of("lodDistances", DOUBLE_LIST, "metres", "Ascending distances: beyond the i-th, "
                        + "i levels collapse into their ancestor; empty for no distance LOD.")
                        .rangeAbove(0, ForceFieldDef.MAX_LOD_DISTANCE).items(0, ForceFieldDef.MAX_LOD_DISTANCES)
                        .def(ForceFieldDef.DEFAULT_LOD_DISTANCES)
                        .get(d -> ((ForceFieldDef) d).lodDistances()))
                .attr(num("thinStart", "metres", "Distance thinning of the drawing (for slow GPUs): beyond this "
                        + "distance fewer plants are drawn, the same ones every frame.")
                        .range(0, ForceFieldDef.MAX_LOD_DISTANCE).def(ForceFieldDef.DEFAULT_THIN_START)
                        .get(d -> ((ForceFieldDef) d).thinStart()))
                .attr(num("thinEnd", "metres", "Distance where the drawn share reaches thinMinFraction; at least "
                        + "thinStart.").range(0, ForceFieldDef.MAX_LOD_DISTANCE).def(ForceFieldDef.DEFAULT_THIN_END)
                        .get(d -> ((ForceFieldDef) d).thinEnd()))
                .attr(num("thinMinFraction", "", "Share of plants drawn at and beyond thinEnd; 1 for no thinning.")
                        .range(0, 1).def(ForceFieldDef.DEFAULT_THIN_MIN_FRACTION)
                        .get(d -> ((ForceFieldDef) d).thinMinFraction()))
                .attr(angle("lodFovY", "The vertical field of view every level-of-detail distance is meant for: "
                        + "another lens, or an orthographic view, picks the level a plant's size on screen gives.")
                        .range(ForceFieldDef.MIN_LOD_FOV_DEGREES, ForceFieldDef.MAX_LOD_FOV_DEGREES)
                        .def(ForceFieldDef.DEFAULT_LOD_FOV_Y).get(d -> ((ForceFieldDef) d).lodFovY()));

        ElementSpec camera = new ElementSpec("camera", "The viewer's start pose and optional path (paper section "
                + "5.2).")
                .attr(num("x", "metres", "Eye X.").range(-Waypoint.MAX_COORDINATE, Waypoint.MAX_COORDINATE).def(0.0)
                        .get(d -> cam(d).x()))
                .attr(num("y", "metres", "Eye height above the terrain.").range(-Waypoint.MAX_HEIGHT, Waypoint.MAX_HEIGHT)
                        .def(1.7).get(d -> cam(d).y()))
                .attr(num("z", "metres", "Eye Z.").range(-Waypoint.MAX_COORDINATE, Waypoint.MAX_COORDINATE).def(0.0)
                        .get(d -> cam(d).z()))
                .attr(angle("yaw", "Heading: 0 looks along -Z, positive turns toward +X.")
                        .range(-CameraDef.MAX_YAW_DEGREES, CameraDef.MAX_YAW_DEGREES).def(0.0).get(d -> cam(d).yaw()))
                .attr(angle("pitch", "Positive looks up.").range(-CameraDef.MAX_PITCH_DEGREES, CameraDef.MAX_PITCH_DEGREES)
                        .def(0.0).get(d -> cam(d).pitch()))
                .attr(angle("fovY", "Vertical field of view.").range(CameraDef.MIN_FOV_DEGREES, CameraDef.MAX_FOV_DEGREES)
                        .def(Math.toRadians(60)).get(d -> cam(d).fovY()))
                .attr(num("near", "metres", "Near clip distance.").range(CameraDef.MIN_NEAR, CameraDef.MAX_NEAR).def(0.1)
                        .get(d -> cam(d).near()))
                .attr(num("far", "metres", "Far clip distance, greater than near.").rangeAbove(0, CameraDef.MAX_FAR)
                        .def(500.0)
                        .get(d -> cam(d).far()))
                .child(path("The path the viewer walks (key P in the viewer; benchmarks).", 1.4, true, true,
                                d -> cam(d).path(), d -> cam(d).pathSpeed(), d -> cam(d).pathLoop()),
                        0, 1, d -> cam(d).path().isEmpty() ? List.of() : List.of(d));

        ElementSpec animation = new ElementSpec("animation", "Animation settings (paper section 4.2).")
                .attr(enumeration("mode", words(AnimationMode.values(), AnimationMode::xmlName),
                        "static, random or constraint (paper Table 7's S1, S2, S3).").def("constraint")
                        .get(d -> ((AnimationDef) d).mode().xmlName()))
                .attr(num("fixedStep", "seconds", "Fixed simulation step.").range(1e-5, 1).def(1.0 / 60)
                        .get(d -> ((AnimationDef) d).fixedStep()))
                .attr(integer("maxSubSteps", "Cap on fixed steps per step(dt) call.").range(1, 1000).def(8)
                        .get(d -> ((AnimationDef) d).maxSubSteps()))
                .attr(integer("subIntervals", "Sub-intervals of each step in the spring update (section 4.2.1): a flow "
                        + "switched inside a step acts from the next sub-interval boundary.")
                        .range(1, 64).def(4).get(d -> ((AnimationDef) d).subIntervals()))
                .attr(integer("threads", "Animation workers; 0 means the available processors.").range(0, 256)
                        .def(0).get(d -> ((AnimationDef) d).workers()))
                .attr(seed("Seed of the random mode.", d -> ((AnimationDef) d).seed()))
                .attr(num("prewarm", "seconds", "Wind the simulation runs before its first step, so the first frame is "
                        + "already in motion (the plants start still, at the equilibrium of the wind); 0 starts at t = 0 "
                        + "as the paper's scenes do.").range(0, AnimationDef.MAX_PREWARM).def(0.0)
                        .get(d -> ((AnimationDef) d).prewarm()));

        ElementSpec render = RenderSchema.render();

        ROOT = new ElementSpec("scene", "A JEcoSys scene, format version 1. Children appear in this order.")
                .attr(integer("version", "Format version.").range(SceneDef.FORMAT_VERSION, SceneDef.FORMAT_VERSION)
                        .required().get(d -> scene(d).version()))
                .attr(AttrSpec.of("name", TEXT, "", "Human-readable name.").def("").get(d -> scene(d).name()))
                .attr(seed("Master seed of the scene (distributions, variation).", d -> scene(d).seed()))
                .child(terrain, 1, 1, d -> List.of(scene(d).terrain()))
                .child(world, 0, 1, d -> scene(d).world() == null ? List.of() : List.of(scene(d).world()))
                .child(species, 0, MAX_SPECIES, d -> scene(d).species())
                .child(distribution, 0, MAX_DISTRIBUTIONS, d -> scene(d).distributions())
                .child(plant, 0, MAX_PLANTS, d -> scene(d).placements())
                .child(wind, 0, 1, d -> scene(d).flows().isEmpty() ? List.of() : List.of(d))
                .child(field, 0, 1, d -> List.of(scene(d).field()))
                .child(camera, 0, 1, d -> List.of(scene(d).camera()))
                .child(animation, 0, 1, d -> List.of(scene(d).animation()))
                .child(render, 0, 1, d -> List.of(scene(d).render()));
    }
}
