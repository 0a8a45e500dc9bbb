package org.jecosys.app;

import org.jecosys.render.gl.GlContexts;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.ByteBuffer;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.jecosys.math.Progress;
import org.jecosys.math.ViewCamera;
import org.jecosys.plant.ComponentType;
import org.jecosys.plant.PoseTable;
import org.jecosys.plant.SpeciesModel;
import org.jecosys.render.GlContext;
import org.jecosys.render.GlContext.DebugOutput;
import org.jecosys.render.gl.GlFramebuffer;
import org.jecosys.render.gl.Pixels;
import org.jecosys.render.SceneRenderer;
import org.jecosys.render.ShadowPath;
import org.jecosys.scene.OutputFiles;
import org.jecosys.scene.RenderDef;
import org.jecosys.scene.Scene;
import org.jecosys.scene.SceneDef;
import org.jecosys.terrain.ImageSource;
import org.jecosys.sim.Frame;
import org.jecosys.sim.Simulation;
import org.jecosys.sim.World;
import org.joml.Vector3f;
import org.lwjgl.system.MemoryUtil;

/**
 * The gallery of {@code jecosys gallery} (and of docs/gallery in the repository): a fixed set of views
 * of the shipped scenes, each rendered headless after {@link #STEPS} fixed animation steps of a fresh
 * simulation, so the pictures depend only on the scene files and the renderer. File names and views:
 * <ul>
 * <li>{@code meadow-default.png}: the meadow from its start camera;</li>
 * <li>{@code meadow-closeup.png}: 1 m from the middle of the densest patch of the meadow's second
 *     species (the yellow flowers), eye 0.6 m above the ground, looking at the flower heads;</li>
 * <li>{@code meadow-above.png}: straight down from 10 m above the middle of the meadow;</li>
 * <li>{@code meadow-backlit.png}: the start camera turned to look toward the scene's sun (its
 *     {@code <light sunAzimuth>});</li>
 * <li>{@code meadow-gusts.png}: from 4 m up at the start camera, looking downwind along the first flow's
 *     heading after {@link #GUST_STEPS} steps: the gusts as bands of bent, paler grass (the wind's
 *     sheen);</li>
 * <li>{@code meadow-trail.png}: a walker (a source of {@link #WALKER_STRENGTH} m^2/s, twice the example
 *     game's player) crosses 8 m of the first species' densest patch (along X) in {@link #TRAIL_STEPS}
 *     steps; the picture is taken from 4 m up, 1.5 m back from the middle of its path: the lane of
 *     flattened tufts it leaves (the grasses' {@code recovery}; without it they would stand again)</li>
 * <li>{@code meadow-shadowmap.png}: the close-up's view with the sun's shadows drawn by the shadow map
 *     ({@code ShadowPath.MAP}, whatever the GL): the plants shade the ground and each other as they
 *     sway (the other views take the path the GL calls for: the ground splat on llvmpipe);</li>
 * <li>{@code textured-default.png} and {@code textured-closeup.png}: the textured meadow
 *     ({@code scenes/textured.xml}, the project's own blade, petal and flower-head images) from its
 *     start camera and from the close-up's place;</li>
 * <li>{@code rose-level0.png}, {@code rose-level1.png}, {@code rose-level2.png}: the rose at 1.2 m,
 *     12 m and 20 m (each distance falls in one level of detail: triangles, fewer triangles, lines),
 *     from 45 degrees, the lens narrowed so that the rose fills the picture's height at every distance;</li>
 * <li>{@code c1.png}, {@code c2.png}, {@code c3.png}: the paper's scenes from their start cameras.</li>
 * </ul>
 */
final class Gallery {
    static final int WIDTH = 960;
    static final int HEIGHT = 540;
    /** Fixed animation steps run before each picture (the wind has started to move the plants). */
    static final int STEPS = 60;
    /** Steps before the gust view: the gusts have crossed the field for five seconds. */
    static final int GUST_STEPS = 300;
    /** Steps the trail view's walker takes to cross its 8 m. */
    static final int TRAIL_STEPS = 360;
    /** The trail view's walker, m^2/s. */
    static final double WALKER_STRENGTH = 40;
    /** The scene files the gallery needs. */
    static final List<String> SCENES = List.of("meadow.xml", "textured.xml", "rose.xml", "c1.xml", "c2.xml", "c3.xml");
    /** Every file the gallery writes, in order. */
    static final List<String> FILES = List.of("meadow-default.png", "meadow-closeup.png", "meadow-above.png",
            "meadow-backlit.png", "meadow-gusts.png", "meadow-trail.png", "meadow-shadowmap.png",
            "textured-default.png", "textured-closeup.png", "rose-level0.png",
            "rose-level1.png", "rose-level2.png", "c1.png", "c2.png", "c3.png");

