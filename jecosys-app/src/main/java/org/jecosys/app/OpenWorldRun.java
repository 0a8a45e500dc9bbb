package org.jecosys.app;

import java.io.IOException;
import java.io.PrintWriter;
import java.lang.management.ManagementFactory;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import org.jecosys.bench.Json;
import org.jecosys.math.ViewCamera;
import org.jecosys.scene.OutputFiles;
import org.jecosys.scene.SceneDef;
import org.jecosys.scene.Scenes;
import org.jecosys.sim.CameraWalk;
import org.jecosys.sim.OpenWorld;
import org.jecosys.sim.WorldTile;
import org.jecosys.sim.SimulationDef;
import org.jecosys.world.WorldDef;

/**
 * {@code jecosys simulate} on an open world ({@code <world>}): the camera walks the scene's path over
 * the world's hills, one fixed step at a time as fast as it goes (after the start is loaded, as behind a
 * loading screen), tiles streamed around it on one tile worker; prints the step's median and 99th percentile, the tiles and plants alive at the end, the
 * tiles built and the steps that waited for one, and a hash of every live tile's state.
 */
final class OpenWorldRun {
    private OpenWorldRun() {
    }

    static int run(Path file, SceneDef scene, SimulationDef sd, int steps, int workers, Path json, PrintWriter out,
                   PrintWriter err) {
        SceneDef withOverrides = new SceneDef(scene.version(), scene.name(), scene.seed(), scene.terrain(),
                scene.species(), scene.distributions(), scene.placements(), scene.flows(), sd.field(), scene.camera(),
                sd.animation(), scene.render(), scene.world());
        WorldDef world = scene.world();
        double[] ms = new double[steps];
        long hash;
        int tiles;
        long plants;
        long components;
        long built;
        long waits;
        double allocated;
        com.sun.management.ThreadMXBean threads = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        long self = Thread.currentThread().getId();
        try (OpenWorld w = Scenes.openWorld(withOverrides, workers, 1)) {
            CameraWalk walk = new CameraWalk(scene.camera(), world.relief(),
                    (double) scene.render().width() / scene.render().height());
            err.printf(Locale.ROOT, "open world: %.0f m tiles within %.0f m of the camera%n", world.tileSize(),
                    world.radius());
            err.flush();
            // the start is loaded first, as a game's loading screen would: the timed steps walk from there
            ViewCamera start = walk.at(0);
            w.load(start);
            int warm = Math.max(1, steps / 2);
            long alloc0 = 0;
            threads.getThreadAllocatedBytes(self);
            for (int i = 0; i < steps; i++) {
                if (i == warm) {
                    alloc0 = threads.getThreadAllocatedBytes(self);
                }
                ViewCamera cam = walk.at(w.time());
                long t0 = System.nanoTime();
                w.stepFixed(cam);
                ms[i] = (System.nanoTime() - t0) / 1e6;
            }
            allocated = (double) (threads.getThreadAllocatedBytes(self) - alloc0) / Math.max(1, steps - warm);
            long h = 1125899906842597L;
            for (int k = 0; k < w.liveTiles(); k++) {
                WorldTile t = w.tile(k);
                h = 31 * (31 * (31 * h + t.i()) + t.j()) + t.simulation().inspect().stateHash();
            }
            hash = h;
            tiles = w.liveTiles();
            plants = w.livePlants();
            components = w.liveComponents();
            built = w.builtTiles();
            waits = w.tileWaits();
        }
        double[] sorted = ms.clone();
        Arrays.sort(sorted);
        double median = sorted[sorted.length / 2];
        double p99 = sorted[Math.min(sorted.length - 1, (int) Math.ceil(0.99 * sorted.length) - 1)];
        out.printf(Locale.ROOT, "scene                 %s (open world)%n", file);
        out.printf(Locale.ROOT, "tiles alive           %d%n", tiles);
        out.printf(Locale.ROOT, "plants alive          %d%n", plants);
        out.printf(Locale.ROOT, "components alive      %d%n", components);
        out.printf(Locale.ROOT, "tiles built           %d (%d steps waited for one)%n", built, waits);
        out.printf(Locale.ROOT, "steps                 %d (dt %s s, %d workers)%n", steps, sd.animation().fixedStep(),
                workers);
        out.printf(Locale.ROOT, "median ms per step    %.4f%n", median);
        out.printf(Locale.ROOT, "p99 ms per step       %.4f%n", p99);
        out.printf(Locale.ROOT, "allocated bytes/step  %.1f%n", allocated);
        out.printf(Locale.ROOT, "state hash            %016x%n", hash);
        out.flush();
        if (json != null) {
            Map<String, Object> m = new LinkedHashMap<>();
            m.put("scene", file.toString());
            m.put("openWorld", true);
            m.put("tiles", tiles);
            m.put("plants", plants);
            m.put("components", components);
            m.put("tilesBuilt", built);
            m.put("waits", waits);
            m.put("steps", steps);
            m.put("medianMsPerStep", median);
            m.put("p99MsPerStep", p99);
            m.put("allocatedBytesPerStep", allocated);
            m.put("stateHash", String.format(Locale.ROOT, "%016x", hash));
            String text = Json.write(m);
            try {
                new OutputFiles().write(json, o -> o.write(text.getBytes(StandardCharsets.UTF_8)));
            } catch (IOException e) {
                err.println("jecosys simulate: " + e.getMessage());
                err.flush();
                return ExitCodes.FAILURE;
            }
        }
        return ExitCodes.OK;
    }
}
