package org.jecosys.scene;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.Supplier;
import org.jecosys.anim.AnimationDef;
import org.jecosys.anim.AnimationMode;
import org.jecosys.field.ForceFieldDef;
import org.jecosys.math.CameraDef;
import org.jecosys.math.Rgb;
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
import org.jecosys.terrain.ImageFiles;
import org.jecosys.terrain.ImageSource;
import org.jecosys.terrain.PlacementDef;
import org.jecosys.terrain.ResourceMapDef;
import org.jecosys.terrain.TerrainDef;
import org.jecosys.wind.ActivationDef;
import org.jecosys.wind.FlowDef;
import org.jecosys.wind.FlowKind;
import org.jecosys.wind.MotionDef;

/**
 * Builds the Def records from validated {@link Values}, checking what a single attribute cannot
 * show: unique ids, references to species and components, ascending levels of detail, min below
 * max, ramps within durations, images that can be read (through the scene's {@link ImageSource}, once:
 * their bytes are kept in {@link #checked}) and decoded. Every problem is reported at the attribute
 * or element it concerns. One instance per load; not thread-safe.
 */
final class SceneBinder {
    private final SceneValidator out;
    /** Where the images the scene names are read from, or null to skip the image checks. */
    private final ImageSource source;
    /** The images the scene names, with their sizes (from their headers). */
    final List<SceneBudget.Image> images = new ArrayList<>();
    /** The bytes of each image that was checked, by the path the scene writes: the bytes the build decodes. */
    final Map<String, byte[]> checked = new HashMap<>();

    SceneBinder(SceneValidator out, ImageSource source) {
        this.out = out;
        this.source = source;
    }

    /** {@return where the scene's files are read from, or null when the image checks are skipped} */
    ImageSource source() {
        return source;
    }

    void problem(Values v, String attr, String message) {
        int[] w = v.where(attr);
        out.problem(w[0], w[1], message);
    }

    /**
     * Runs a Def constructor; a check it makes that the schema missed is reported at the attribute
     * its message names first (e.g. "maxAltitude must be ..."), else at the element.
     */
    <T> T make(Values v, Supplier<T> ctor) {
        try {
            return ctor.get();
        } catch (IllegalArgumentException e) {
            String m = String.valueOf(e.getMessage());
            int end = 0;
            while (end < m.length() && Character.isJavaIdentifierPart(m.charAt(end))) {
                end++;
            }
            int[] w = v.where(m.substring(0, end));
            out.problem(w[0], w[1], "<" + v.node.name + ">: " + m);
            return null;
        }
    }

