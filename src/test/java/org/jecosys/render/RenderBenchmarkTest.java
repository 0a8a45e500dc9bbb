package org.jecosys.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.lwjgl.opengl.GL11C.GL_COLOR_BUFFER_BIT;
import static org.lwjgl.opengl.GL11C.GL_DEPTH_BUFFER_BIT;
import static org.lwjgl.opengl.GL11C.GL_DEPTH_TEST;
import static org.lwjgl.opengl.GL11C.GL_FLOAT;
import static org.lwjgl.opengl.GL11C.GL_LINES;
import static org.lwjgl.opengl.GL11C.GL_TRIANGLES;
import static org.lwjgl.opengl.GL11C.glClear;
import static org.lwjgl.opengl.GL11C.glDisable;
import static org.lwjgl.opengl.GL11C.glEnable;
import static org.lwjgl.opengl.GL11C.glFinish;
import static org.lwjgl.opengl.GL15C.GL_ARRAY_BUFFER;
import static org.lwjgl.opengl.GL15C.GL_STATIC_DRAW;
import static org.lwjgl.opengl.GL20C.glEnableVertexAttribArray;
import static org.lwjgl.opengl.GL20C.glUniformMatrix4fv;
import static org.lwjgl.opengl.GL20C.glVertexAttribPointer;
import static org.lwjgl.opengl.GL30C.glBindVertexArray;
import static org.lwjgl.opengl.GL31C.glDrawArraysInstanced;
import static org.lwjgl.opengl.GL33C.glVertexAttribDivisor;

import java.nio.FloatBuffer;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.jecosys.anim.AnimationMode;
import org.jecosys.math.ViewCamera;
import org.jecosys.scene.SceneDef;
import org.jecosys.sim.Frame;
import org.jecosys.sim.Simulation;
import org.jecosys.sim.World;
import org.joml.Matrix4f;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.lwjgl.system.MemoryUtil;

/**
 * Rendering benchmark on this machine's GL (llvmpipe here): C1-C3 and meadow at 1280x720 from each
 * scene's start camera, driven by the real {@link Simulation} (stepped 1/30 s per frame on its worker
 * threads): S1 = mode STATIC vs S3 = mode CONSTRAINT (Table 7), force field enabled vs disabled in
 * CONSTRAINT mode (Table 6), and the scene's frame against a bare instanced draw of the same numbers
 * of triangles and lines (20 per instance, instances at the plants' bases, a one-line shader, depth
 * test on, same framebuffer), in the same run. fps = frames / wall time with glFinish per frame; CPU
 * ms = time in SceneRenderer.render before glFinish (culling, component pass, upload, GL calls).
 * Writes target/bench/render.md. Run with {@code mvn -B verify -Pbench
 * -Dtest=RenderBenchmarkTest -Dsurefire.failIfNoSpecifiedTests=false}. No timing assertions.
 */
@Tag("benchmark")
class RenderBenchmarkTest {
    private static final int W = 1280;
    private static final int H = 720;
    private static final int WARM = 4;
    private static final int FRAMES = 16;
    private static final double DT = 1.0 / 30;
    private static final int PER_INSTANCE = 20;

    private double cpuMs;

    @Test
    void renderBenchmark() throws Exception {
        StringBuilder md = new StringBuilder("# Rendering benchmark\n\n");
        try (GlContext gl = GlContext.headless(false); GlFramebuffer fb = new GlFramebuffer(gl.tracker(), W, H)) {
            md.append("GL: ").append(gl.describe()).append(", ").append(W).append('x').append(H)
                    .append(", ").append(FRAMES).append(" frames after ").append(WARM).append(" warm-up, glFinish per frame, ")
                    .append(Runtime.getRuntime().availableProcessors()).append(" CPUs. Frames from the real Simulation ")
                    .append("(1/30 s step per frame, start camera). Bare = the same triangles and lines as the scene's ")
                    .append("frame, instanced, trivial shader.\n\n")
                    .append("| scene | plants | triangles | lines | S1 static fps | S3 animated fps | S3/S1 | field off fps")
                    .append(" | field on fps | on/off | CPU ms/frame | bare fps | scene/bare |\n")
                    .append("|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
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
                    double bare = bareFps(gl, world, cam, tri, lines);
                    md.append(String.format("| %s | %d | %d | %d | %.1f | %.1f | %.2f | %.1f | %.1f | %.2f | %.1f | %.1f | %.2f |%n",
                            def.name(), world.plantCount(), tri, lines, s1, s3, s3 / s1, off, on, on / off, cpu, bare,
                            s3 / bare));
                }
                assertEquals(0, gl.tracker().live() - 3);
            }
        }
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

