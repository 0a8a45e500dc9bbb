package org.jecosys.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;

/**
 * One source of truth for ranges: for every numeric attribute of a scene holding every element, a
 * value at the schema's minimum and at its maximum loads (so no Def constructor refuses what the
 * schema allows, which used to surface at the element with the Def's own units), and a value just
 * outside is refused at that attribute, in the attribute's units. Pairs of attributes that bound each
 * other (near below far, ramps within the duration) are listed in {@link #COUPLED}.
 */
class SchemaBoundsTest {
    /** A valid scene with every element and, each on its own line, almost every attribute. */
    static final String TEMPLATE = """
            <scene version="1" name="bounds" seed="7">
            <terrain sizeX="24" sizeZ="24" resolution="17" heightScale="1" roughness="0.5" seed="3">
            <water source="noise" resolution="16" amount="0.9" scale="6"/>
            <nutrients source="noise" resolution="16" amount="0.8" scale="9"/>
            </terrain>
            <species id="s" name="S" poses="8" maxBend="60">
            <lod maxDistance="10"/>
            <lod primitive="lines"/>
            <variation variants="2" length="0.1" width="0.1" curvature="0.1" tilt="5"/>
            <component id="stalk" type="stalk" shape="strip" count="1" segments="4" length="0.4" baseWidth="0.004"
             tipWidth="0.002" curvature="5" twist="10" tilt="3" mass="0.003" stiffness="0.8" responseTime="0.4"
             dragArea="0.004" colour="#3f7a2a" lodSegments="1 1"/>
            </species>
            <distribution species="s" count="20" density="2" minWater="0" maxWater="1" minNutrients="0"
             maxNutrients="1" maxSlope="45" minAltitude="-100000" maxAltitude="100000" footprint="0.5"
             waterUse="0.3" nutrientUse="0.3"/>
            <plant species="s" x="1" z="1" azimuth="30"/>
            <wind>
            <uniform id="u" x="0" z="0" strength="2" direction="20" coreRadius="0.5" influenceRadius="100"
             start="0" rampIn="1" rampOut="1"/>
            <source id="so" x="1" z="2" strength="3" coreRadius="0.5" start="1">
            <path speed="1.5" loop="true">
            <waypoint x="0" z="0"/>
            <waypoint x="3" z="4"/>
            </path>
            </source>
            <sink id="si" x="-1" z="2" strength="3" duration="5"/>
            <vortex id="v" x="2" z="-2" strength="-4" coreRadius="0.7"/>
            <gust id="g" strength="2.5" direction="30" noiseScale="6" noiseFrequency="0.3" seed="3"/>
            <blast id="b" x="0" z="0" strength="40" start="2"/>
            <rain id="r" x="0" z="0" strength="5" influenceRadius="6" noiseScale="0.5" noiseFrequency="2"/>
            </wind>
            <field enabled="true" maxObjectsPerNode="4" maxDepth="6" lodDistances="10 15"/>
            <camera x="0" y="1.7" z="11" yaw="10" pitch="-12" fovY="60" near="0.1" far="10000000">
            <path speed="1.2" loop="true">
            <waypoint x="0" y="1.7" z="11"/>
            <waypoint x="0" y="2" z="2"/>
            </path>
            </camera>
            <animation mode="constraint" fixedStep="0.016" maxSubSteps="8" subIntervals="4" threads="2" seed="1"
             prewarm="1"/>
            <render width="320" height="200" lodTransition="1"/>
            </scene>
            """;

    /** element/attribute@bound that another attribute bounds (checked by the binder at the attribute). */
    static final Set<String> COUPLED = Set.of(
            "camera/far@min", // far must be greater than near
            "terrain/sizeX@min", "terrain/sizeZ@min", // the template's plant at (1, 1) must stand on the terrain
            "plant/x@min", "plant/x@max", "plant/z@min", "plant/z@max"); // ... and be refused at x or z otherwise // only when a later level exists; here the last one is unbounded

    private record Site(String element, String attr, int start, int end, List<String> path) {
    }

