package org.jecosys.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.util.List;
import org.jecosys.field.ForceFieldDef;
import org.jecosys.math.Waypoint;
import org.jecosys.plant.ComponentDef;
import org.jecosys.plant.ComponentType;
import org.jecosys.plant.LodDef;
import org.jecosys.plant.Primitive;
import org.jecosys.plant.SpeciesDef;
import org.jecosys.plant.VariationDef;
import org.jecosys.terrain.DistributionDef;
import org.jecosys.wind.FlowDef;
import org.jecosys.wind.FlowKind;
import org.jecosys.wind.MotionDef;
import org.junit.jupiter.api.Test;

/**
 * The Def builders' defaults are the scene schema's: a Def built with only the required values
 * equals what the loader makes of an element with only the required attributes, for every builder
 * and every flow kind. The schema table and the builders read the same {@code DEFAULT_*} constants;
 * this test keeps the binder's fallbacks in line with both.
 */
class DefBuildersTest {
    private static final String MINIMAL = """
            <scene version="1">
              <terrain sizeX="10" sizeZ="10"/>
              <species id="s">
                <lod/>
                <component id="leaf" type="leaf" segments="4" length="0.3" baseWidth="0.01" mass="0.001"
                    stiffness="0.5" lodSegments="4"/>
              </species>
              <distribution species="s"/>
              <wind>
                <uniform id="uniform" strength="2"/>
                <source id="source" strength="2"/>
                <sink id="sink" strength="2"/>
                <vortex id="vortex" strength="2"/>
                <gust id="gust" strength="2"/>
                <blast id="blast" strength="2"/>
                <rain id="rain" strength="2" influenceRadius="5"/>
                <source id="advected" strength="2" advected="true"/>
                <vortex id="walker" strength="2"><path><waypoint x="0" z="0"/><waypoint x="3" z="4"/></path></vortex>
              </wind>
            </scene>
            """;

    private static SceneDef minimal() throws SceneLoadException {
        return SceneFiles.parse(MINIMAL.getBytes(StandardCharsets.UTF_8), "minimal.xml", null);
    }

    private static ComponentDef leaf() {
        return ComponentDef.builder("leaf", ComponentType.LEAF).segments(4).length(0.3).baseWidth(0.01).mass(0.001)
                .stiffness(0.5).lodSegments(4).build();
    }

    @Test
    void componentBuilderDefaultsAreTheSchemas() throws Exception {
        ComponentDef loaded = minimal().species().get(0).components().get(0);
        assertEquals(loaded, leaf());
        assertEquals(loaded, loaded.toBuilder().build());
    }

    @Test
    void speciesBuilderDefaultsAreTheSchemas() throws Exception {
        SpeciesDef built = SpeciesDef.builder("s").lod(new LodDef(Double.POSITIVE_INFINITY, Primitive.TRIANGLES))
                .component(leaf()).build();
        SpeciesDef loaded = minimal().species().get(0);
        assertEquals(loaded, built);
        assertEquals(loaded, loaded.toBuilder().build());
    }

    @Test
    void distributionBuilderDefaultsAreTheSchemas() throws Exception {
        DistributionDef loaded = minimal().distributions().get(0);
        assertEquals(loaded, DistributionDef.builder("s").build());
        assertEquals(loaded, loaded.toBuilder().build());
    }

    @Test
    void flowBuilderDefaultsAreTheSchemasForEveryKind() throws Exception {
        List<FlowDef> loaded = minimal().flows();
        assertEquals(FlowKind.values().length + 2, loaded.size());
        for (FlowKind k : FlowKind.values()) {
            FlowDef.Builder b = FlowDef.builder(k.xmlName(), k).strength(2);
            if (k == FlowKind.RAIN) {
                b.influenceRadius(5);
            }
            FlowDef d = loaded.get(k.ordinal());
            assertEquals(k, d.kind());
            assertEquals(d, b.build(), k.xmlName());
            assertEquals(d, d.toBuilder().build(), k.xmlName());
        }
        assertEquals(0.5, loaded.get(FlowKind.BLAST.ordinal()).activation().duration(), 0, "a blast's default pulse");
        assertEquals(loaded.get(FlowKind.values().length),
                FlowDef.builder("advected", FlowKind.SOURCE).strength(2).advected(true).build());
        assertEquals(loaded.get(FlowKind.values().length + 1), FlowDef.builder("walker", FlowKind.VORTEX).strength(2)
                .path(List.of(new Waypoint(0, 0, 0), new Waypoint(3, 0, 4))).build());
    }

