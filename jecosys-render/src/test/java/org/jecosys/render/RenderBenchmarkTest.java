package org.jecosys.render;

import org.jecosys.render.GlContext.DebugOutput;
import org.jecosys.sim.internal.DecisionWriter;
import org.jecosys.render.gl.Closing;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.lwjgl.opengl.GL11C.GL_COLOR_BUFFER_BIT;
import static org.lwjgl.opengl.GL11C.GL_DEPTH_BUFFER_BIT;
import static org.lwjgl.opengl.GL11C.GL_DEPTH_TEST;
import static org.lwjgl.opengl.GL11C.GL_FLOAT;
import static org.lwjgl.opengl.GL11C.GL_LEQUAL;
import static org.lwjgl.opengl.GL11C.GL_LINES;
import static org.lwjgl.opengl.GL11C.GL_TRIANGLES;
import static org.lwjgl.opengl.GL11C.GL_UNSIGNED_INT;
import static org.lwjgl.opengl.GL11C.glClear;
import static org.lwjgl.opengl.GL11C.glDepthFunc;
import static org.lwjgl.opengl.GL11C.glDisable;
import static org.lwjgl.opengl.GL11C.glEnable;
import static org.lwjgl.opengl.GL11C.glFinish;
import static org.lwjgl.opengl.GL11C.glViewport;
import static org.lwjgl.opengl.GL15C.GL_ARRAY_BUFFER;
import static org.lwjgl.opengl.GL15C.GL_ELEMENT_ARRAY_BUFFER;
import static org.lwjgl.opengl.GL15C.GL_STATIC_DRAW;
import static org.lwjgl.opengl.GL20C.glEnableVertexAttribArray;
import static org.lwjgl.opengl.GL20C.glUniformMatrix4fv;
import static org.lwjgl.opengl.GL20C.glVertexAttribPointer;
import static org.lwjgl.opengl.GL30C.glBindVertexArray;
import static org.lwjgl.opengl.GL31C.glDrawElementsInstanced;
import static org.lwjgl.opengl.GL33C.glVertexAttribDivisor;

import java.nio.FloatBuffer;
import java.nio.IntBuffer;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.jecosys.anim.AnimationMode;
import org.jecosys.math.ViewCamera;
import org.jecosys.plant.LodMesh;
import org.jecosys.plant.PoseTable;
import org.jecosys.plant.SpeciesModel;
import org.jecosys.scene.SceneDef;
import org.jecosys.sim.Frame;
import org.jecosys.sim.Simulation;
import org.jecosys.sim.World;
import org.jecosys.terrain.Heightfield;
import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.lwjgl.system.MemoryUtil;
import org.jecosys.render.gl.GlBuffer;
import org.jecosys.render.gl.GlFramebuffer;
import org.jecosys.render.gl.GlProgram;
import org.jecosys.render.gl.GlTracker;
import org.jecosys.render.gl.GlVertexArray;
import org.jecosys.render.ground.TerrainRenderer;
import org.jecosys.render.plant.PlantBatches;
import org.jecosys.render.plant.PlantRenderer;

