package org.jecosys.plant;

import java.util.List;
import org.jecosys.math.Rgb;

/**
 * The species of the paper's experiments (§5.2, Tables 1-3), as {@link SpeciesDef}s whose primitive
 * counts equal the paper's exactly under the {@link ComponentMesh} rules. Levels are Table 3's
 * ({@link #table3Lods()}); {@code lodSegments} lists LOD1/LOD2/LOD3.
 *
 * <table>
 * <caption>component layout: count x primitives per instance at LOD1 / LOD2 / LOD3</caption>
 * <tr><th>species</th><th>components</th><th>LOD1 tri</th><th>LOD2 tri</th><th>LOD3 lines</th></tr>
 * <tr><td>A grass tuft</td><td>25 leaves, blunt strip, 5 segments, uses 5/3/3</td>
 *     <td>25x10 = 250</td><td>25x6 = 150</td><td>25x7 = 175</td></tr>
 * <tr><td>B yellow flower (7)</td><td>stalk 1 (blunt strip, 6 seg, 6/3/3), head 1 (fan, 10, 10/6/5),
 *     petals 5 (blunt strip, 5 seg, 5/4/2)</td>
 *     <td>12+10+50 = 72</td><td>6+6+40 = 52</td><td>7+5+25 = 37</td></tr>
 * <tr><td>C purple flower (7)</td><td>stalk 1 (blunt, 8 seg, 8/4/3), leaves 2 (pointed, 5 seg, 5/4/2),
 *     petals 4 (pointed, 6 seg, 6/5/3)</td>
 *     <td>16+18+44 = 78</td><td>8+14+36 = 58</td><td>7+8+24 = 39</td></tr>
 * <tr><td>rose (19)</td><td>stalk 1 (blunt, 12 seg, 12/6/4), leaves 2 (pointed, 5 seg, 5/3/3),
 *     sepals 5 (pointed, 3 seg, 3/2/2), petals 10 (blunt, 5 seg, 5/3/3), head 1 (fan, 10, 10/8/7)</td>
 *     <td>24+18+25+100+10 = 177</td><td>12+10+15+60+8 = 105</td><td>9+12+20+70+7 = 118</td></tr>
 * </table>
 * Sizes are realistic (grass leaves 0.45 m, flowers 0.4-0.6 m tall); masses in kg, spring constants
 * PC in N/m, response times 0.2-0.5 s, drag areas in m^2.
 *
 * <p>Static factories; any thread; each call allocates a new (immutable) definition.
 */
public final class SpeciesLibrary {
    /** Pose-table size of the library species. */
    public static final int POSES = SpeciesDef.DEFAULT_POSES;

    private SpeciesLibrary() {
    }

    /** {@return Table 3's levels: LOD1 0-10 m triangles, LOD2 10-15 m triangles, LOD3 beyond 15 m lines} */
    public static List<LodDef> table3Lods() {
        return List.of(new LodDef(10, Primitive.TRIANGLES), new LodDef(15, Primitive.TRIANGLES),
                new LodDef(Double.POSITIVE_INFINITY, Primitive.LINES));
    }

    /** {@return grass tuft A: 25 leaves; 250 / 150 triangles, 175 lines (Table 2)} */
    public static SpeciesDef grassTuftA() {
        ComponentDef leaf = ComponentDef.builder("leaf", ComponentType.LEAF)
                .shape(ComponentShape.STRIP).count(25)
                .segments(5).length(0.45).baseWidth(0.006).tipWidth(0.0015)
                .curvature(0.35).twist(0.4).tilt(0.3).mass(4.0e-4)
                .stiffness(0.2).responseTime(0.3).dragArea(0.002)
                .colour(Rgb.parseHex("#4f8a2b")).lodSegments(5, 3, 3).build();
        return SpeciesDef.builder("grassA").name("grass tuft A").poses(POSES).maxBend(1.2)
                .components(List.of(leaf)).lods(table3Lods())
                .variation(VariationDef.builder().variants(8).length(0.2).width(0.15).curvature(0.3).tilt(0.15)
                        .build())
                .build();
    }

    /** {@return yellow flower B: stalk, head, 5 petals; 72 / 52 triangles, 37 lines (Table 2)} */
    public static SpeciesDef yellowFlowerB() {
        ComponentDef stalk = ComponentDef.builder("stalk", ComponentType.STALK)
                .shape(ComponentShape.STRIP).count(1)
                .segments(6).length(0.40).baseWidth(0.004).tipWidth(0.003)
                .curvature(0.05).twist(0).tilt(0.05).mass(3.0e-3)
                .stiffness(0.8).responseTime(0.45).dragArea(0.004)
                .colour(Rgb.parseHex("#3f7a2a")).lodSegments(6, 3, 3).build();
        ComponentDef head = ComponentDef.builder("head", ComponentType.HEAD)
                .shape(ComponentShape.FAN).count(1).attachTo("stalk")
                .segments(10).length(0.01).baseWidth(0.004).tipWidth(0.025)
                .curvature(0).twist(0).tilt(0).mass(2.0e-3)
                .stiffness(1.5).responseTime(0.25).dragArea(6.0e-4)
                .colour(Rgb.parseHex("#c98a12")).lodSegments(10, 6, 5).build();
        ComponentDef petal = ComponentDef.builder("petal", ComponentType.PETAL)
                .shape(ComponentShape.STRIP).count(5).attachTo("stalk")
                .segments(5).length(0.03).baseWidth(0.006).tipWidth(0.008)
                .curvature(0.4).twist(0.1).tilt(1.25).mass(2.0e-4)
                .stiffness(0.4).responseTime(0.2).dragArea(2.5e-4)
                .colour(Rgb.parseHex("#f2d21b")).lodSegments(5, 4, 2).build();
        return SpeciesDef.builder("flowerB").name("yellow flower B").poses(POSES).maxBend(1.0)
                .components(List.of(stalk, head, petal)).lods(table3Lods())
                .variation(VariationDef.builder().variants(6).length(0.12).width(0.1).curvature(0.25).tilt(0.08)
                        .build())
                .build();
    }