    /** Every attribute of the template, with the path of elements down to its own. */
    private static List<Site> sites() {
        List<Site> out = new ArrayList<>();
        Matcher tag = Pattern.compile("<(/?)([a-z]+)([^>]*?)(/?)>").matcher(TEMPLATE);
        Pattern attr = Pattern.compile("([A-Za-z]+)=\"([^\"]*)\"");
        List<String> stack = new ArrayList<>();
        while (tag.find()) {
            if (!tag.group(1).isEmpty()) {
                stack.remove(stack.size() - 1);
                continue;
            }
            stack.add(tag.group(2));
            Matcher a = attr.matcher(tag.group(3));
            while (a.find()) {
                int base = tag.start(3);
                out.add(new Site(tag.group(2), a.group(1), base + a.start(2), base + a.end(2), List.copyOf(stack)));
            }
            if (!tag.group(4).isEmpty()) {
                stack.remove(stack.size() - 1);
            }
        }
        return out;
    }

    /** The attribute's spec, found along the element path from the root. */
    private static AttrSpec spec(Site s) {
        ElementSpec e = SceneSchema.ROOT;
        assertEquals(e.name, s.path().get(0));
        for (String name : s.path().subList(1, s.path().size())) {
            ElementSpec.Child c = e.childSpec(name);
            assertNotNull(c, String.join("/", s.path()));
            e = c.spec;
        }
        return e.attrSpec(s.attr());
    }

    private static String with(Site s, String value) {
        return TEMPLATE.substring(0, s.start()) + value + TEMPLATE.substring(s.end());
    }

    private static SceneLoadException load(String xml) {
        try {
            SceneFiles.parse(xml.getBytes(StandardCharsets.UTF_8), "bounds.xml", null);
            return null;
        } catch (SceneLoadException e) {
            return e;
        }
    }

    private static String text(double v, boolean integer) {
        return integer ? String.valueOf((long) v) : Double.toString(v);
    }

    @Test
    void theTemplateIsValid() {
        SceneLoadException e = load(TEMPLATE);
        assertEquals(null, e == null ? null : e.getMessage());
    }

    @Test
    void everyBoundOfTheSchemaLoadsAndEveryValueJustOutsideIsRefusedAtTheAttribute() {
        int tested = 0;
        List<String> failures = new ArrayList<>();
        for (Site s : sites()) {
            AttrSpec a = spec(s);
            if (a == null) {
                failures.add(s.element() + "/" + s.attr() + " is not in the schema");
                continue;
            }
            boolean integer = a.type == AttrType.INT || a.type == AttrType.LONG;
            if (!(a.type == AttrType.DOUBLE || a.type == AttrType.ANGLE || integer) || !a.hasRange()) {
                continue;
            }
            String name = s.element() + "/" + s.attr();
            int line = 1 + (int) TEMPLATE.substring(0, s.start()).chars().filter(c -> c == '\n').count();
            int column = s.start() - TEMPLATE.lastIndexOf('\n', s.start() - 1) - s.attr().length() - 2;
            double lo = a.minExclusive ? Math.nextUp(a.min) : a.min;
            double[][] cases = {{lo, a.max}, {integer ? a.min - 1 : (a.minExclusive ? a.min : Math.nextDown(a.min)),
                    integer ? a.max + 1 : Math.nextUp(a.max)}};
            String[] bound = {"min", "max"};
            for (int b = 0; b < 2; b++) {
                if (COUPLED.contains(name + "@" + bound[b]) || Double.isInfinite(cases[0][b])) {
                    continue;
                }
                SceneLoadException ok = load(with(s, text(cases[0][b], integer)));
                if (ok != null) {
                    failures.add(name + " at its " + bound[b] + " " + text(cases[0][b], integer) + " is refused: "
                            + ok.problems().get(0));
                }
                SceneLoadException out = load(with(s, text(cases[1][b], integer)));
                if (out == null) {
                    failures.add(name + " just outside its " + bound[b] + " (" + text(cases[1][b], integer)
                            + ") loads");
                } else {
                    SceneProblem p = out.problems().get(0);
                    if (p.line() != line || p.column() != column || !p.message().contains(s.attr())) {
                        failures.add(name + " outside its " + bound[b] + " is reported at " + p + ", not at " + line
                                + ":" + column);
                    } else if (a.type == AttrType.ANGLE && !p.message().contains("degrees")) {
                        failures.add(name + " is an angle in degrees, its message says: " + p.message());
                    }
                }
                tested++;
            }
        }
        if (!failures.isEmpty()) {
            fail(failures.size() + " bound(s) disagree:\n" + String.join("\n", failures));
        }
        assertTrue(tested >= 200, "bounds tested: " + tested);
    }
}