/**
 * Rendering benchmark on this machine's GL (llvmpipe here): C1-C3 and meadow at 1280x720 from each
 * scene's start camera, driven by the real {@link Simulation} (stepped 1/30 s per frame on its worker
 * threads): S1 = mode STATIC vs S3 = mode CONSTRAINT (Table 7), force field enabled vs disabled in
 * CONSTRAINT mode (Table 6), and the scene's frame against a bare instanced draw of the same geometry
 * in the same run.
 *
 * <p>Method. Every configuration (S1, S3 = field on, field off, render only, bare) is measured in
 * many short rounds: in each round each configuration runs one block of one or two warm-up frames and
 * a few timed frames, glFinish per frame, and the block order is rotated from round to round so that
 * no configuration always comes first or follows the same neighbour. A frame's time is wall time from
 * the step (if any) to the end of glFinish. Why short blocks: on this shared 2-CPU machine the same
 * frame drawn again and again takes, say, 6.2 ms for half a second and then 9.4 ms for the next (the
 * rasteriser's threads, the simulation's workers and the neighbours share two cores), so a block of a
 * second or so lands on one such plateau by chance; blocks of a few frames, interleaved, give every
 * configuration the same share of fast and slow stretches. A configuration's fps is 1000 / the median
 * frame time over all its timed frames; a ratio is the median over rounds of the ratio of the two
 * blocks' median frame times in the same round, reported with the first and third quartiles of the
 * rounds. CPU ms = median time in SceneRenderer.render before glFinish in S3 frames (culling,
 * component pass, upload, GL calls).
 *
 * <p>Bare reference: from one S3 frame after warm-up, for every species and level list that frame drew,
 * the real mesh of that level (same vertices, same index buffer, same primitive: triangles or lines)
 * posed as the list's first plant is in that frame, resolved once on the CPU into plain positions
 * relative to its base, drawn with one glDrawElementsInstanced per list with the list's plants' bases
 * as a per-instance offset; plus the scene's terrain mesh (same grid, same indices); one shader that
 * only transforms by the view-projection and writes a constant colour; same clear, same depth test,
 * same framebuffer. So: the same numbers of triangles and lines at the same places and sizes, with no
 * pose fetch, no animation, no lighting, no fog and no dither. Render only = the scene renderer drawing
 * the latest frame again, no step. A breakdown of the render-only frame follows (terrain only, plants
 * only, per level, per-frame CPU/upload only, tiny viewport for the vertex share, no dither band) and
 * of the bare frame (its terrain alone, with its triangles, with its lines: against the scene's
 * levels), one block each.
 *
 * <p>Writes target/bench/render.md. Run with {@code mvn -B verify -Pbench
 * -Dtest=RenderBenchmarkTest -Dsurefire.failIfNoSpecifiedTests=false}; {@code -Djecosys.renderRounds=N}
 * changes the number of rounds (default 40, half for meadow) and {@code -Djecosys.renderScenes=meadow.xml}
 * (comma-separated) measures only the scenes named. No timing assertions.
 */
@Tag("benchmark")
class RenderBenchmarkTest {
    private static final int W = 1280;
    private static final int H = 720;
    private static final int WARM = 30;
    private static final int FRAMES = 64;
    private static final double DT = 1.0 / 30;
    private static final int ROUNDS = Integer.getInteger("jecosys.renderRounds", 40);
    /** Scenes measured, in order; {@code -Djecosys.renderScenes=meadow.xml} (comma-separated) picks some. */
    private static final List<String> SCENES = List.of(
            System.getProperty("jecosys.renderScenes", "c1.xml,c2.xml,c3.xml,meadow.xml").split(","));

    /** Configurations measured in rounds, in their first round's order. */
    private static final String[] CONFIGS = {"S1", "S3", "field off", "render", "bare"};
    private static final int S1 = 0;
    private static final int S3 = 1;
    private static final int OFF = 2;
    private static final int RENDER = 3;
    private static final int BARE = 4;
    /** Bare draws: every primitive, or the terrain alone. */
    private static final int ALL = -1;
    private static final int TERRAIN = -2;

