package org.jecosys.plant;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import org.jecosys.math.Progress;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * Benchmark (not a timed test; runs only with {@code mvn -B verify -Pbench}): pre-computing every
 * library species (paper §4.1; budget: under 200 ms in all). Prints the median of several
 * cold-model builds and writes {@code target/bench/plant.md}.
 */
@Tag("benchmark")
class PlantBenchmarkTest {
    private static final int RUNS = 15;

    @Test
    void precomputeAllLibrarySpecies() throws IOException {
        List<SpeciesDef> defs = SpeciesLibrary.all();
        double first = PlantModel.build(defs, 1, GravityBend.EARTH_GRAVITY, Progress.NONE).buildMillis();
        double[] ms = new double[RUNS];
        PlantModel last = null;
        for (int r = 0; r < RUNS; r++) {
            last = PlantModel.build(defs, 1 + r, GravityBend.EARTH_GRAVITY, Progress.NONE);
            ms[r] = last.buildMillis();
        }
        Arrays.sort(ms);
        double median = ms[RUNS / 2];
        assertEquals(defs.size(), last.species().size());
        StringBuilder md = new StringBuilder();
        md.append("# Plant pre-computation (paper §4.1)\n\n");
        md.append(String.format(Locale.ROOT, "Species: %d (A, B, C, rose); runs: %d after one cold run.%n%n",
                defs.size(), RUNS));
        md.append("| measure | ms |\n|---|---|\n");
        md.append(String.format(Locale.ROOT, "| first (cold JVM) build | %.2f |%n", first));
        md.append(String.format(Locale.ROOT, "| median build | %.2f |%n", median));
        md.append(String.format(Locale.ROOT, "| min / max | %.2f / %.2f |%n%n", ms[0], ms[RUNS - 1]));
        md.append("| species | variants | pose tables | floats | LOD1 | LOD2 | LOD3 |\n|---|---|---|---|---|---|---|\n");
        for (SpeciesModel m : last.species()) {
            int floats = 0;
            for (int c = 0; c < m.componentCount(); c++) {
                for (int v = 0; v < m.variants(); v++) {
                    floats += m.component(c).poseTable(v).floatCount();
                }
            }
            md.append(String.format(Locale.ROOT, "| %s | %d | %d | %d | %d %s | %d %s | %d %s |%n",
                    m.def().id(), m.variants(), m.componentCount() * m.variants(), floats,
                    m.primitiveCount(0), m.mesh(0).primitive().xmlName(),
                    m.primitiveCount(1), m.mesh(1).primitive().xmlName(),
                    m.primitiveCount(2), m.mesh(2).primitive().xmlName()));
        }
        md.append(String.format(Locale.ROOT, "%nJava %s, %d processors.%n",
                System.getProperty("java.version"), Runtime.getRuntime().availableProcessors()));
        Path out = Path.of("target", "bench", "plant.md");
        Files.createDirectories(out.getParent());
        Files.writeString(out, md.toString(), StandardCharsets.UTF_8);
        System.out.print(md);
    }
}
