package org.jecosys.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * The quick benchmark suite, written to target/bench/report (tables.md, results.json, charts).
 * Tagged "benchmark": runs only with {@code mvn -B verify -Pbench}; reports, never asserts a speed.
 */
@Tag("benchmark")
class BenchSuiteBenchmarkTest {
    @Test
    void quickSuite() throws Exception {
        Report r = BenchSuite.standard(Path.of("scenes")).run(Mode.QUICK, Path.of("target", "bench", "report"),
                System.out);
        assertEquals(List.of(), r.failures());
    }
}
