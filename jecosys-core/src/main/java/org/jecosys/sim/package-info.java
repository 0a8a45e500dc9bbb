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
 *
 * <h2>How a simulation steps</h2>
 * {@link org.jecosys.sim.Simulation#step(double, org.jecosys.math.Camera)} adds real time to an
 * accumulator and runs as many fixed steps ({@link org.jecosys.anim.AnimationDef#fixedStep()}) as it
 * holds, at most {@link org.jecosys.anim.AnimationDef#maxSubSteps()}; the backlog beyond that is
 * dropped (the meadow slows down rather than spiral). One fixed step:
 * <ol>
 * <li>the queued commands (flows, agents, mode, field, LOD) are applied;</li>
 * <li>the workers animate fixed chunks of plants ({@code ChunkAnimator}) from the force field's result
 * for the end of this step, writing the back frame;</li>
 * <li>at the same time the stepping thread advances the wind clock and updates the force field for
 * the end of the <em>next</em> step (visibility and LOD from the camera given now), so the field and
 * the animation run concurrently (§5.1) without either waiting for the other's data, then helps with
 * the chunks left. Visibility thus follows the camera one fixed step late. With N workers, N - 1
 * pool threads and the stepping thread animate; with 1, the stepping thread does everything;</li>
 * <li>the frame is published (triple buffering, {@code FrameExchange}).</li>
 * </ol>
 * With the field off ({@link org.jecosys.sim.Simulation#setFieldEnabled}) no flow is evaluated and no
 * culling is done: every plant is visible and feels no wind (paper Table 6's "Force field
 * disabled").
 *
 * <h2>Start</h2>
 * In CONSTRAINT mode with the paper's field on, a new simulation puts every plant at the equilibrium
 * of the flows at its position at t = 0 (one evaluation per plant, once), so the frames before the
 * first step already show the meadow in the wind. The first step samples the field at t = 0 as well (the
 * force its spring update starts from; when the plants were not settled at construction, the plants
 * it sees are settled on it), then for the end of the step as usual. A plant that comes into view
 * later starts at the equilibrium of the wind it then feels ({@code AnimationState}). When the flows
 * switch within a step (a window opens or closes, a flow is added, removed or switched:
 * {@link org.jecosys.wind.WindField#lastEdge}), that step's spring update changes the force at the
 * sub-interval boundary of the switch instead of spreading it over the step
 * ({@code SpringKinds.prepare}).
 *
 * <h2>Determinism</h2>
 * Chunks are fixed by the world (about {@value org.jecosys.sim.Simulation#CHUNK_COMPONENTS}
 * components each), random mode uses one random stream per chunk, and nothing sums floating-point
 * values across chunks, so the state (see {@link org.jecosys.sim.Inspection#stateHash()}) is
 * bit-identical for any number of workers.
 *
 * <h2>Threads</h2>
 * <ul>
 * <li>{@link Simulation#step}, {@link Simulation#stepFixed} and the stepping-thread methods of
 * {@link Simulation#inspect()} (the state hash, the animated state, the force field, the wind a plant
 * felt, the clock): one <em>stepping thread</em> at a time (the game loop), never concurrently with a
 * step.</li>
 * <li>{@link Simulation#latestFrame()}: one reader thread (the renderer, the first thread that calls
 * it), concurrently with steps; it never blocks and never sees a frame being written. Another thread
 * that calls it while the reader lives gets an IllegalStateException.
 * {@link Simulation#copyLatestFrame(Frame)}: any number of threads, concurrently with steps and the
 * reader; each gets a complete copy.</li>
 * <li>Commands ({@link Simulation#addFlow}, {@link Simulation#removeFlow},
 * {@link Simulation#attachAgent}, {@link Simulation#moveAgent}, {@link Simulation#blast},
 * {@link Simulation#setFlowEnabled}, {@link Simulation#setMode}, {@link Simulation#setFieldEnabled},
 * {@link Simulation#setLodScale}): any thread; checked by the call (the same ranges as the scene
 * schema; duplicate flow ids and more than {@link Simulation#MAX_FLOWS} flows are refused there),
 * queued and applied at the start of the next fixed step. A step applies at most the commands queued
 * when it started, so producers can never keep it from returning; at most
 * {@link Simulation#MAX_PENDING_COMMANDS} wait at a time, and a command past that is refused with an
 * IllegalStateException (back-pressure: step more often or send fewer). They allocate a small
 * command, except {@link Simulation#moveAgent}, which allocates nothing after a flow's first move;
 * steps allocate nothing after warm-up, on the stepping thread and on every worker.</li>
 * <li>{@link Simulation#close()}: any thread, any time, idempotent: it refuses every later step and
 * command ({@code IllegalStateException}), waits for a running step to end its fixed step, and stops
 * the workers.</li>
 * </ul>
 */
package org.jecosys.sim;