    @Test
    void fieldVariationAndRenderBuilderDefaultsAreTheSchemas() throws Exception {
        String xml = MINIMAL.replace("<lod/>", "<lod/>\n    <variation/>")
                .replace("</scene>", "  <field/>\n  <render/>\n</scene>");
        SceneDef loaded = SceneFiles.parse(xml.getBytes(StandardCharsets.UTF_8), "empty-elements.xml", null);
        VariationDef variation = loaded.species().get(0).variation();
        assertEquals(variation, VariationDef.builder().build());
        assertEquals(VariationDef.NONE, variation);
        assertEquals(variation, variation.toBuilder().build());
        assertEquals(loaded.simulationDef().field(), ForceFieldDef.builder().build());
        assertEquals(ForceFieldDef.defaults(), loaded.simulationDef().field());
        assertEquals(loaded.render(), RenderDef.builder().build());
        assertEquals(RenderDef.defaults(), loaded.render());
        // every setter reaches its component, and toBuilder keeps every value
        VariationDef v = VariationDef.builder().variants(6).length(0.1).width(0.2).curvature(0.3).tilt(0.1)
                .responseTime(0.4).stiffness(0.5).hue(6).value(0.2).dryTips(0.7).size(0.3).sizeClasses(3)
                .azimuth(0.5).build();
        assertEquals(new VariationDef(6, 0.1, 0.2, 0.3, 0.1, 0.4, 0.5, 6, 0.2, 0.7, 0.3, 3, 0.5), v);
        assertEquals(v, v.toBuilder().build());
        ForceFieldDef f = ForceFieldDef.builder().enabled(false).maxObjectsPerNode(3).maxDepth(5).lodDistances(2, 4)
                .thinning(10, 20, 0.5).lodFovY(1).build();
        assertEquals(new ForceFieldDef(false, 3, 5, List.of(2.0, 4.0), 10, 20, 0.5, 1), f);
        assertEquals(f, f.toBuilder().build());
        RenderDef r = RenderDef.builder().size(320, 200).sky(new org.jecosys.math.Rgb(0.1f, 0.2f, 0.3f))
                .lodTransition(2).terrainTint(RenderDef.Tint.WATER).showField(true).showWind(true)
                .patches(new RenderDef.Patches(10, 0.5, 3)).antialiasing(2).build();
        assertEquals(new RenderDef(320, 200, new org.jecosys.math.Rgb(0.1f, 0.2f, 0.3f), 2, RenderDef.Tint.WATER, true,
                true, RenderDef.Light.DEFAULT, new RenderDef.Patches(10, 0.5, 3), 2, RenderDef.GroundCover.NONE), r);
        assertEquals(r, r.toBuilder().build());
    }

    @Test
    void theFactoriesAgreeWithTheBuilders() {
        assertEquals(FlowDef.uniform("u", 3, 0.5), FlowDef.builder("u", FlowKind.UNIFORM).strength(3).direction(0.5)
                .build());
        assertEquals(FlowDef.point("p", FlowKind.SOURCE, 1, 2, 3), FlowDef.builder("p", FlowKind.SOURCE).centre(1, 2)
                .strength(3).build());
        assertEquals(MotionDef.ADVECTED, FlowDef.builder("a", FlowKind.SINK).strength(1).advected(true).build()
                .motion());
    }

    @Test
    void buildersSayWhatIsMissingOrWrong() {
        IllegalStateException e = assertThrows(IllegalStateException.class,
                () -> ComponentDef.builder("leaf", ComponentType.LEAF).segments(4).length(0.3).build());
        assertTrue(e.getMessage().contains("baseWidth") && e.getMessage().contains("mass")
                && e.getMessage().contains("stiffness") && e.getMessage().contains("lodSegments"), e.getMessage());
        assertTrue(assertThrows(IllegalStateException.class, () -> FlowDef.builder("g", FlowKind.GUST).build())
                .getMessage().contains("strength"));
        assertTrue(assertThrows(IllegalStateException.class,
                () -> FlowDef.builder("r", FlowKind.RAIN).strength(1).build()).getMessage().contains("influenceRadius"));
        assertTrue(assertThrows(IllegalArgumentException.class,
                () -> DistributionDef.builder("s").water(0.8, 0.2).build()).getMessage().contains("maxWater"));
        assertThrows(IllegalArgumentException.class, () -> SpeciesDef.builder("s").component(leaf()).build());
        assertTrue(assertThrows(IllegalArgumentException.class,
                () -> VariationDef.builder().variants(2).sizeClasses(3).build()).getMessage().contains("sizeClasses"));
        assertTrue(assertThrows(IllegalArgumentException.class,
                () -> ForceFieldDef.builder().lodDistances(30, 15).build()).getMessage().contains("ascending"));
        assertTrue(assertThrows(IllegalArgumentException.class,
                () -> RenderDef.builder().antialiasing(3).build()).getMessage().contains("antialiasing"));
        assertNotEquals(leaf(), leaf().toBuilder().stiffness(0.6).build());
    }
}