    SceneDef bind(Values root) {
        TerrainDef terrain = terrain(root.child("terrain"));
        List<SpeciesDef> species = new ArrayList<>();
        Map<String, Values> speciesIds = new HashMap<>();
        for (Values s : root.children("species")) {
            String id = s.str("id");
            if (speciesIds.containsKey(id)) {
                problem(s, "id", "duplicate species id '" + id + "' (first defined at line "
                        + speciesIds.get(id).node.line + ")");
            } else {
                speciesIds.put(id, s);
            }
            SpeciesDef def = species(s);
            if (def != null) {
                species.add(def);
            }
        }
        List<String> known = new ArrayList<>(speciesIds.keySet());
        known.sort(null);
        List<DistributionDef> distributions = new ArrayList<>();
        for (Values d : root.children("distribution")) {
            checkSpeciesRef(d, speciesIds, known);
            DistributionDef def = distribution(d);
            if (def != null) {
                distributions.add(def);
            }
        }
        List<PlacementDef> placements = new ArrayList<>();
        for (Values p : root.children("plant")) {
            checkSpeciesRef(p, speciesIds, known);
            if (terrain != null) {
                insideTerrain(p, "x", terrain.sizeX());
                insideTerrain(p, "z", terrain.sizeZ());
            }
            PlacementDef def = make(p, () -> new PlacementDef(p.str("species"), p.num("x"), p.num("z"),
                    p.num("azimuth")));
            if (def != null) {
                placements.add(def);
            }
        }
        List<FlowDef> flows = new ArrayList<>();
        Values wind = root.child("wind");
        if (wind != null) {
            Map<String, Integer> flowIds = new HashMap<>();
            for (Values f : wind.children) {
                String id = f.str("id");
                if (flowIds.containsKey(id)) {
                    problem(f, "id", "duplicate flow id '" + id + "' (first defined at line " + flowIds.get(id) + ")");
                } else {
                    flowIds.put(id, f.node.line);
                }
                FlowDef def = flow(f);
                if (def != null) {
                    flows.add(def);
                }
            }
        }
        org.jecosys.world.WorldDef world = null;
        Values wv = root.child("world");
        if (wv != null) {
            world = make(wv, () -> new org.jecosys.world.WorldDef(wv.num("tileSize"), wv.num("radius"),
                    wv.num("reliefHeight"), wv.num("reliefWavelength"), wv.integer("reliefOctaves"),
                    wv.longValue("seed")));
            if (world != null) {
                WorldRules.check(root, wv, world, species, distributions, this::problem, () -> out.problems().isEmpty());
            }
        }
        ForceFieldDef field = field(root.child("field"));
        CameraDef camera = camera(root.child("camera"));
        AnimationDef animation = animation(root.child("animation"));
        RenderDef render = render(root.child("render"));
        if (out.problems().isEmpty() && species.isEmpty()) {
            // the schema allows it (a scene is written top down), a run does not: nothing to animate
            int[] w = {root.node.line, root.node.column};
            out.problem(w[0], w[1], "<scene> has no <species>: a scene needs at least one species to grow plants "
                    + "(paper section 4.1), even when it places none");
        }
        if (!out.problems().isEmpty() || terrain == null || field == null || camera == null || animation == null
                || render == null || wv != null && world == null) {
            return null;
        }
        org.jecosys.world.WorldDef open = world;
        return make(root, () -> new SceneDef(root.integer("version"), root.str("name"), root.longValue("seed"),
                terrain, species, distributions, placements, flows, field, camera, animation, render, open));
    }

    /** A hand-placed plant stands on the terrain, which spans [-size/2, size/2] (as floats, like the layout). */
    private void insideTerrain(Values p, String attr, double size) {
        float c = (float) p.num(attr);
        if (c < -size / 2 || c > size / 2) {
            problem(p, attr, "attribute '" + attr + "' of <plant>: " + SceneWriter.formatNumber(p.num(attr))
                    + " lies outside the terrain, which spans [" + SceneWriter.formatNumber(-size / 2) + ", "
                    + SceneWriter.formatNumber(size / 2) + "] metres along " + attr.toUpperCase(java.util.Locale.ROOT));
        }
    }

    private void checkSpeciesRef(Values v, Map<String, Values> ids, List<String> known) {
        String ref = v.str("species");
        if (ref != null && !ids.containsKey(ref)) {
            problem(v, "species", "attribute 'species' of <" + v.node.name + ">: undefined species '" + ref + "'"
                    + Names.didYouMean(ref, known) + (known.isEmpty() ? "; no species is defined"
                    : "; defined: " + String.join(", ", known)));
        }
    }

    private TerrainDef terrain(Values t) {
        ResourceMapDef water = resourceMap(t.child("water"));
        ResourceMapDef nutrients = resourceMap(t.child("nutrients"));
        String heightmap = t.str("heightmap");
        checkFile(t, "heightmap", heightmap);
        if (water == null || nutrients == null) {
            return null;
        }
        return make(t, () -> new TerrainDef(t.num("sizeX"), t.num("sizeZ"), t.integer("resolution"),
                t.num("heightScale"), t.num("roughness"), t.longValue("seed"), heightmap, water, nutrients));
    }

    private ResourceMapDef resourceMap(Values m) {
        if (m == null) {
            return ResourceMapDef.UNIFORM_FULL;
        }
        ResourceMapDef.Source source = byXml(ResourceMapDef.Source.values(), m.str("source"));
        String image = m.str("image");
        if (source == ResourceMapDef.Source.IMAGE && image == null) {
            problem(m, "source", "<" + m.node.name + "> with source=\"image\" needs an 'image' attribute");
            return null;
        }
        if (source != ResourceMapDef.Source.IMAGE && image != null) {
            problem(m, "image", "attribute 'image' of <" + m.node.name + "> is allowed only with source=\"image\"");
            return null;
        }
        checkFile(m, "image", image);
        return make(m, () -> new ResourceMapDef(source, m.integer("resolution"), m.num("amount"), m.num("scale"),
                image));
    }