    /** Bare instanced draws of {@code triangles} triangles and {@code lines} lines, 20 per instance. */
    private static double bareFps(GlContext gl, World world, ViewCamera cam, long triangles, long lines) {
        int triInstances = (int) ((triangles + PER_INSTANCE - 1) / PER_INSTANCE);
        int lineInstances = (int) ((lines + PER_INSTANCE - 1) / PER_INSTANCE);
        // a narrow blade of 20 stacked triangles, and a polyline of 20 segments, both 0.4 m high
        FloatBuffer v = MemoryUtil.memAllocFloat(PER_INSTANCE * 9 + PER_INSTANCE * 6);
        FloatBuffer o = MemoryUtil.memAllocFloat(3 * Math.max(1, Math.max(triInstances, lineInstances)));
        for (int t = 0; t < PER_INSTANCE; t++) {
            float y = t * 0.02f;
            v.put(0).put(y).put(0).put(0.006f).put(y).put(0).put(0).put(y + 0.02f).put(0);
        }
        for (int t = 0; t < PER_INSTANCE; t++) {
            float y = t * 0.02f;
            v.put(0).put(y).put(0).put(0.002f * (t % 2)).put(y + 0.02f).put(0);
        }
        v.flip();
        int plants = Math.max(1, world.plantCount());
        for (int i = 0; i < o.capacity() / 3; i++) {
            int p = i % plants;
            float jitter = 0.05f * (i / plants);
            o.put(world.plantX(p) + jitter).put(world.plantY(p)).put(world.plantZ(p) + jitter);
        }
        o.flip();
        try (GlProgram prog = new GlProgram(gl.tracker(), "bare.vert", "bare.frag");
             GlVertexArray vao = new GlVertexArray(gl.tracker());
             GlBuffer buf = GlBuffer.of(gl.tracker(), GL_ARRAY_BUFFER, v, GL_STATIC_DRAW);
             GlBuffer offsets = GlBuffer.of(gl.tracker(), GL_ARRAY_BUFFER, o, GL_STATIC_DRAW)) {
            vao.bind();
            buf.bind();
            glEnableVertexAttribArray(0);
            glVertexAttribPointer(0, 3, GL_FLOAT, false, 12, 0L);
            offsets.bind();
            glEnableVertexAttribArray(1);
            glVertexAttribPointer(1, 3, GL_FLOAT, false, 12, 0L);
            glVertexAttribDivisor(1, 1);
            prog.use();
            FloatBuffer m = MemoryUtil.memAllocFloat(16);
            glUniformMatrix4fv(prog.uniform("uViewProj"), false, cam.viewProjection(new Matrix4f()).get(m));
            MemoryUtil.memFree(m);
            glEnable(GL_DEPTH_TEST);
            long t0 = 0;
            for (int i = 0; i < WARM + FRAMES; i++) {
                if (i == WARM) {
                    t0 = System.nanoTime();
                }
                glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
                if (triInstances > 0) {
                    glDrawArraysInstanced(GL_TRIANGLES, 0, PER_INSTANCE * 3, triInstances);
                }
                if (lineInstances > 0) {
                    glDrawArraysInstanced(GL_LINES, PER_INSTANCE * 3, PER_INSTANCE * 2, lineInstances);
                }
                glFinish();
            }
            glDisable(GL_DEPTH_TEST);
            glBindVertexArray(0);
            return FRAMES / ((System.nanoTime() - t0) / 1e9);
        } finally {
            MemoryUtil.memFree(v);
            MemoryUtil.memFree(o);
        }
    }
}
