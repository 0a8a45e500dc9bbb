package org.jecosys.app;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.ByteBuffer;
import java.nio.file.Path;
import org.jecosys.math.ViewCamera;
import org.jecosys.render.GlContext;
import org.jecosys.render.GlContext.DebugOutput;
import org.jecosys.render.OpenWorldRenderer;
import org.jecosys.render.RenderSettings;
import org.jecosys.render.ShadowPath;
import org.jecosys.render.gl.GlContexts;
import org.jecosys.render.gl.GlFramebuffer;
import org.jecosys.render.gl.Pixels;
import org.jecosys.scene.OutputFiles;
import org.jecosys.scene.SceneDef;
import org.jecosys.scene.Scenes;
import org.jecosys.sim.CameraWalk;
import org.jecosys.sim.DrawQuality;
import org.jecosys.sim.OpenWorld;
import org.lwjgl.system.MemoryUtil;

/**
 * {@code jecosys render} on an open world ({@code <world>}): the camera walks the scene's path over the
 * world's hills, 30 frames a second, tiles streamed around it and drawn by an {@link OpenWorldRenderer}
 * (sky, each tile's ground, the plants); frames written as for a scene of one square. On a software
 * rasteriser without {@code --quality} the plants are thinned at the low quality, as the viewer does.
 */
final class OpenWorldFrames {
    private OpenWorldFrames() {
    }

    static void run(org.jecosys.scene.Scene scene, DrawQuality quality, int frames, Path out, int width, int height,
                    boolean holdFirst, PrintWriter log) throws IOException {
        SceneDef def = scene.def();
        OutputFiles files = new OutputFiles();
        ByteBuffer px = MemoryUtil.memAlloc(4 * width * height);
        try (OpenWorld world = Scenes.openWorld(scene, 2, 1);
             GlContext gl = GlContext.headless(DebugOutput.OFF)) {
            log.println("OpenGL: " + gl.describe());
            log.printf("Open world: %s m tiles within %s m of the camera, streamed along its path%n",
                    def.world().tileSize(), def.world().radius());
            log.flush();
            DrawQuality q = quality != null ? quality : ShadowPath.software(gl.describe()) ? DrawQuality.LOW : null;
            if (q != null) {
                world.setThinning(q.thinStart(), q.thinEnd(), q.thinMinFraction());
            }
            CameraWalk walk = new CameraWalk(def.camera(), def.world().relief(), width / (double) height);
            RenderSettings settings = HeadlessRender.settings(def.render());
            // the start is loaded first, as behind a loading screen
            ViewCamera start = walk.at(0);
            world.load(start);
            try (GlFramebuffer fb = new GlFramebuffer(GlContexts.tracker(gl), width, height,
                    def.render().antialiasing());
                 OpenWorldRenderer renderer = new OpenWorldRenderer(gl, world, settings)) {
                // the tiles' renderers are made a few a frame: draw until every live tile has one
                for (int k = 0; k < 256 && renderer.tileRenderers() < world.liveTiles(); k++) {
                    fb.bind();
                    renderer.render(start, width, height);
                }
                HeadlessRender.accumulate(fb);
                for (int i = 1; i <= frames; i++) {
                    ViewCamera camera = walk.at(world.time());
                    world.step(HeadlessRender.FRAME_DT, camera);
                    // the first picture as a view held still shows it (the render command); later ones as the walk
                    // and the wind move
                    boolean hold = i == 1 && holdFirst;
                    for (int k = 0; k < (hold ? Math.max(1, fb.accumulation()) : 1); k++) {
                        fb.bind();
                        renderer.render(fb.jittered(camera, hold), width, height);
                        fb.resolve();
                    }
                    Pixels.read(width, height, px);
                    files.writeFile(out.resolve(HeadlessRender.frameName(i)),
                            temporary -> Pixels.writePng(temporary, px, width, height));
                }
                log.printf("%d tiles alive at the end, %d tile renderers made%n", world.liveTiles(),
                        renderer.renderersMade());
            }
        } finally {
            MemoryUtil.memFree((java.nio.Buffer) px);
        }
        log.println("Wrote " + frames + " frame(s) of " + width + "x" + height + " to " + out.toAbsolutePath());
        log.flush();
    }
}
