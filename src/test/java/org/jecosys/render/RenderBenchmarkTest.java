package org.jecosys.render;

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

/**
 * Rendering benchmark on this machine's GL (llvmpipe here): C1-C3 and meadow at 1280x720 from each
 * scene's start camera, driven by the real {@link Simulation} (stepped 1/30 s per frame on its worker
 * threads): S1 = mode STATIC vs S3 = mode CONSTRAINT (Table 7), force field enabled vs disabled in
 * CONSTRAINT mode (Table 6), and the scene's frame against a bare instanced draw of the same geometry
 * in the same run. fps = frames / wall time with glFinish per frame; CPU ms = time in
 * SceneRenderer.render before glFinish (culling, component pass, upload, GL calls).
 *
 * <p>Bare reference: after the scene's last frame, for every species and level list that frame drew,
 * the real mesh of that level (same vertices, same index buffer, same primitive: triangles or lines)
 * posed as the list's first plant is in that frame, resolved once on the CPU into plain positions
 * relative to its base, drawn with one glDrawElementsInstanced per list with the list's plants' bases
 * as a per-instance offset; plus the scene's terrain mesh (same grid, same indices); one shader that
 * only transforms by the view-projection and writes a constant colour; same clear, same depth test,
 * same framebuffer. So: the same numbers of triangles and lines at the same places and sizes, with no
 * pose fetch, no animation, no lighting, no fog and no dither. Render-only fps (no simulation step) is
 * reported next to it, and a breakdown of the render-only frame (terrain only, plants only, per level,
 * per-frame CPU/upload only, tiny viewport for the vertex share, no dither band).
 *
 * <p>Writes target/bench/render.md. Run with {@code mvn -B verify -Pbench
 * -Dtest=RenderBenchmarkTest -Dsurefire.failIfNoSpecifiedTests=false}. No timing assertions.
 */
@Tag("benchmark")
class RenderBenchmarkTest {
    private static final int W = 1280;
    private static final int H = 720;
    private static final int WARM = 30;
    private static final int FRAMES = 64;
    private static final double DT = 1.0 / 30;

    private double cpuMs;

