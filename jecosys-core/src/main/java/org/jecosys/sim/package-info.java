/**
 * The simulation: the {@link org.jecosys.sim.Simulation} facade for embedding, its fixed-step loop
 * and worker threads (paper §5.1), the immutable {@link org.jecosys.sim.World} and the published
 * {@link org.jecosys.sim.Frame}s.
 *
 * <h2>Embedding in a game loop</h2>
 * <pre>{@code
 * SimulationDef def = ...;                         // in code, or SceneDef.simulationDef(), or
 * try (Simulation sim = Scenes.simulation(Path.of("scenes/c1.xml"), Progress.NONE)) {
 *     ViewCamera camera = new ViewCamera();
 *     camera.setPosition(0, 1.7, 14);
 *     WindSource player = sim.attachAgent(FlowDef.point("player", FlowKind.SOURCE, 0, 14, 3));
 *     long last = System.nanoTime();
 *     while (running) {
 *         long now = System.nanoTime();
 *         // game logic: move the camera, the player...
 *         sim.moveAgent(player, playerX, playerZ);     // any thread; applied at the next fixed step
 *         sim.step((now - last) * 1e-9, camera);        // fixed steps on this thread + the workers
 *         last = now;
 *         Frame f = sim.latestFrame();                  // the render thread may do this instead
 *         for (int c = 0; c < f.componentCount(); c++) {
 *             draw(c, f.poseCoord(c), f.bendAzimuth(c));
 *         }
 *     }
 * }
 * }</pre>
 * {@code Scenes} lives in the scene package; {@code Simulation.create(def, baseDir, 0, progress)}
 * does the same from a def built in code (the Defs have builders with the scene format's defaults,
 * e.g. {@code ComponentDef.builder("leaf", ComponentType.LEAF)}). Any finite frame time may be
 * passed to {@code step}: after a long pause the backlog beyond {@code maxSubSteps} is dropped and
 * counted in {@code inspect().droppedSteps()}.
 *
 * <h2>A game's own parts (paper §5.1)</h2>
 * <ul>
 * <li>Wind: {@code sim.addFlow(WindSource)} with a subclass of {@code AbstractWindSource}.</li>
 * <li>Force field: {@code Simulation.of(world, def, workers, ForceFieldFactory)}.</li>
 * <li>Plant components and placement: {@code World.build(def, baseDir, workers, progress, distributor,
 * ComponentFactories)}, then {@code Simulation.of(world, def, workers)}.</li>
 * </ul>
 * Reading the state: {@code sim.inspect().state()} is a read-only {@code AnimationView}; {@code latestFrame()}
 * is what one render thread reads (a second thread calling it is refused); any other thread copies
 * frames with {@code copyLatestFrame(frame)}. Frames are never torn.
 */
package org.jecosys.sim;
