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
        ComponentDef leaf = new ComponentDef("leaf", ComponentType.LEAF, ComponentShape.STRIP, 25, null,
                5, 0.45, 0.006, 0.0015, 0.35, 0.4, 0.3, 4.0e-4, 0.2, 0.3, 0.002,
                Rgb.parseHex("#4f8a2b"), List.of(5, 3, 3));
        return new SpeciesDef("grassA", "grass tuft A", POSES, 1.2, List.of(leaf), table3Lods(),
                new VariationDef(8, 0.2, 0.15, 0.3, 0.15));
    }

    /** {@return yellow flower B: stalk, head, 5 petals; 72 / 52 triangles, 37 lines (Table 2)} */
    public static SpeciesDef yellowFlowerB() {
        ComponentDef stalk = new ComponentDef("stalk", ComponentType.STALK, ComponentShape.STRIP, 1, null,
                6, 0.40, 0.004, 0.003, 0.05, 0, 0.05, 3.0e-3, 0.8, 0.45, 0.004,
                Rgb.parseHex("#3f7a2a"), List.of(6, 3, 3));
        ComponentDef head = new ComponentDef("head", ComponentType.HEAD, ComponentShape.FAN, 1, "stalk",
                10, 0.01, 0.004, 0.025, 0, 0, 0, 2.0e-3, 1.5, 0.25, 6.0e-4,
                Rgb.parseHex("#c98a12"), List.of(10, 6, 5));
        ComponentDef petal = new ComponentDef("petal", ComponentType.PETAL, ComponentShape.STRIP, 5, "stalk",
                5, 0.03, 0.006, 0.008, 0.4, 0.1, 1.25, 2.0e-4, 0.4, 0.2, 2.5e-4,
                Rgb.parseHex("#f2d21b"), List.of(5, 4, 2));
        return new SpeciesDef("flowerB", "yellow flower B", POSES, 1.0, List.of(stalk, head, petal),
                table3Lods(), new VariationDef(6, 0.12, 0.1, 0.25, 0.08));
    }

    /** {@return purple flower C: stalk, 2 leaves, 4 petals; 78 / 58 triangles, 39 lines (Table 2)} */
    public static SpeciesDef purpleFlowerC() {
        ComponentDef stalk = new ComponentDef("stalk", ComponentType.STALK, ComponentShape.STRIP, 1, null,
                8, 0.45, 0.004, 0.003, 0.08, 0, 0.05, 3.5e-3, 0.9, 0.45, 0.0045,
                Rgb.parseHex("#3c6e28"), List.of(8, 4, 3));
        ComponentDef leaf = new ComponentDef("leaf", ComponentType.LEAF, ComponentShape.STRIP, 2, null,
                5, 0.18, 0.012, 0.0, 0.5, 0.2, 0.6, 8.0e-4, 0.3, 0.3, 0.002,
                Rgb.parseHex("#4a8530"), List.of(5, 4, 2));
        ComponentDef petal = new ComponentDef("petal", ComponentType.PETAL, ComponentShape.STRIP, 4, "stalk",
                6, 0.035, 0.004, 0.0, 0.3, 0.1, 1.1, 2.5e-4, 0.5, 0.2, 3.0e-4,
                Rgb.parseHex("#7b3fb0"), List.of(6, 5, 3));
        return new SpeciesDef("flowerC", "purple flower C", POSES, 1.0, List.of(stalk, leaf, petal),
                table3Lods(), new VariationDef(6, 0.12, 0.1, 0.25, 0.08));
    }

    /** {@return the rose: stalk, 2 leaves, 5 sepals, 10 petals, head; 177 / 105 triangles, 118 lines (Table 1)} */
    public static SpeciesDef rose() {
        ComponentDef stalk = new ComponentDef("stalk", ComponentType.STALK, ComponentShape.STRIP, 1, null,
                12, 0.60, 0.007, 0.005, 0.1, 0, 0.04, 1.2e-2, 1.5, 0.5, 0.006,
                Rgb.parseHex("#2f5e22"), List.of(12, 6, 4));
        ComponentDef leaf = new ComponentDef("leaf", ComponentType.LEAF, ComponentShape.STRIP, 2, null,
                5, 0.12, 0.03, 0.0, 0.4, 0.3, 0.9, 1.2e-3, 0.4, 0.3, 0.003,
                Rgb.parseHex("#2e6b2a"), List.of(5, 3, 3));
        ComponentDef sepal = new ComponentDef("sepal", ComponentType.LEAF, ComponentShape.STRIP, 5, "stalk",
                3, 0.025, 0.006, 0.0, 0.3, 0, 1.4, 1.0e-4, 0.6, 0.2, 1.0e-4,
                Rgb.parseHex("#35702b"), List.of(3, 2, 2));
        ComponentDef petal = new ComponentDef("petal", ComponentType.PETAL, ComponentShape.STRIP, 10, "stalk",
                5, 0.045, 0.012, 0.03, -0.6, 0.3, 0.7, 3.0e-4, 0.5, 0.25, 6.0e-4,
                Rgb.parseHex("#b01830"), List.of(5, 3, 3));
        ComponentDef head = new ComponentDef("head", ComponentType.HEAD, ComponentShape.FAN, 1, "stalk",
                10, 0.015, 0.008, 0.02, 0, 0, 0, 1.5e-3, 1.5, 0.25, 4.0e-4,
                Rgb.parseHex("#7a0f22"), List.of(10, 8, 7));
        return new SpeciesDef("rose", "rose", POSES, 0.9, List.of(stalk, leaf, sepal, petal, head),
                table3Lods(), new VariationDef(4, 0.1, 0.1, 0.2, 0.05));
    }

    /** {@return A, B, C and the rose, in that order} */
    public static List<SpeciesDef> all() {
        return List.of(grassTuftA(), yellowFlowerB(), purpleFlowerC(), rose());
    }
}