    void checkFile(Values v, String attr, String path) {
        if (path == null || source == null) {
            return;
        }
        try {
            byte[] bytes = checked.get(path);
            if (bytes == null) {
                bytes = source.read(path); // read once: the bytes checked here are the bytes the build decodes
            }
            // the size from the header, bounded before decoding; then the data, at reduced resolution
            ImageFiles.Size size = ImageFiles.verify("'" + path + "'", bytes);
            images.add(new SceneBudget.Image(v, attr, size, checked.containsKey(path) ? 0 : bytes.length));
            checked.put(path, bytes);
        } catch (java.io.IOException e) {
            problem(v, attr, "attribute '" + attr + "' of <" + v.node.name + ">: " + e.getMessage());
        }
    }

    private SpeciesDef species(Values s) {
        List<Values> lodValues = s.children("lod");
        List<LodDef> lods = new ArrayList<>();
        double prev = 0;
        for (int i = 0; i < lodValues.size(); i++) {
            Values l = lodValues.get(i);
            double d = l.num("maxDistance");
            boolean last = i == lodValues.size() - 1;
            if (last && d != Double.POSITIVE_INFINITY) {
                problem(l, "maxDistance", "the last <lod> of species '" + s.str("id")
                        + "' covers every farther distance: leave out its maxDistance");
            } else if (!last && d == Double.POSITIVE_INFINITY) {
                problem(l, "maxDistance", "<lod> needs a maxDistance: only the last level is unbounded");
            } else if (d <= prev) {
                problem(l, "maxDistance", "lod maxDistance must ascend: " + SceneWriter.formatNumber(d)
                        + " is not above " + SceneWriter.formatNumber(prev));
            }
            prev = d == Double.POSITIVE_INFINITY ? prev : d;
            lods.add(make(l, () -> new LodDef(l.num("maxDistance"), byXml(Primitive.values(), l.str("primitive")))));
        }
        Values varV = s.child("variation");
        VariationDef variation = varV == null ? VariationDef.NONE : make(varV, () -> new VariationDef(
                varV.integer("variants"), varV.num("length"), varV.num("width"), varV.num("curvature"),
                varV.num("tilt"), varV.num("responseTime"), varV.num("stiffness"), varV.num("hue"), varV.num("value"),
                varV.num("dryTips"), varV.num("size"), varV.integer("sizeClasses"), varV.num("azimuth")));
        List<Values> compValues = s.children("component");
        Set<String> compIds = new HashSet<>();
        for (Values c : compValues) {
            if (!compIds.add(c.str("id"))) {
                problem(c, "id", "duplicate component id '" + c.str("id") + "' in species '" + s.str("id") + "'");
            }
        }
        List<ComponentDef> components = new ArrayList<>();
        for (Values c : compValues) {
            ComponentDef def = ComponentBinder.component(this, c, compIds, lodValues.size());
            if (def != null) {
                components.add(def);
            }
        }
        if (lods.contains(null) || variation == null || components.size() != compValues.size()
                || !out.problems().isEmpty()) {
            return null;
        }
        String name = s.str("name").isEmpty() ? s.str("id") : s.str("name");
        return make(s, () -> new SpeciesDef(s.str("id"), name, s.integer("poses"), s.num("maxBend"), components,
                lods, variation, new TrailDef(s.num("recovery"), s.num("flattenAt"))));
    }

    private DistributionDef distribution(Values d) {
        boolean ok = minMax(d, "minWater", "maxWater") & minMax(d, "minNutrients", "maxNutrients")
                & minMax(d, "minAltitude", "maxAltitude");
        if (!ok) {
            return null;
        }
        return make(d, () -> new DistributionDef(d.str("species"), d.integer("count"), d.num("density"),
                d.num("minWater"), d.num("maxWater"), d.num("minNutrients"), d.num("maxNutrients"),
                d.num("maxSlope"), d.num("minAltitude"), d.num("maxAltitude"), d.num("footprint"),
                d.num("waterUse"), d.num("nutrientUse"), d.num("clumpSize"), d.num("clumpStrength"),
                d.num("tuftSize"), d.integer("tuftCount"), d.integer("tuftBunches"), d.num("tuftRing")));
    }

