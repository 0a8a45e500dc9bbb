package org.jecosys.scene;

import java.util.List;
import java.util.Locale;
import org.jecosys.plant.ComponentDef;
import org.jecosys.plant.SpeciesDef;
import org.jecosys.terrain.CompetitiveDistributor;
import org.jecosys.terrain.DistributionDef;
import org.jecosys.terrain.ImageFiles;
import org.jecosys.terrain.TerrainDef;

/**
 * "Accepted means runnable": an upper bound of the memory a valid scene needs to be built and run
 * (plants, components, pose tables, terrain grids and maps, images from their headers, the
 * distribution's working state), compared with the Java heap before anything is built. A scene that
 * cannot fit is refused with a located problem naming the limit, at the attribute that asks for the
 * most. The per-item costs are measured peaks of building and running (World, Simulation, frames,
 * quadtree with one plant per node), rounded up. Time is bounded beside it by {@link SceneWorkBudget}
 * (placement work, ground-cover blades per frame). One instance per load; not thread-safe.
 */
final class SceneBudget {
    /** Heap bytes per plant, peak (layout, world, quadtree down to one plant per node, animation). */
    static final long BYTES_PER_PLANT = 1000;
    /** Heap and direct bytes per component, peak (world index, animation state, three frames). */
    static final long BYTES_PER_COMPONENT = 130;
    /** Bytes per skeleton point of one pose of one variant (pose table and meshes). */
    static final long BYTES_PER_POSE_POINT = 48;
    /** Bytes per heightfield vertex (heights, normals, the build's and the valleys' work arrays). */
    static final long BYTES_PER_TERRAIN_VERTEX = 64;
    /** Bytes per resource-map cell (the terrain's map, the distribution's copy and the result). */
    static final long BYTES_PER_MAP_CELL = 48;
    /** Bytes of one distribution's working state beyond its plants (suitability mask, candidates). */
    static final long BYTES_PER_DISTRIBUTION = 512L * 512 * 5 + 32768L * 25;
    /** What the program itself needs besides the scene. */
    static final long BASELINE_BYTES = 48L << 20;
    /** Share of the heap a scene may take. */
    static final double HEAP_SHARE = 0.8;
    /** Most plants or components: they are indexed by int. */
    static final long MAX_INDEX = Integer.MAX_VALUE - 8;

    /**
     * An image the scene names, where, its size from its header, and the bytes of its file held
     * until the build (0 when another attribute names the same file).
     */
    record Image(Values where, String attr, ImageFiles.Size size, long fileBytes) {
        long bytes() {
            return size.bytes() + fileBytes;
        }
    }

    private final SceneValidator out;
    private final long heap;

    SceneBudget(SceneValidator out, long heap) {
        this.out = out;
        this.heap = heap;
    }

    /** The most plants distribution {@code d} can place on {@code t}: its count or density, capped. */
    static long plantsAtMost(TerrainDef t, DistributionDef d) {
        return CompetitiveDistributor.plantsAtMost(t.sizeX(), t.sizeZ(), d);
    }

    /** Pose-table bytes of a species: every variant of every component type at every pose. */
    static long poseBytes(SpeciesDef s) {
        long points = 0;
        for (ComponentDef c : s.components()) {
            points += c.segments() + 1L;
        }
        return points * s.poses() * s.variation().variants() * BYTES_PER_POSE_POINT;
    }

    /**
     * Checks the scene against the heap, and its work against {@link SceneWorkBudget}'s limits (placement,
     * ground cover); reports a problem for each that is over (and returns false).
     */
    boolean check(SceneDef scene, Values root, List<Image> images) {
        boolean memory = checkMemory(scene, root, images);
        boolean work = new SceneWorkBudget(out).check(scene, root);
        return memory && work;
    }