    /** A scene file with problems (already printed). */
    static final class BadScene extends Exception {
        private static final long serialVersionUID = 1L;

        BadScene(String file) {
            super(file);
        }
    }

    private Gallery() {
    }

    /**
     * A view: its file, camera, the steps run before it and, for the trail view, a walker's path from
     * (x0, z0) to (x1, z1), metres (null for none).
     */
    private record View(String file, ViewCamera camera, int steps, double[] walk, ShadowPath shadows) {
        View(String file, ViewCamera camera) {
            this(file, camera, STEPS, null, ShadowPath.AUTO);
        }
    }

    static void render(Path scenes, Path out, int width, int height, PrintWriter log, PrintWriter err)
            throws IOException, BadScene {
        OutputFiles files = new OutputFiles(); // makes the folder with the first picture, once a scene was accepted
        double aspect = width / (double) height;
        ByteBuffer px = MemoryUtil.memAlloc(4 * width * height);
        try (GlContext gl = GlContext.headless(DebugOutput.OFF);
             GlFramebuffer fb = new GlFramebuffer(GlContexts.tracker(gl), width, height, RenderDef.DEFAULT_ANTIALIASING)) {
            for (String name : SCENES) {
                Scene loaded = SceneArgs.load(scenes.resolve(name), ImageSource.folder(scenes), err);
                if (loaded == null) {
                    throw new BadScene(name);
                }
                SceneDef def = loaded.def();
                World world = World.build(def.simulationDef(), loaded.images(),
                        Runtime.getRuntime().availableProcessors(), Progress.NONE);
                List<View> views = views(name, def, world, aspect);
                try (SceneRenderer renderer = new SceneRenderer(gl, world, HeadlessRender.settings(def.render()))) {
                    for (View v : views) {
                        try (Simulation sim = Simulation.of(world, def.simulationDef(), 0)) {
                            sim.setLodTransition(def.render().lodTransition());
                            org.jecosys.wind.WindSource walker = v.walk() == null ? null : sim.attachAgent(
                                    org.jecosys.wind.FlowDef.point("walker", org.jecosys.wind.FlowKind.SOURCE,
                                            v.walk()[0], v.walk()[1], WALKER_STRENGTH));
                            for (int i = 0; i < v.steps(); i++) {
                                if (walker != null) {
                                    double f = Math.min(1, i / (0.9 * v.steps()));
                                    sim.moveAgent(walker, v.walk()[0] + f * (v.walk()[2] - v.walk()[0]),
                                            v.walk()[1] + f * (v.walk()[3] - v.walk()[1]));
                                }
                                sim.stepFixed(v.camera());
                            }
                            Frame frame = sim.latestFrame();
                            renderer.settings().setShadowPath(v.shadows());
                            HeadlessRender.accumulate(fb);
                            fb.resetHistory();
                            HeadlessRender.drawStill(fb, renderer, frame, v.camera(), width, height);
                            Pixels.read(width, height, px);
                            files.writeFile(out.resolve(v.file()),
                                    temporary -> Pixels.writePng(temporary, px, width, height));
                        }
                        log.println("Wrote " + out.resolve(v.file()));
                        log.flush();
                    }
                }
            }
        } finally {
            MemoryUtil.memFree((java.nio.Buffer) px);
        }
    }