    private boolean minMax(Values v, String min, String max) {
        if (v.num(min) > v.num(max)) {
            String at = v.present(max) ? max : min;
            problem(v, at, "<" + v.node.name + ">: " + min + "=" + SceneWriter.formatNumber(v.num(min))
                    + " is above " + max + "=" + SceneWriter.formatNumber(v.num(max)));
            return false;
        }
        return true;
    }

    private FlowDef flow(Values f) {
        FlowKind kind = null;
        for (FlowKind k : FlowKind.values()) {
            if (k.xmlName().equals(f.node.name)) {
                kind = k;
            }
        }
        double duration = f.num("duration");
        double ramps = f.num("rampIn") + f.num("rampOut");
        if (duration != Double.POSITIVE_INFINITY && ramps > duration) {
            problem(f, "rampOut", "<" + f.node.name + " id=\"" + f.str("id") + "\">: rampIn + rampOut = "
                    + SceneWriter.formatNumber(ramps) + " s is longer than duration = "
                    + SceneWriter.formatNumber(duration) + " s");
            return null;
        }
        Values path = f.child("path");
        boolean advected = f.bool("advected");
        if (path != null && advected) {
            problem(f, "advected", "<" + f.node.name + " id=\"" + f.str("id")
                    + "\"> cannot both follow a <path> and be advected; choose one");
            return null;
        }
        MotionDef motion = MotionDef.FIXED;
        if (path != null) {
            motion = make(path, () -> new MotionDef(MotionDef.Kind.PATH, waypoints(path), path.num("speed"),
                    path.bool("loop")));
        } else if (advected) {
            motion = MotionDef.ADVECTED;
        }
        if (motion == null) {
            return null;
        }
        ActivationDef activation = make(f, () -> new ActivationDef(f.num("start"), duration, f.num("rampIn"),
                f.num("rampOut")));
        if (activation == null) {
            return null;
        }
        FlowKind k = kind;
        MotionDef m = motion;
        return make(f, () -> new FlowDef(f.str("id"), k, f.bool("enabled"), f.num("x"), f.num("z"),
                f.num("strength"), numOr(f, "direction", FlowDef.DEFAULT_DIRECTION), f.num("coreRadius"),
                f.num("influenceRadius"), activation, m, numOr(f, "noiseScale", FlowDef.DEFAULT_NOISE_SCALE),
                numOr(f, "noiseFrequency", FlowDef.DEFAULT_NOISE_FREQUENCY),
                f.values.containsKey("seed") ? f.longValue("seed") : FlowDef.DEFAULT_SEED,
                numOr(f, "gustStrength", FlowDef.DEFAULT_GUST_STRENGTH),
                numOr(f, "turbulence", FlowDef.DEFAULT_TURBULENCE),
                numOr(f, "gustStretch", FlowDef.DEFAULT_GUST_STRETCH)));
    }

    private static double numOr(Values v, String name, double fallback) {
        return v.values.containsKey(name) ? v.num(name) : fallback;
    }

    private static List<Waypoint> waypoints(Values path) {
        List<Waypoint> out = new ArrayList<>();
        for (Values w : path.children("waypoint")) {
            out.add(new Waypoint(w.num("x"), w.values.containsKey("y") ? w.num("y") : 0, w.num("z")));
        }
        return out;
    }

    @SuppressWarnings("unchecked")
    private ForceFieldDef field(Values f) {
        if (f == null) {
            return ForceFieldDef.defaults();
        }
        List<Double> distances = (List<Double>) f.get("lodDistances");
        for (int i = 1; i < distances.size(); i++) {
            if (distances.get(i) <= distances.get(i - 1)) {
                problem(f, "lodDistances", "attribute 'lodDistances' of <field>: distances must ascend strictly, got "
                        + f.node.attrs.get("lodDistances").value().strip());
                return null;
            }
        }
        if (!minMax(f, "thinStart", "thinEnd")) {
            return null;
        }
        return make(f, () -> new ForceFieldDef(f.bool("enabled"), f.integer("maxObjectsPerNode"),
                f.integer("maxDepth"), distances, f.num("thinStart"), f.num("thinEnd"), f.num("thinMinFraction"),
                f.num("lodFovY")));
    }