    @Test
    void renderBenchmark() throws Exception {
        StringBuilder md = new StringBuilder("# Rendering benchmark\n\n");
        StringBuilder parts = new StringBuilder();
        try (GlContext gl = GlContext.headless(DebugOutput.OFF); GlFramebuffer fb = new GlFramebuffer(gl.tracker(), W, H)) {
            md.append("GL: ").append(gl.describe()).append(", ").append(W).append('x').append(H).append(", ")
                    .append(Runtime.getRuntime().availableProcessors()).append(" CPUs. ").append(ROUNDS)
                    .append(" rounds (meadow: ").append(rounds(true)).append("); per round and configuration one block of warm-up and timed frames (C1-C3: ")
                    .append(blockWarm(false)).append(" + ").append(blockFrames(false)).append(", meadow: ")
                    .append(blockWarm(true)).append(" + ").append(blockFrames(true))
                    .append("), block order rotated each round, glFinish per frame. fps = 1000 / median frame ms; ")
                    .append("ratio = median over rounds of the paired blocks' ratio [first, third quartile of the rounds]. ")
                    .append("S1/S3/field off: frames from the real Simulation (1/30 s step per frame, start camera), ")
                    .append("step time included; field on is S3. Render: the latest frame drawn again, no step. ")
                    .append("Bare: the same terrain mesh and the same plant meshes (same triangles and lines, same ")
                    .append("sizes, at the drawn plants), pre-posed, instanced, transform-only shader, constant colour, ")
                    .append("depth test on (see the class Javadoc). Step ms: median wall time of Simulation.step in ")
                    .append("those frames; 'from step ms' = (render ms + step ms of the reference) / (render ms + step ms ")
                    .append("of S3): the ratio if the step were the only difference between the frames (it runs before the draw, with the rasteriser idle).\n\n")
                    .append("| scene | plants | triangles | lines | S1 static fps | S3 animated fps | S3/S1 | field off fps")
                    .append(" | on/off | CPU ms/frame | step ms S1 / S3 / off | S3/S1, on/off from step ms")
                    .append(" | render fps | bare fps | S3/bare | render/bare |\n")
                    .append("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
            parts.append("\n## Where a frame's time goes (render only, ms per frame, one block of ").append(FRAMES)
                    .append(" frames after ").append(WARM).append(")\n\n")
                    .append("| scene | full | clear only | terrain only | plants only | plants CPU+upload, no draw |")
                    .append(" plants by level (L0/L1/L2/L3) | full, 16x9 viewport | full, no dither band | bare 16x9 |")
                    .append(" bare: terrain only / with triangles / with lines |\n")
                    .append("|---|---|---|---|---|---|---|---|---|---|---|\n");
            for (String name : SCENES) {
                SceneDef def = RenderScenes.load(name);
                World world = RenderScenes.build(def);
                ViewCamera cam = RenderScenes.camera(def, world, W, H);
                boolean big = world.plantCount() > 1000;
                try (Simulation sim = Simulation.of(world, def.simulationDef(), 0);
                     SceneRenderer r = new SceneRenderer(gl, world, RenderSettings.standalone())) {
                    fb.bind();
                    sim.setMode(AnimationMode.CONSTRAINT);
                    sim.setFieldEnabled(true);
                    long[] cpu = new long[2]; // render CPU, step
                    Runnable stepAndRender = () -> {
                        long s0 = System.nanoTime();
                        sim.step(DT, cam);
                        cpu[1] = System.nanoTime() - s0;
                        long c0 = System.nanoTime();
                        r.render(sim.latestFrame(), cam, W, H);
                        cpu[0] = System.nanoTime() - c0;
                    };
                    for (int i = 0; i < WARM; i++) {
                        stepAndRender.run();
                        glFinish();
                    }
                    long tri = r.triangles();
                    long lines = r.lines();
                    try (Bare bare = new Bare(gl, world, r.plants(), cam)) {
                        assertEquals(tri, bare.triangles);
                        assertEquals(lines, bare.lines);
                        Runnable[] setup = {
                            () -> sim.setMode(AnimationMode.STATIC),
                            () -> {
                                sim.setMode(AnimationMode.CONSTRAINT);
                                sim.setFieldEnabled(true);
                            },
                            () -> {
                                sim.setMode(AnimationMode.CONSTRAINT);
                                sim.setFieldEnabled(false);
                            },
                            () -> {
                                sim.setMode(AnimationMode.CONSTRAINT);
                                sim.setFieldEnabled(true);
                                sim.step(DT, cam); // an animated frame to draw again and again
                            },
                            () -> { },
                        };
                        Runnable[] frame = {stepAndRender, stepAndRender, stepAndRender,
                            () -> r.render(sim.latestFrame(), cam, W, H), () -> bare.draw(W, H, ALL)};
                        Rounds m = new Rounds(CONFIGS.length, rounds(big), blockFrames(big));
                        double[] cpuMs = new double[rounds(big) * blockFrames(big)];
                        int cpuN = 0;
                        double[][] stepMs = new double[OFF + 1][rounds(big) * blockFrames(big)];
                        int[] stepN = new int[OFF + 1];
                        for (int round = 0; round < rounds(big); round++) {
                            for (int k = 0; k < CONFIGS.length; k++) {
                                int c = (k + round) % CONFIGS.length;
                                setup[c].run();
                                for (int i = 0; i < blockWarm(big); i++) {
                                    frame[c].run();
                                    glFinish();
                                }
                                for (int i = 0; i < blockFrames(big); i++) {
                                    long t0 = System.nanoTime();
                                    frame[c].run();
                                    glFinish();
                                    m.add(c, round, (System.nanoTime() - t0) / 1e6);
                                    if (c == S3) {
                                        cpuMs[cpuN++] = cpu[0] / 1e6;
                                    }
                                    if (c <= OFF) {
                                        stepMs[c][stepN[c]++] = cpu[1] / 1e6;
                                    }
                                }
                            }
                        }
                        double step1 = median(stepMs[S1], stepN[S1]);
                        double step3 = median(stepMs[S3], stepN[S3]);
                        double stepOff = median(stepMs[OFF], stepN[OFF]);
                        double renderMs = 1000 / m.fps(RENDER);
                        md.append(String.format("| %s | %d | %d | %d | %.1f | %.1f | %s | %.1f | %s | %.1f | %.3f / %.3f / %.3f | %.2f / %.2f | %.1f | %.1f | %s | %s |%n",
                                def.name(), world.plantCount(), tri, lines, m.fps(S1), m.fps(S3), m.ratio(S1, S3),
                                m.fps(OFF), m.ratio(OFF, S3), median(cpuMs, cpuN), step1, step3, stepOff,
                                (renderMs + step1) / (renderMs + step3), (renderMs + stepOff) / (renderMs + step3),
                                m.fps(RENDER), m.fps(BARE), m.ratio(BARE, S3), m.ratio(BARE, RENDER)));
                        double bareTiny = bare.ms(16, 9, ALL);
                        parts.append(breakdown(def.name(), r, sim.latestFrame(), cam)).append(String.format(
                                " %.1f | %.1f / %.1f / %.1f |%n", bareTiny, bare.ms(W, H, TERRAIN), bare.ms(W, H, GL_TRIANGLES),
                                bare.ms(W, H, GL_LINES)));
                    }
                }
                assertEquals(0, gl.tracker().live() - 3);
            }
        }
        md.append(parts);
        Path out = Path.of("target/bench/render.md");
        Files.createDirectories(out.getParent());
        Files.writeString(out, md.toString());
        System.out.println(md);
    }

    private static int blockWarm(boolean big) {
        return big ? 1 : 2;
    }

    private static int blockFrames(boolean big) {
        return big ? 3 : 8;
    }

    private static int rounds(boolean big) {
        return big ? ROUNDS / 2 : ROUNDS;
    }

    /** The breakdown row of the render-only frame, less its last cell. Leaves the renderer as found. */
    private static String breakdown(String name, SceneRenderer r, Frame frame, ViewCamera cam) {
        double full = ms(r, frame, cam, W, H);
        double tiny = ms(r, frame, cam, 16, 9);
        r.drawPlants = false;
        r.drawTerrain = false;
        double clear = ms(r, frame, cam, W, H);
        r.drawTerrain = true;
        double terrain = ms(r, frame, cam, W, H);
        r.drawTerrain = false;
        r.drawPlants = true;
        double plants = ms(r, frame, cam, W, H);
        r.plants().setLevelMask(0);
        double upload = ms(r, frame, cam, W, H);
        StringBuilder byLevel = new StringBuilder();
        for (int l = 0; l < 4; l++) {
            r.plants().setLevelMask(1 << l);
            byLevel.append(l == 0 ? "" : " / ").append(String.format("%.1f", ms(r, frame, cam, W, H)));
        }
        r.plants().setLevelMask(~0);
        r.drawTerrain = true;
        // the same view decided with no transition band (rest poses: drawing cost does not depend on them)
        org.jecosys.sim.DrawDecision noBandDecision = org.jecosys.sim.DrawDecision.of(r.world());
        DecisionWriter.setTransition(noBandDecision, 0);
        Frame noBandFrame = DecisionWriter.decideAll(noBandDecision, cam, TestFrames.rest(r.world()));
        double noBand = ms(r, noBandFrame, cam, W, H);
        return String.format("| %s | %.1f | %.1f | %.1f | %.1f | %.1f | %s | %.1f | %.1f |",
                name, full, clear, terrain, plants, upload, byLevel, tiny, noBand);
    }

    /** Median of the first {@code n} values (sorts them). */
    static double median(double[] v, int n) {
        java.util.Arrays.sort(v, 0, n);
        return n % 2 == 1 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
    }

    /** Frame times of several configurations over several rounds, and the medians and ratios the report quotes. */
    static final class Rounds {
        private final double[][][] ms; // config, round, frame
        private final int[][] n;

        Rounds(int configs, int rounds, int frames) {
            ms = new double[configs][rounds][frames];
            n = new int[configs][rounds];
        }

        void add(int config, int round, double frameMs) {
            ms[config][round][n[config][round]++] = frameMs;
        }

        /** Median frame time of one block, ms. */
        double blockMs(int config, int round) {
            return median(ms[config][round].clone(), n[config][round]);
        }

        /** 1000 / the median over all of a configuration's timed frames. */
        double fps(int config) {
            int total = 0;
            double[] all = new double[ms[config].length * ms[config][0].length];
            for (int r = 0; r < ms[config].length; r++) {
                System.arraycopy(ms[config][r], 0, all, total, n[config][r]);
                total += n[config][r];
            }
            return 1000 / median(all, total);
        }

        /**
         * The median over rounds of (block time of {@code slower} / block time of {@code faster}), i.e. the
         * fps of {@code faster} relative to {@code slower}, with the rounds' first and third quartiles.
         */
        double[] ratios(int reference, int config) {
            double[] q = new double[ms[config].length];
            for (int r = 0; r < q.length; r++) {
                q[r] = blockMs(reference, r) / blockMs(config, r);
            }
            java.util.Arrays.sort(q);
            return new double[] {median(q.clone(), q.length), q[q.length / 4], q[(3 * q.length) / 4]};
        }

        /** fps of {@code config} over fps of {@code reference}, formatted "median [low, high]". */
        String ratio(int reference, int config) {
            double[] q = ratios(reference, config);
            return String.format("%.2f [%.2f, %.2f]", q[0], q[1], q[2]);
        }
    }

    /** Milliseconds per render-only frame of {@code frame} over a {@code w x h} viewport. */
    private static double ms(SceneRenderer r, Frame frame, ViewCamera cam, int w, int h) {
        long t0 = 0;
        for (int i = 0; i < WARM + FRAMES; i++) {
            if (i == WARM) {
                t0 = System.nanoTime();
            }
            r.render(frame, cam, w, h);
            glFinish();
        }
        return (System.nanoTime() - t0) / 1e6 / FRAMES;
    }

    /** The bare reference (see the class Javadoc): GL objects built from the scene's last frame. */
    private static final class Bare implements AutoCloseable {
        private final List<AutoCloseable> owned = new ArrayList<>();
        private final List<int[]> draws = new ArrayList<>(); // vao index, primitive, index count, instances
        private final List<GlVertexArray> vaos = new ArrayList<>();
        private final GlProgram prog;
        private final FloatBuffer viewProj = MemoryUtil.memAllocFloat(16);
        long triangles;
        long lines;
        private boolean freed;

        /** From the records the renderer resolved for its last frame (read back from the GPU). */
        Bare(GlContext gl, World world, PlantRenderer renderer, ViewCamera cam) {
            cam.viewProjection(new Matrix4f()).get(viewProj);
            GlTracker t = gl.tracker();
            prog = own(new GlProgram(t, "bare.vert", "bare.frag"));
            List<SpeciesModel> models = world.plants().species();
            int[][][] firstTexel = new int[models.size()][][];
            PlantRenderer.poseTexelLayout(models, firstTexel);
            PlantBatches b = renderer.batches();
            FloatBuffer rec = MemoryUtil.memAllocFloat(Math.max(1, PlantRenderer.RECORD_FLOATS * b.components()));
            try {
                renderer.readRecords(rec);
                terrain(t, world);
                Vector3f p = new Vector3f();
                Vector3f q = new Vector3f();
                Vector3f side = new Vector3f();
                Vector3f nrm = new Vector3f();
                for (int s = 0; s < b.speciesCount(); s++) {
                    SpeciesModel m = models.get(s);
                    for (int l = 0; l < b.levels(s); l++) {
                        int li = b.list(s, l);
                        int n = b.count(li);
                        LodMesh mesh = m.mesh(l);
                        if (n == 0 || mesh.indexCount() == 0) {
                            continue;
                        }
                        int p0 = b.plant(li, 0);
                        int v0 = world.plantVariant(p0);
                        FloatBuffer v = MemoryUtil.memAllocFloat(3 * mesh.vertexCount());
                        IntBuffer idx = MemoryUtil.memAllocInt(mesh.indexCount());
                        FloatBuffer off = MemoryUtil.memAllocFloat(3 * n);
                        try {
                            for (int k = 0; k < mesh.vertexCount(); k++) {
                                int slot = mesh.vertexSlot(k);
                                int r = PlantRenderer.RECORD_FLOATS * (b.componentOffset(li) + slot);
                                PoseTable pt = m.slotPoseTable(slot, v0);
                                int stride = 3 * pt.points();
                                int first = firstTexel[s][m.slotComponent(slot)][m.slotVariant(slot, v0)];
                                int pose = (Math.round(rec.get(r + 4)) - first) / stride;
                                float w = rec.get(r + 5);
                                int pose1 = Math.min(pose + 1, pt.poses() - 1);
                                int point = mesh.vertexPoint(k);
                                pt.position(pose, point, p).lerp(pt.position(pose1, point, q), w);
                                pt.side(pose, point, side).lerp(pt.side(pose1, point, q), w);
                                pt.normal(pose, point, nrm).lerp(pt.normal(pose1, point, q), w);
                                p.fma(mesh.vertexA(k), side).fma(mesh.vertexB(k), nrm);
                                float c = rec.get(r + 3);
                                float sn = rec.get(r + 6);
                                v.put(rec.get(r) - world.plantX(p0) + p.x * c - p.z * sn)
                                        .put(rec.get(r + 1) - world.plantY(p0) + p.y)
                                        .put(rec.get(r + 2) - world.plantZ(p0) + p.x * sn + p.z * c);
                            }
                            for (int i = 0; i < mesh.indexCount(); i++) {
                                idx.put(mesh.index(i));
                            }
                            for (int i = 0; i < n; i++) {
                                int pl = b.plant(li, i);
                                off.put(world.plantX(pl)).put(world.plantY(pl)).put(world.plantZ(pl));
                            }
                            v.flip();
                            idx.flip();
                            off.flip();
                            boolean isLines = b.lines(li);
                            mesh(t, v, idx, off, isLines ? GL_LINES : GL_TRIANGLES, mesh.indexCount(), n);
                            if (isLines) {
                                lines += (long) n * mesh.indexCount() / 2;
                            } else {
                                triangles += (long) n * mesh.indexCount() / 3;
                            }
                        } finally {
                            MemoryUtil.memFree((java.nio.Buffer) v);
                            MemoryUtil.memFree((java.nio.Buffer) idx);
                            MemoryUtil.memFree((java.nio.Buffer) off);
                        }
                    }
                }
            } catch (RuntimeException | Error e) {
                close();
                throw e;
            } finally {
                MemoryUtil.memFree((java.nio.Buffer) rec);
            }
        }

        private <T extends AutoCloseable> T own(T resource) {
            owned.add(resource);
            return resource;
        }

        /** The scene's terrain grid (same vertices and triangles as TerrainRenderer), one instance at 0. */
        private void terrain(GlTracker t, World world) {
            Heightfield h = world.terrain().heightfield();
            int res = h.resolution();
            float[] heights = h.copyHeights(new float[res * res]);
            FloatBuffer v = MemoryUtil.memAllocFloat(3 * res * res);
            IntBuffer idx = MemoryUtil.memAllocInt(6 * (res - 1) * (res - 1));
            FloatBuffer off = MemoryUtil.memAllocFloat(3);
            try {
                for (int j = 0; j < res; j++) {
                    for (int i = 0; i < res; i++) {
                        v.put((float) (h.minX() + i * h.cellX())).put(heights[j * res + i])
                                .put((float) (h.minZ() + j * h.cellZ()));
                    }
                }
                for (int j = 0; j < res - 1; j++) {
                    for (int i = 0; i < res - 1; i++) {
                        int a = j * res + i;
                        idx.put(a).put(a + res).put(a + 1).put(a + 1).put(a + res).put(a + res + 1);
                    }
                }
                off.put(0).put(0).put(0);
                v.flip();
                idx.flip();
                off.flip();
                mesh(t, v, idx, off, GL_TRIANGLES, idx.limit(), 1);
                triangles += idx.limit() / 3;
            } finally {
                MemoryUtil.memFree((java.nio.Buffer) v);
                MemoryUtil.memFree((java.nio.Buffer) idx);
                MemoryUtil.memFree((java.nio.Buffer) off);
            }
        }

        private void mesh(GlTracker t, FloatBuffer v, IntBuffer idx, FloatBuffer off, int primitive, int count,
                          int instances) {
            GlVertexArray vao = own(new GlVertexArray(t));
            vao.bind();
            own(GlBuffer.of(t, GL_ARRAY_BUFFER, v, GL_STATIC_DRAW));
            glEnableVertexAttribArray(0);
            glVertexAttribPointer(0, 3, GL_FLOAT, false, 12, 0L);
            own(GlBuffer.of(t, GL_ARRAY_BUFFER, off, GL_STATIC_DRAW));
            glEnableVertexAttribArray(1);
            glVertexAttribPointer(1, 3, GL_FLOAT, false, 12, 0L);
            glVertexAttribDivisor(1, 1);
            own(GlBuffer.of(t, GL_ELEMENT_ARRAY_BUFFER, idx, GL_STATIC_DRAW));
            glBindVertexArray(0);
            vaos.add(vao);
            draws.add(new int[] {primitive, count, instances});
        }

        /**
         * One bare frame over a {@code w x h} viewport: clear, the terrain and the plant draws of the
         * given primitive ({@link #ALL}, GL_TRIANGLES, GL_LINES or {@link #TERRAIN}: none), glFinish
         * left to the caller.
         */
        void draw(int w, int h, int primitive) {
            prog.use();
            glUniformMatrix4fv(prog.uniform("uViewProj"), false, viewProj);
            glViewport(0, 0, w, h);
            glEnable(GL_DEPTH_TEST);
            glDepthFunc(GL_LEQUAL);
            glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
            for (int d = 0; d < draws.size(); d++) {
                int[] dr = draws.get(d);
                if (d > 0 && primitive != ALL && primitive != dr[0]) {
                    continue; // draw 0 is the terrain
                }
                vaos.get(d).bind();
                glDrawElementsInstanced(dr[0], dr[1], GL_UNSIGNED_INT, 0L, dr[2]);
            }
            glDisable(GL_DEPTH_TEST);
            glBindVertexArray(0);
        }

        /** Milliseconds per bare frame over a {@code w x h} viewport, one block (see {@link #draw}). */
        double ms(int w, int h, int primitive) {
            long t0 = 0;
            for (int i = 0; i < WARM + FRAMES; i++) {
                if (i == WARM) {
                    t0 = System.nanoTime();
                }
                draw(w, h, primitive);
                glFinish();
            }
            return (System.nanoTime() - t0) / 1e6 / FRAMES;
        }

        @Override
        public void close() {
            Closing.closeReverse(owned);
            owned.clear();
            if (!freed) {
                freed = true;
                MemoryUtil.memFree((java.nio.Buffer) viewProj);
            }
        }
    }
}