    /** {@return purple flower C: stalk, 2 leaves, 4 petals; 78 / 58 triangles, 39 lines (Table 2)} */
    public static SpeciesDef purpleFlowerC() {
        ComponentDef stalk = ComponentDef.builder("stalk", ComponentType.STALK)
                .shape(ComponentShape.STRIP).count(1)
                .segments(8).length(0.45).baseWidth(0.004).tipWidth(0.003)
                .curvature(0.08).twist(0).tilt(0.05).mass(3.5e-3)
                .stiffness(0.9).responseTime(0.45).dragArea(0.0045)
                .colour(Rgb.parseHex("#3c6e28")).lodSegments(8, 4, 3).build();
        ComponentDef leaf = ComponentDef.builder("leaf", ComponentType.LEAF)
                .shape(ComponentShape.STRIP).count(2)
                .segments(5).length(0.18).baseWidth(0.012).tipWidth(0.0)
                .curvature(0.5).twist(0.2).tilt(0.6).mass(8.0e-4)
                .stiffness(0.3).responseTime(0.3).dragArea(0.002)
                .colour(Rgb.parseHex("#4a8530")).lodSegments(5, 4, 2).build();
        ComponentDef petal = ComponentDef.builder("petal", ComponentType.PETAL)
                .shape(ComponentShape.STRIP).count(4).attachTo("stalk")
                .segments(6).length(0.035).baseWidth(0.004).tipWidth(0.0)
                .curvature(0.3).twist(0.1).tilt(1.1).mass(2.5e-4)
                .stiffness(0.5).responseTime(0.2).dragArea(3.0e-4)
                .colour(Rgb.parseHex("#7b3fb0")).lodSegments(6, 5, 3).build();
        return SpeciesDef.builder("flowerC").name("purple flower C").poses(POSES).maxBend(1.0)
                .components(List.of(stalk, leaf, petal)).lods(table3Lods())
                .variation(VariationDef.builder().variants(6).length(0.12).width(0.1).curvature(0.25).tilt(0.08)
                        .build())
                .build();
    }

    /** {@return the rose: stalk, 2 leaves, 5 sepals, 10 petals, head; 177 / 105 triangles, 118 lines (Table 1)} */
    public static SpeciesDef rose() {
        ComponentDef stalk = ComponentDef.builder("stalk", ComponentType.STALK)
                .shape(ComponentShape.STRIP).count(1)
                .segments(12).length(0.60).baseWidth(0.007).tipWidth(0.005)
                .curvature(0.1).twist(0).tilt(0.04).mass(1.2e-2)
                .stiffness(1.5).responseTime(0.5).dragArea(0.006)
                .colour(Rgb.parseHex("#2f5e22")).lodSegments(12, 6, 4).build();
        ComponentDef leaf = ComponentDef.builder("leaf", ComponentType.LEAF)
                .shape(ComponentShape.STRIP).count(2)
                .segments(5).length(0.12).baseWidth(0.03).tipWidth(0.0)
                .curvature(0.4).twist(0.3).tilt(0.9).mass(1.2e-3)
                .stiffness(0.4).responseTime(0.3).dragArea(0.003)
                .colour(Rgb.parseHex("#2e6b2a")).lodSegments(5, 3, 3).build();
        ComponentDef sepal = ComponentDef.builder("sepal", ComponentType.LEAF)
                .shape(ComponentShape.STRIP).count(5).attachTo("stalk")
                .segments(3).length(0.025).baseWidth(0.006).tipWidth(0.0)
                .curvature(0.3).twist(0).tilt(1.4).mass(1.0e-4)
                .stiffness(0.6).responseTime(0.2).dragArea(1.0e-4)
                .colour(Rgb.parseHex("#35702b")).lodSegments(3, 2, 2).build();
        ComponentDef petal = ComponentDef.builder("petal", ComponentType.PETAL)
                .shape(ComponentShape.STRIP).count(10).attachTo("stalk")
                .segments(5).length(0.045).baseWidth(0.012).tipWidth(0.03)
                .curvature(-0.6).twist(0.3).tilt(0.7).mass(3.0e-4)
                .stiffness(0.5).responseTime(0.25).dragArea(6.0e-4)
                .colour(Rgb.parseHex("#b01830")).lodSegments(5, 3, 3).build();
        ComponentDef head = ComponentDef.builder("head", ComponentType.HEAD)
                .shape(ComponentShape.FAN).count(1).attachTo("stalk")
                .segments(10).length(0.015).baseWidth(0.008).tipWidth(0.02)
                .curvature(0).twist(0).tilt(0).mass(1.5e-3)
                .stiffness(1.5).responseTime(0.25).dragArea(4.0e-4)
                .colour(Rgb.parseHex("#7a0f22")).lodSegments(10, 8, 7).build();
        return SpeciesDef.builder("rose").name("rose").poses(POSES).maxBend(0.9)
                .components(List.of(stalk, leaf, sepal, petal, head)).lods(table3Lods())
                .variation(VariationDef.builder().variants(4).length(0.1).width(0.1).curvature(0.2).tilt(0.05)
                        .build())
                .build();
    }

    /** {@return A, B, C and the rose, in that order} */
    public static List<SpeciesDef> all() {
        return List.of(grassTuftA(), yellowFlowerB(), purpleFlowerC(), rose());
    }
}
