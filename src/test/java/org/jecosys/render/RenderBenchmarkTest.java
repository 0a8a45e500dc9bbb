package org.jecosys.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.lwjgl.opengl.GL11C.GL_FLOAT;
import static org.lwjgl.opengl.GL11C.GL_TRIANGLES;
import static org.lwjgl.opengl.GL11C.glFinish;
import static org.lwjgl.opengl.GL15C.GL_ARRAY_BUFFER;
import static org.lwjgl.opengl.GL15C.GL_STATIC_DRAW;
import static org.lwjgl.opengl.GL20C.glEnableVertexAttribArray;
import static org.lwjgl.opengl.GL20C.glUniformMatrix4fv;
import static org.lwjgl.opengl.GL20C.glVertexAttribPointer;
import static org.lwjgl.opengl.GL31C.glDrawArraysInstanced;

import java.nio.FloatBuffer;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.jecosys.field.QuadtreeForceField;
import org.jecosys.math.ViewCamera;
import org.jecosys.scene.SceneDef;
import org.jecosys.sim.Frame;
import org.jecosys.sim.World;
import org.jecosys.terrain.Heightfield;
import org.jecosys.wind.WindField;
import org.joml.Matrix4f;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.lwjgl.system.MemoryUtil;

/**
 * Rendering benchmark on this machine's GL (llvmpipe here): C1-C3 and meadow at 1280x720, static vs
 * animated frames (Table 7 S1 vs S3), force field updated per frame vs not (Table 6), and the scene's
 * frame against a bare instanced draw of the same triangle count, in the same run. Writes
 * target/bench/render.md. Run with {@code mvn -B verify -Pbench}. No timing assertions.
 */
@Tag("benchmark")
class RenderBenchmarkTest {
    private static final int W = 1280;
    private static final int H = 720;
    private static final int WARM = 3;
    private static final int FRAMES = 12;

    @Test
    void renderBenchmark() throws Exception {
        StringBuilder md = new StringBuilder("# Rendering benchmark\n\n");
        try (GlContext gl = GlContext.headless(false); GlFramebuffer fb = new GlFramebuffer(gl.tracker(), W, H)) {
            md.append("GL: ").append(gl.describe()).append(", ").append(W).append('x').append(H)
                    .append(", ").append(FRAMES).append(" frames after ").append(WARM).append(" warm-up, glFinish per frame. ")
                    .append("Animated frames are refilled every frame (a synthetic travelling wave, the animation engine ")
                    .append("is not merged yet); field on = QuadtreeForceField.update(camera) every frame.\n\n")
                    .append("| scene | plants | triangles | lines | S1 static fps | S3 animated fps | S3/S1 | field off fps")
                    .append(" | field on fps | on/off | bare instanced fps | scene/bare |\n")
                    .append("|---|---|---|---|---|---|---|---|---|---|---|---|\n");
            for (String name : List.of("c1.xml", "c2.xml", "c3.xml", "meadow.xml")) {
                SceneDef def = RenderScenes.load(name);
                World world = RenderScenes.build(def);
                ViewCamera cam = RenderScenes.camera(def, world, W, H);
                Heightfield h = world.terrain().heightfield();
                float[] xs = new float[world.plantCount()];
                float[] zs = new float[world.plantCount()];
                for (int p = 0; p < xs.length; p++) {
                    xs[p] = world.plantX(p);
                    zs[p] = world.plantZ(p);
                }
                QuadtreeForceField field = QuadtreeForceField.build(def.field(), h.minX(), h.minZ(), h.maxX(), h.maxZ(),
                        h.minHeight(), h.maxHeight() + 1, WindField.of(def.flows()), xs, zs);
                Frame rest = TestFrames.rest(world);
                Frame[] wind = new Frame[8];
                for (int i = 0; i < wind.length; i++) {
                    wind[i] = TestFrames.wind(world, i * 0.1);
                }
                try (SceneRenderer r = new SceneRenderer(gl, world, new RenderSettings())) {
                    fb.bind();
                    double s1 = fps(r, rest, null, cam, null);
                    double s3 = fps(r, null, wind, cam, null);
                    double off = fps(r, null, wind, cam, null);
                    double on = fps(r, null, wind, cam, field);
                    long tri = r.triangles();
                    long lines = r.lines();
                    double bare = bareFps(gl, cam, tri);
                    md.append(String.format("| %s | %d | %d | %d | %.1f | %.1f | %.2f | %.1f | %.1f | %.2f | %.1f | %.2f |%n",
                            def.name(), world.plantCount(), tri, lines, s1, s3, s3 / s1, off, on, on / off, bare,
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

    private static double fps(SceneRenderer r, Frame fixed, Frame[] frames, ViewCamera cam, QuadtreeForceField field) {
        long t0 = 0;
        for (int i = 0; i < WARM + FRAMES; i++) {
            if (i == WARM) {
                t0 = System.nanoTime();
            }
            if (field != null) {
                field.update(cam);
            }
            r.render(fixed != null ? fixed : frames[i % frames.length], cam, W, H);
            glFinish();
        }
        return FRAMES / ((System.nanoTime() - t0) / 1e9);
    }

    /** A bare instanced draw of {@code triangles} triangles, 20 per instance, with a trivial shader. */
    private static double bareFps(GlContext gl, ViewCamera cam, long triangles) {
        int perInstance = 20;
        int instances = (int) Math.max(1, triangles / perInstance);
        FloatBuffer v = MemoryUtil.memAllocFloat(perInstance * 9);
        for (int t = 0; t < perInstance; t++) {
            float y = t * 0.02f;
            v.put(0).put(y).put(0).put(0.01f).put(y).put(0).put(0).put(y + 0.02f).put(0);
        }
        v.flip();
        try (GlProgram prog = new GlProgram(gl.tracker(), "bare.vert", "bare.frag");
             GlVertexArray vao = new GlVertexArray(gl.tracker())) {
            vao.bind();
            try (GlBuffer buf = GlBuffer.of(gl.tracker(), GL_ARRAY_BUFFER, v, GL_STATIC_DRAW)) {
                glEnableVertexAttribArray(0);
                glVertexAttribPointer(0, 3, GL_FLOAT, false, 12, 0L);
                prog.use();
                FloatBuffer m = MemoryUtil.memAllocFloat(16);
                glUniformMatrix4fv(prog.uniform("uViewProj"), false, cam.viewProjection(new Matrix4f()).get(m));
                MemoryUtil.memFree(m);
                long t0 = 0;
                for (int i = 0; i < WARM + FRAMES; i++) {
                    if (i == WARM) {
                        t0 = System.nanoTime();
                    }
                    org.lwjgl.opengl.GL11C.glClear(org.lwjgl.opengl.GL11C.GL_COLOR_BUFFER_BIT
                            | org.lwjgl.opengl.GL11C.GL_DEPTH_BUFFER_BIT);
                    glDrawArraysInstanced(GL_TRIANGLES, 0, perInstance * 3, instances);
                    glFinish();
                }
                return FRAMES / ((System.nanoTime() - t0) / 1e9);
            }
        } finally {
            MemoryUtil.memFree(v);
        }
    }
}
