package org.jecosys.bench;

import java.lang.management.ManagementFactory;
import java.lang.management.MemoryMXBean;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.jecosys.terrain.DistributionDef;
import org.jecosys.world.RollingTerrain;
import org.jecosys.world.TilePlacer;
import org.jecosys.world.TilePlants;
import org.jecosys.world.TileStreamer;

/**
 * The open world's tiles along a walk (issue 39, its placement part): a view walks straight at 10 m/s
 * over unbounded rolling hills, 30 updates a second, keeping the plants of 32 m tiles within 100 m
 * (a meadow-like mix at about 5.7 plants per m^2, on two workers). Each simulated second the section
 * waits for the tiles started (settle), and the time that takes is what the workers need per second
 * of walking: below a second, tiles keep pace in real time. At checkpoints it reports the heap after a
 * full GC, the tiles and plants alive and the tiles built so far. The simulation and the renderer do not
 * stream yet: this measures what placing and holding the tiles costs.
 */
final class StreamingSection implements Section {
    private static final double SPEED = 10;
    private static final double RATE = 30;
    private static final double TILE = 32;
    private static final double RADIUS = 100;

    @Override
    public String name() {
        return "open-world tiles along a walk";
    }

    /** A meadow-like mix: 7.6 candidates per m^2, of which the competition keeps about 5.7. */
    static List<DistributionDef> meadow() {
        return List.of(
                DistributionDef.builder("grassA").density(4.3).footprint(0.05).tufts(0.12, 3).build(),
                DistributionDef.builder("flowerB").density(2.4).footprint(0.08).clump(2, 0.6).build(),
                DistributionDef.builder("grassS").density(0.9).footprint(0.15).build());
    }

    @Override
    public void run(Mode mode, Report report) throws Exception {
        double[] checkpoints = switch (mode) {
            case SMOKE -> new double[] {100, 250};
            case QUICK -> new double[] {500, 1000, 2000};
            case FULL -> new double[] {1000, 2500, 5000};
        };
        TilePlacer placer = new TilePlacer(2005, TILE, meadow(), new int[] {0, 1, 2}, RollingTerrain.gentle(2005));
        Table t = new Table("streaming", "Open-world tiles along a straight walk at 10 m/s (32 m tiles within 100 m, "
                + "2 workers)", List.of("distance m", "heap after GC MB", "tiles alive", "plants alive", "tiles built",
                "worker s per s walked (median)", "worker s per s walked (max)", "update ms (p99)"));
        MemoryMXBean memory = ManagementFactory.getMemoryMXBean();
        List<Object> raw = new ArrayList<>();
        try (TileStreamer<TilePlants> s = TileStreamer.of(placer, RADIUS, 2, 16)) {
            double[] x = {0};
            double[] z = {0};
            // load the start before timing, as a game's loading screen would
            for (int k = 0; k < 64; k++) {
                s.update(x, z, 1);
                if (s.pendingTiles() == 0) {
                    break; // nothing more to start: every tile within the radius is alive
                }
                s.settle();
            }
            int perSecond = (int) RATE;
            double end = checkpoints[checkpoints.length - 1];
            int seconds = (int) Math.ceil(end / SPEED);
            double[] settle = new double[seconds];
            double[] update = new double[seconds * perSecond];
            int next = 0;
            for (int sec = 0; sec < seconds; sec++) {
                for (int k = 0; k < perSecond; k++) {
                    x[0] += SPEED / RATE;
                    long t0 = System.nanoTime();
                    s.update(x, z, 1);
                    update[sec * perSecond + k] = (System.nanoTime() - t0) * 1e-6;
                }
                long t0 = System.nanoTime();
                s.settle();
                settle[sec] = (System.nanoTime() - t0) * 1e-9;
                if (next < checkpoints.length && (sec + 1) * SPEED >= checkpoints[next] - 1e-9) {
                    System.gc();
                    System.gc();
                    double heap = memory.getHeapMemoryUsage().getUsed() / (1024.0 * 1024.0);
                    double[] sofar = java.util.Arrays.copyOf(settle, sec + 1);
                    double[] updates = java.util.Arrays.copyOf(update, (sec + 1) * perSecond);
                    double most = 0;
                    for (double v : sofar) {
                        most = Math.max(most, v);
                    }
                    t.row(Math.round(x[0]), heap, s.liveTiles(), s.livePlants(), s.builtTiles(), Stats.median(sofar),
                            most, Stats.percentile(updates, 0.99));
                    Map<String, Object> row = new LinkedHashMap<>();
                    row.put("distance", x[0]);
                    row.put("heapMB", heap);
                    row.put("tiles", s.liveTiles());
                    row.put("plants", s.livePlants());
                    row.put("built", s.builtTiles());
                    row.put("workerSecondsPerSecondMedian", Stats.median(sofar));
                    row.put("workerSecondsPerSecondMax", most);
                    row.put("updateP99Ms", Stats.percentile(updates, 0.99));
                    raw.add(row);
                    next++;
                }
            }
            t.note("The heap after GC stays level while the walk goes on: tiles behind the view are let go. "
                    + "Workers keep pace in real time while their seconds per second walked stay below 1. "
                    + "Each second the run waits for the tiles started; updates themselves never wait.");
        }
        report.add(t);
        report.raw("streaming", raw);
    }
}
