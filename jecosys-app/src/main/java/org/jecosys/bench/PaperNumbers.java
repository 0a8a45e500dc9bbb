package org.jecosys.bench;

/**
 * The numbers the paper published (Endo, Morimoto, Fabris, CGI 2005, section 5.2), for the
 * side-by-side columns of the report. Pentium III 900 MHz, 512 MB, a 64 MB graphics card, Java 3D.
 */
public final class PaperNumbers {
    private PaperNumbers() {
    }

    /** Table 1: the rose, primitives of levels a, b, c (triangles, triangles, lines). */
    public static final int[] TABLE1_ROSE = {177, 105, 118};

    /** Table 2: plants A, B, C, primitives at LOD1, LOD2 (triangles) and LOD3 (lines). */
    public static final int[][] TABLE2 = {{250, 150, 175}, {72, 52, 37}, {78, 58, 39}};
    /** Table 2's plant names. */
    public static final String[] TABLE2_NAMES = {"A grass tuft", "B yellow flower", "C purple flower"};

    /** Table 3: LOD bands: (from, to) metres and primitive. */
    public static final String[][] TABLE3 = {{"0", "10", "triangle"}, {"10", "15", "triangle"},
            {"15", "-", "line"}};

    /** Table 4: scenes C1-C3, number of plants A, B, C. */
    public static final int[][] TABLE4 = {{50, 15, 15}, {75, 0, 0}, {0, 100, 100}};

    /** Table 5: ~triangles, ~lines, fps mean, fps sd, for C1-C3 (field and animation on). */
    public static final double[][] TABLE5 = {{7300, 4000, 29, 11}, {10000, 4400, 26, 9}, {8000, 3750, 33, 6}};

    /** Table 6: field update ms mean and sd; fps with field (mean, sd); fps without field (mean, sd). */
    public static final double[][] TABLE6 = {{40, 30, 44, 10, 47, 5}, {30, 20, 42, 7, 44, 6},
            {45, 35, 36, 15, 38, 5}};

    /** Table 7: fps mean and sd for S1 static, S2 random, S3 the framework's animation. */
    public static final double[][] TABLE7 = {{50, 10, 44, 10, 29, 11}, {52, 8, 42, 7, 26, 9},
            {49, 11, 36, 15, 33, 6}};

    /** Scene names of Tables 4-7. */
    public static final String[] SCENES = {"C1", "C2", "C3"};
}