    /** Checks the scene against the heap; reports a problem (and returns false) when it cannot fit. */
    private boolean checkMemory(SceneDef scene, Values root, List<Image> images) {
        TerrainDef t = scene.terrain();
        List<Values> distValues = root.children("distribution");
        long plants = scene.placements().size();
        long components = 0;
        long biggest = -1;
        Values biggestAt = root.child("terrain");
        String biggestAttr = "sizeX";
        for (var p : scene.placements()) {
            components += scene.speciesById(p.species()).componentsPerPlant();
        }
        for (int i = 0; i < scene.distributions().size(); i++) {
            DistributionDef d = scene.distributions().get(i);
            long n = plantsAtMost(t, d);
            long c = n * scene.speciesById(d.species()).componentsPerPlant();
            plants += n;
            components += c;
            long bytes = n * BYTES_PER_PLANT + c * BYTES_PER_COMPONENT;
            if (bytes > biggest && i < distValues.size()) {
                biggest = bytes;
                biggestAt = distValues.get(i);
                biggestAttr = d.count() >= 0 ? "count" : "density";
            }
        }
        Values where = biggestAt;
        String attr = biggestAttr;
        if (plants > MAX_INDEX || components > MAX_INDEX) {
            report(where, attr, "the scene asks for up to " + count(plants) + " plants with " + count(components)
                    + " components; at most " + count(MAX_INDEX) + " of each are possible (they are indexed by int)");
            return false;
        }
        long plantBytes = plants * BYTES_PER_PLANT + components * BYTES_PER_COMPONENT;
        long poses = 0;
        List<Values> speciesValues = root.children("species");
        for (int i = 0; i < scene.species().size(); i++) {
            long b = poseBytes(scene.species().get(i));
            poses += b;
            if (b > biggest && i < speciesValues.size()) {
                biggest = b;
                where = speciesValues.get(i);
                attr = "poses";
            }
        }
        long terrain = (long) t.resolution() * t.resolution() * BYTES_PER_TERRAIN_VERTEX
                + ((long) t.water().resolution() * t.water().resolution()
                + (long) t.nutrients().resolution() * t.nutrients().resolution()) * BYTES_PER_MAP_CELL
                + scene.distributions().size() * BYTES_PER_DISTRIBUTION;
        if (terrain > biggest) {
            biggest = terrain;
            where = root.child("terrain");
            attr = "resolution";
        }
        long imageBytes = 0;
        for (Image im : images) {
            long b = im.bytes();
            imageBytes += b;
            if (b > biggest) {
                biggest = b;
                where = im.where();
                attr = im.attr();
            }
        }
        long total = BASELINE_BYTES + plantBytes + poses + terrain + imageBytes;
        long allowed = (long) (heap * HEAP_SHARE);
        if (total <= allowed) {
            return true;
        }
        report(where, attr, "the scene needs about " + bytes(total) + " of memory to build and run (up to "
                + count(plants) + " plants with " + count(components) + " components: " + bytes(plantBytes)
                + "; pose tables " + bytes(poses) + "; terrain, maps and distribution " + bytes(terrain)
                + (images.isEmpty() ? "" : "; images " + bytes(imageBytes)) + "), more than the "
                + bytes(allowed) + " it may use (" + Math.round(HEAP_SHARE * 100) + "% of the Java heap of "
                + bytes(heap) + ", Runtime.maxMemory; set with -Xmx); this attribute asks for the most");
        return false;
    }

    private void report(Values v, String attr, String message) {
        int[] w = v.where(attr);
        out.problem(w[0], w[1], "<" + v.node.name + ">: " + message);
    }

    static String count(long n) {
        return String.format(Locale.ROOT, "%,d", n);
    }

    static String bytes(long b) {
        if (b >= 1L << 30) {
            return String.format(Locale.ROOT, "%.1f GiB", b / (double) (1L << 30));
        }
        return String.format(Locale.ROOT, "%.0f MiB", Math.max(1, b / (double) (1L << 20)));
    }
}
