/**
 * The benchmark suite behind {@code jecosys bench}: it reproduces the paper's Tables 1-7 (paper
 * §5.2; §4.1 model complexity, §3.1 field scaling, §4.2 animation modes) on the shipped scenes and
 * writes a report ({@code tables.md}, {@code results.json} and PNG charts) with the paper's own
 * numbers alongside. Each {@link org.jecosys.bench.Section} measures one part; runs are headless and
 * single-threaded unless a section says otherwise.
 */
package org.jecosys.bench;