    @Test
    void renderBenchmark() throws Exception {
        StringBuilder md = new StringBuilder("# Rendering benchmark\n\n");
        StringBuilder parts = new StringBuilder();
        try (GlContext gl = GlContext.headless(false); GlFramebuffer fb = new GlFramebuffer(gl.tracker(), W, H)) {
            md.append("GL: ").append(gl.describe()).append(", ").append(W).append('x').append(H)
                    .append(", ").append(FRAMES).append(" frames after ").append(WARM).append(" warm-up, glFinish per frame, ")
                    .append(Runtime.getRuntime().availableProcessors()).append(" CPUs. S1/S3/field columns: frames from ")
                    .append("the real Simulation (1/30 s step per frame, start camera), step time included. Render fps: ")
                    .append("the last S3 frame rendered again and again, no step. Bare: the same terrain mesh and the same ")
                    .append("plant meshes (same triangles and lines, same sizes, at the drawn plants), pre-posed, ")
                    .append("instanced, transform-only shader, constant colour, depth test on (see the class Javadoc).\n\n")
                    .append("| scene | plants | triangles | lines | S1 static fps | S3 animated fps | S3/S1 | field off fps")
                    .append(" | field on fps | on/off | CPU ms/frame | render fps | bare fps | S3/bare | render/bare |\n")
                    .append("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
            parts.append("\n## Where a frame's time goes (render only, ms per frame)\n\n")
                    .append("| scene | full | clear only | terrain only | plants only | plants CPU+upload, no draw |")
                    .append(" plants by level (L0/L1/L2/L3) | full, 16x9 viewport | full, no dither band | bare | bare 16x9 |\n")
                    .append("|---|---|---|---|---|---|---|---|---|---|---|\n");
            for (String name : List.of("c1.xml", "c2.xml", "c3.xml", "meadow.xml")) {
                SceneDef def = RenderScenes.load(name);
                World world = RenderScenes.build(def);
                ViewCamera cam = RenderScenes.camera(def, world, W, H);
                try (Simulation sim = Simulation.of(world, def.simulationDef(), 0);
                     SceneRenderer r = new SceneRenderer(gl, world, new RenderSettings())) {
                    fb.bind();
                    sim.setFieldEnabled(true);
                    sim.setMode(AnimationMode.STATIC);
                    double s1 = fps(r, sim, cam);
                    sim.setMode(AnimationMode.CONSTRAINT);
                    double s3 = fps(r, sim, cam);
                    double cpu = cpuMs;
                    sim.setFieldEnabled(false);
                    double off = fps(r, sim, cam);
                    sim.setFieldEnabled(true);
                    double on = fps(r, sim, cam);
                    long tri = r.triangles();
                    long lines = r.lines();
                    Frame frame = sim.latestFrame();
                    double full = ms(r, frame, cam, W, H);
                    double bareMs;
                    double bareTiny;
                    try (Bare bare = new Bare(gl, world, r.plants().batches(), frame, cam)) {
                        assertEquals(tri, bare.triangles);
                        assertEquals(lines, bare.lines);
                        bareMs = bare.ms(W, H);
                        bareTiny = bare.ms(16, 9);
                    }
                    double tiny = ms(r, frame, cam, 16, 9);
                    r.drawPlants = false;
                    r.drawTerrain = false;
                    double clear = ms(r, frame, cam, W, H);
                    r.drawTerrain = true;
                    double terrain = ms(r, frame, cam, W, H);
                    r.drawTerrain = false;
                    r.drawPlants = true;
                    double plants = ms(r, frame, cam, W, H);
                    r.plants().levelMask = 0;
                    double upload = ms(r, frame, cam, W, H);
                    StringBuilder byLevel = new StringBuilder();
                    for (int l = 0; l < 4; l++) {
                        r.plants().levelMask = 1 << l;
                        byLevel.append(l == 0 ? "" : " / ").append(String.format("%.1f", ms(r, frame, cam, W, H)));
                    }
                    r.plants().levelMask = ~0;
                    r.drawTerrain = true;
                    r.settings().lodTransition(0);
                    double noBand = ms(r, frame, cam, W, H);
                    double bare = 1000 / bareMs;
                    md.append(String.format("| %s | %d | %d | %d | %.1f | %.1f | %.2f | %.1f | %.1f | %.2f | %.1f | %.1f | %.1f | %.2f | %.2f |%n",
                            def.name(), world.plantCount(), tri, lines, s1, s3, s3 / s1, off, on, on / off, cpu,
                            1000 / full, bare, s3 / bare, 1000 / full / bare));
                    parts.append(String.format("| %s | %.1f | %.1f | %.1f | %.1f | %.1f | %s | %.1f | %.1f | %.1f | %.1f |%n",
                            def.name(), full, clear, terrain, plants, upload, byLevel, tiny, noBand, bareMs, bareTiny));
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

    private double fps(SceneRenderer r, Simulation sim, ViewCamera cam) {
        long t0 = 0;
        long cpu = 0;
        for (int i = 0; i < WARM + FRAMES; i++) {
            if (i == WARM) {
                t0 = System.nanoTime();
                cpu = 0;
            }
            sim.step(DT, cam);
            Frame frame = sim.latestFrame();
            long c0 = System.nanoTime();
            r.render(frame, cam, W, H);
            cpu += System.nanoTime() - c0;
            glFinish();
        }
        cpuMs = cpu / 1e6 / FRAMES;
        return FRAMES / ((System.nanoTime() - t0) / 1e9);
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
        private final ViewCamera cam;
        long triangles;
        long lines;

        Bare(GlContext gl, World world, PlantBatches b, Frame frame, ViewCamera cam) {
            this.cam = cam;
            GlTracker t = gl.tracker();
            prog = own(new GlProgram(t, "bare.vert", "bare.frag"));
            List<SpeciesModel> models = world.plants().species();
            int[][][] zero = new int[models.size()][][];
            for (int s = 0; s < models.size(); s++) {
                zero[s] = new int[models.get(s).componentCount()][models.get(s).variants()];
            }
            FloatBuffer rec = MemoryUtil.memAllocFloat((int) (ComponentStream.FLOATS * Math.max(1, b.maxComponents())));
            try {
                new ComponentStream(world, zero).write(b, frame, cam.x(), cam.y(), cam.z(), rec);
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
                                int r = ComponentStream.FLOATS * (b.componentOffset(li) + slot);
                                PoseTable pt = m.slotPoseTable(slot, v0);
                                int stride = 3 * pt.points();
                                int pose = Math.round(rec.get(r + 4)) / stride;
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
                            MemoryUtil.memFree(v);
                            MemoryUtil.memFree(idx);
                            MemoryUtil.memFree(off);
                        }
                    }
                }
            } catch (RuntimeException | Error e) {
                close();
                throw e;
            } finally {
                MemoryUtil.memFree(rec);
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
                MemoryUtil.memFree(v);
                MemoryUtil.memFree(idx);
                MemoryUtil.memFree(off);
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

        /** Milliseconds per bare frame over a {@code w x h} viewport. */
        double ms(int w, int h) {
            prog.use();
            FloatBuffer m = MemoryUtil.memAllocFloat(16);
            glUniformMatrix4fv(prog.uniform("uViewProj"), false, cam.viewProjection(new Matrix4f()).get(m));
            MemoryUtil.memFree(m);
            glViewport(0, 0, w, h);
            glEnable(GL_DEPTH_TEST);
            glDepthFunc(GL_LEQUAL);
            long t0 = 0;
            for (int i = 0; i < WARM + FRAMES; i++) {
                if (i == WARM) {
                    t0 = System.nanoTime();
                }
                glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
                for (int d = 0; d < draws.size(); d++) {
                    int[] dr = draws.get(d);
                    vaos.get(d).bind();
                    glDrawElementsInstanced(dr[0], dr[1], GL_UNSIGNED_INT, 0L, dr[2]);
                }
                glFinish();
            }
            glDisable(GL_DEPTH_TEST);
            glBindVertexArray(0);
            return (System.nanoTime() - t0) / 1e6 / FRAMES;
        }

        @Override
        public void close() {
            PlantRenderer.closeReverse(owned);
            owned.clear();
        }
    }
}
