/**
 * The {@code jecosys} command-line application (picocli): the desktop viewer
 * ({@code Viewer}: fly camera, Dear ImGui panel for flows, animation mode, force
 * field, levels of detail, overlays and terrain tint), headless rendering to PNG files and GIFs,
 * headless simulation runs, scene-file checks, and the benchmarks that reproduce the paper's tables.
 * The framework of paper §5.1 put together: the viewer's thread is the render thread and also steps
 * the {@link org.jecosys.sim.Simulation}, whose workers animate the plants.
 *
 * <p>Entry point: {@link org.jecosys.app.Main}. Exit codes: 0 success, 1 a runtime failure, 2 bad
 * input (flags or scene files). Not a library API: everything here may change between versions.
 */
package org.jecosys.app;
