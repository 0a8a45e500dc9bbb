package org.jecosys.scene;

import java.util.List;
import java.util.Locale;
import org.jecosys.terrain.DistributionDef;
import org.jecosys.terrain.PlacementWork;
import org.jecosys.terrain.TerrainDef;

/**
 * "Accepted means runnable", in time: the scene check's bounds on the work a valid scene asks for,
 * beside {@link SceneBudget}'s bound on its memory. Two costs are bounded, each with a stated limit
 * and refused with a located problem that names it:
 * <ul>
 * <li><b>placement</b>: {@link PlacementWork}'s upper bound of the competitive distribution's work
 * (candidates, footprint search, resource maps, suitability masks) must stay within
 * {@link #MAX_PLACEMENT_WORK}; refused at the distribution with the largest share, at its
 * {@code footprint} when its search dominates (a footprint far larger than its neighbours'), else at
 * its {@code count} or {@code density};</li>
 * <li><b>ground cover</b>: {@link RenderDef.GroundCover#bladesPerViewAtMost} must stay within
 * {@link RenderDef.GroundCover#MAX_BLADES_PER_VIEW}; refused at the {@code <groundCover>}'s
 * {@code density} or {@code reach}, whichever is further above its default.</li>
 * </ul>
 * One instance per load; not thread-safe; allocates its messages.
 */
final class SceneWorkBudget {
    /**
     * Most placement work a scene may ask for, in {@link PlacementWork} units (about one bucket or disc
     * the footprint search looks at). Where the bound is nearly reached (a distribution whose water is
     * never met, averaging its footprint over a fine map for every candidate) a unit took 0.8 ns on the
     * machine it was measured on, so a scene at the limit places in about 30 s of one core in its worst
     * case, and far sooner in the usual one. The shipped scenes bound at 1.1e9 (meadow, prairie) at most.
     */
    static final double MAX_PLACEMENT_WORK = 3e10;
    /**
     * Units one candidate may cost before the footprint is blamed rather than the count: a plain
     * candidate costs about 100 (drawing it, a few buckets and discs); one of a footprint far larger
     * than its neighbours' searches thousands, and one whose footprint covers much of a resource map
     * averages thousands of cells.
     */
    static final double FOOTPRINT_BLAME_UNITS = 2000;

    private final SceneValidator out;

    SceneWorkBudget(SceneValidator out) {
        this.out = out;
    }

    /** Checks both costs; reports a problem for each that is over its limit. @return whether both fit */
    boolean check(SceneDef scene, Values root) {
        boolean placement = checkPlacement(scene, root);
        boolean cover = checkCover(scene, root);
        return placement && cover;
    }

    private boolean checkPlacement(SceneDef scene, Values root) {
        TerrainDef t = scene.terrain();
        PlacementWork w = PlacementWork.estimate(t, scene.distributions(), scene.placements());
        if (w.total() <= MAX_PLACEMENT_WORK) {
            return true;
        }
        int d = w.largest();
        List<Values> dv = root.children("distribution");
        if (d < 0 || d >= dv.size()) { // hand placements alone: they cannot be that costly, but say so
            report(root.child("terrain"), "sizeX", "placing the scene's plants takes up to about "
                    + units(w.total()) + ", more than the " + limit() + "; the hand placements ask for "
                    + units(w.placements()));
            return false;
        }
        DistributionDef def = scene.distributions().get(d);
        boolean footprint = w.costPerCandidate(d) > FOOTPRINT_BLAME_UNITS;
        String attr = footprint ? "footprint" : (def.count() >= 0 ? "count" : "density");
        report(dv.get(d), attr, "placing the scene's plants takes up to about " + units(w.total())
                + ", more than the " + limit() + "; this distribution (species '" + def.species() + "', footprint "
                + num(def.footprint()) + " m) asks for the most, " + units(w.work(d)) + ": up to "
                + SceneBudget.count(w.candidates(d)) + " candidates, each costing up to "
                + SceneBudget.count((long) Math.min(Long.MAX_VALUE, w.costPerCandidate(d))) + " units (its footprint search"
                + " looks at up to " + SceneBudget.count((long) Math.min(Long.MAX_VALUE, w.searchPerCandidate(d)))
                + " buckets and discs of other plants; its footprint covers up to "
                + SceneBudget.count((long) w.mapCellsPerFootprint(d)) + " water and nutrient map cells)"
                + (footprint ? "; a footprint this large among many smaller plants, or over this many map cells, makes"
                + " every candidate costly: use a smaller footprint, coarser maps, or fewer small neighbours"
                : "; use fewer plants or a smaller terrain"));
        return false;
    }

    private boolean checkCover(SceneDef scene, Values root) {
        RenderDef.GroundCover gc = scene.render().groundCover();
        TerrainDef t = scene.terrain();
        long blades = gc.bladesPerViewAtMost(t.sizeX(), t.sizeZ());
        if (blades <= RenderDef.GroundCover.MAX_BLADES_PER_VIEW) {
            return true;
        }
        Values render = root.child("render");
        Values gv = render == null ? null : render.child("groundCover");
        if (gv == null) { // a cover comes only from the element; keep the check total all the same
            gv = root;
        }
        RenderDef.GroundCover def = RenderDef.GroundCover.NONE;
        double densityRatio = gc.density() / def.density();
        double reachRatio = (gc.reach() + 1) * (gc.reach() + 1) / ((def.reach() + 1) * (def.reach() + 1));
        String attr = densityRatio >= reachRatio ? "density" : "reach";
        report(gv, attr, "the ground cover draws up to " + SceneBudget.count(blades) + " blades per view in a frame ("
                + SceneBudget.count(gc.bladesPerTile()) + " per square metre on each of up to "
                + SceneBudget.count(blades / Math.max(1, gc.bladesPerTile())) + " one-metre tiles within its reach of "
                + num(gc.reach()) + " m), more than the limit of " + SceneBudget.count(RenderDef.GroundCover.MAX_BLADES_PER_VIEW)
                + " blades per view (RenderDef.GroundCover.MAX_BLADES_PER_VIEW; at density 20000 and reach 50 a frame"
                + " takes about 28 s on a software renderer): lower the density or the reach");
        return false;
    }

    private void report(Values v, String attr, String message) {
        int[] w = v.where(attr);
        out.problem(w[0], w[1], "<" + v.node.name + ">: " + message);
    }

    private static String limit() {
        return "placement budget of " + units(MAX_PLACEMENT_WORK) + " (SceneWorkBudget.MAX_PLACEMENT_WORK, about"
                + " 30 s of one core in the worst case)";
    }

    static String units(double u) {
        return SceneBudget.count((long) Math.min(Long.MAX_VALUE, u)) + " units of work";
    }

    private static String num(double v) {
        String s = String.format(Locale.ROOT, "%.4g", v);
        return s.contains(".") && !s.contains("e") ? s.replaceAll("0+$", "").replaceAll("\\.$", "") : s;
    }
}