    private static List<View> views(String scene, SceneDef def, World world, double aspect) {
        List<View> views = new ArrayList<>();
        double ground = world.terrain().heightfield().height(def.camera().x(), def.camera().z());
        switch (scene) {
            case "meadow.xml" -> {
                views.add(new View("meadow-default.png", ViewCamera.of(def.camera(), ground, aspect)));
                views.add(new View("meadow-closeup.png", closeUp(def, world, aspect)));
                double gy = world.terrain().heightfield().height(0, 0);
                views.add(new View("meadow-above.png", camera(0, gy + 10, 0, 0, -Math.PI / 2 + 1e-3,
                        def.camera().fovY(), aspect, 0.1, 200)));
                ViewCamera back = ViewCamera.of(def.camera(), ground, aspect);
                double az = def.render().light().sunAzimuth(); // toward the sun: (cos az, sin az) on the ground
                back.setOrientation(Math.atan2(Math.cos(az), -Math.sin(az)), def.camera().pitch());
                views.add(new View("meadow-backlit.png", back));
                views.add(gusts(def, ground, aspect));
                views.add(trail(def, world, aspect));
                views.add(new View("meadow-shadowmap.png", closeUp(def, world, aspect), STEPS, null, ShadowPath.MAP));
            }
            case "rose.xml" -> {
                double[] distances = {1.2, 12, 20};
                double tip = stalkTip(world, 0);
                double mid = world.plantY(0) + 0.5 * tip;
                for (int level = 0; level < distances.length; level++) {
                    double d = distances[level];
                    double a = Math.toRadians(45);
                    double fov = 2 * Math.atan(0.6 * tip / d);
                    views.add(new View("rose-level" + level + ".png", camera(world.plantX(0) - d * Math.sin(a), mid,
                            world.plantZ(0) + d * Math.cos(a), a, 0, fov, aspect, 0.02, 500)));
                }
            }
            case "textured.xml" -> {
                views.add(new View("textured-default.png", ViewCamera.of(def.camera(), ground, aspect)));
                views.add(new View("textured-closeup.png", closeUp(def, world, aspect)));
            }
            default -> views.add(new View(scene.replace(".xml", ".png"), ViewCamera.of(def.camera(), ground, aspect)));
        }
        return views;
    }

    /** From 4 m over the start camera's ground, looking downwind (the first flow's heading), 15 degrees down. */
    private static View gusts(SceneDef def, double ground, double aspect) {
        double heading = def.simulationDef().flows().isEmpty() ? 0 : def.simulationDef().flows().get(0).direction();
        ViewCamera c = camera(def.camera().x(), ground + 4, def.camera().z(),
                Math.atan2(Math.cos(heading), -Math.sin(heading)), Math.toRadians(-15), def.camera().fovY(), aspect,
                0.1, 300);
        return new View("meadow-gusts.png", c, GUST_STEPS, null, ShadowPath.AUTO);
    }

    /**
     * A walker across 8 m (along X) of the first species' densest patch, seen from 4 m above the
     * ground 1.5 m south of the middle of its path, looking at that middle.
     */
    private static View trail(SceneDef def, World world, double aspect) {
        int best = Math.max(0, world.densestPlant(0, 2));
        double x = world.plantX(best);
        double z = world.plantZ(best);
        double eye = world.terrain().heightfield().height(x, z + 1.5) + 4;
        double pitch = Math.atan2(world.plantY(best) - eye, 1.5);
        ViewCamera c = camera(x, eye, z + 1.5, 0, pitch, def.camera().fovY(), aspect, 0.05, 300);
        return new View("meadow-trail.png", c, TRAIL_STEPS, new double[] {x - 4, z, x + 4, z}, ShadowPath.AUTO);
    }

    /** 1 m south of the yellow flowers' densest patch, eye 0.6 m up, looking at the flower heads. */
    private static ViewCamera closeUp(SceneDef def, World world, double aspect) {
        int species = Math.min(1, world.plants().species().size() - 1);
        int best = Math.max(0, world.densestPlant(species, 1));
        double x = world.plantX(best);
        double z = world.plantZ(best) + 1;
        double eye = world.terrain().heightfield().height(x, z) + 0.6;
        double target = world.plantY(best) + stalkTip(world, best);
        double pitch = Math.atan2(target - eye, 1);
        return camera(x, eye, z, 0, pitch, def.camera().fovY(), aspect, 0.02, 500);
    }

    /** A camera at (x, y, z) metres looking by yaw and pitch (radians) through the given lens. */
    private static ViewCamera camera(double x, double y, double z, double yaw, double pitch, double fovY,
                                     double aspect, double near, double far) {
        ViewCamera c = new ViewCamera();
        c.setPosition(x, y, z);
        c.setOrientation(yaw, pitch);
        c.setLens(fovY, aspect, near, far);
        return c;
    }

    /** Height of plant p's stalk tip at rest above its base, metres (0.3 when it has no stalk). */
    private static double stalkTip(World world, int p) {
        SpeciesModel m = world.plants().species().get(world.plantSpecies(p));
        for (int slot = 0; slot < m.slotCount(); slot++) {
            if (m.def().components().get(m.slotComponent(slot)).type() == ComponentType.STALK) {
                PoseTable t = m.slotPoseTable(slot, world.plantVariant(p));
                return t.position(0, t.points() - 1, new Vector3f()).y;
            }
        }
        return 0.3;
    }
}