    private CameraDef camera(Values c) {
        if (c == null) {
            return CameraDef.defaults();
        }
        if (c.num("far") <= c.num("near")) {
            problem(c, "far", "<camera>: far=" + SceneWriter.formatNumber(c.num("far")) + " must be greater than near="
                    + SceneWriter.formatNumber(c.num("near")));
            return null;
        }
        Values path = c.child("path");
        List<Waypoint> wps = path == null ? List.of() : waypoints(path);
        ElementSpec pathSpec = c.spec.childSpec("path").spec;
        double speed = path == null ? (Double) pathSpec.attrSpec("speed").defaultValue : path.num("speed");
        boolean loop = path == null ? (Boolean) pathSpec.attrSpec("loop").defaultValue : path.bool("loop");
        return make(c, () -> new CameraDef(c.num("x"), c.num("y"), c.num("z"), c.num("yaw"), c.num("pitch"),
                c.num("fovY"), c.num("near"), c.num("far"), wps, speed, loop));
    }

    private AnimationDef animation(Values a) {
        if (a == null) {
            return AnimationDef.defaults();
        }
        return make(a, () -> new AnimationDef(byXml(AnimationMode.values(), a.str("mode")), a.num("fixedStep"),
                a.integer("maxSubSteps"), a.integer("subIntervals"), a.integer("threads"), a.longValue("seed"),
                a.num("prewarm")));
    }

    private RenderDef render(Values r) {
        if (r == null) {
            return RenderDef.defaults();
        }
        Values lv = r.child("light");
        RenderDef.Light light = lv == null ? RenderDef.Light.DEFAULT : make(lv, () -> new RenderDef.Light(
                lv.num("sunAzimuth"), lv.num("sunElevation"), (Rgb) lv.get("sunColour"), lv.num("sunIntensity"),
                (Rgb) lv.get("skyZenith"), (Rgb) lv.get("ambient"), lv.num("contactShadow"), lv.num("fogStart"),
                lv.num("fogEnd"), lv.num("sheen"), lv.num("shadows"), lv.num("clouds")));
        Values pv = r.child("patches");
        RenderDef.Patches patches = pv == null ? RenderDef.Patches.DEFAULT : make(pv, () -> new RenderDef.Patches(
                pv.num("scale"), pv.num("strength"), pv.integer("seed")));
        Values gv = r.child("groundCover");
        RenderDef.GroundCover cover = gv == null ? RenderDef.GroundCover.NONE : make(gv,
                () -> new RenderDef.GroundCover(gv.num("amount"), gv.num("height"), gv.num("density"), gv.num("reach"),
                        gv.num("spread"), (Rgb) gv.get("colour"), (Rgb) gv.get("dryColour")));
        if (light == null || patches == null || cover == null) {
            return null;
        }
        return make(r, () -> new RenderDef(r.integer("width"), r.integer("height"), (Rgb) r.get("sky"),
                r.num("lodTransition"), byXml(RenderDef.Tint.values(), r.str("terrainTint")), r.bool("showField"),
                r.bool("showWind"), light, patches, Integer.parseInt(r.str("antialiasing")), cover));
    }

    /** The constant whose xmlName() is {@code word}; the validator has already checked it exists. */
    static <E extends Enum<E>> E byXml(E[] constants, String word) {
        for (E e : constants) {
            if (xmlName(e).equals(word)) {
                return e;
            }
        }
        throw new IllegalStateException("no constant '" + word + "'");
    }

    private static String xmlName(Enum<?> e) {
        if (e instanceof ComponentType t) {
            return t.xmlName();
        } else if (e instanceof ComponentShape s) {
            return s.xmlName();
        } else if (e instanceof Primitive p) {
            return p.xmlName();
        } else if (e instanceof ResourceMapDef.Source s) {
            return s.xmlName();
        } else if (e instanceof AnimationMode m) {
            return m.xmlName();
        } else if (e instanceof RenderDef.Tint t) {
            return t.xmlName();
        } else if (e instanceof FlowKind k) {
            return k.xmlName();
        }
        throw new IllegalStateException("enum without xml name: " + e);
    }
}
