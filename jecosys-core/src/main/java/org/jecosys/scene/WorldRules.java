package org.jecosys.scene;

import java.util.List;
import java.util.function.BooleanSupplier;
import org.jecosys.plant.SpeciesDef;
import org.jecosys.terrain.DistributionDef;
import org.jecosys.world.WorldDef;

/** The checks of a scene with a {@code <world>} ({@link SceneBinder}): what an open world cannot stream. */
final class WorldRules {
    /** Reports a problem at an element's attribute. */
    interface Problems {
        void at(Values v, String attr, String message);
    }

    private WorldRules() {
    }

    /**
     * What an open world cannot stream: a distribution by count (tiles grow plants by density), plants
     * placed by hand, water or nutrient limits (the hills have no resource maps), and tiles too small for
     * the footprints and tufts (the placer's own check).
     */
    static void check(Values root, Values w, WorldDef world, List<SpeciesDef> species,
                      List<DistributionDef> distributions, Problems problems, BooleanSupplier clean) {
        for (Values d : root.children("distribution")) {
            if (d.integer("count") != -1) {
                problems.at(d, "count", "attribute 'count' of <distribution>: an open world (<world>) grows plants by "
                        + "density; use count=\"-1\" and 'density' (plants per square metre)");
            }
            for (String limit : new String[] {"minWater", "maxWater", "minNutrients", "maxNutrients"}) {
                double v = d.num(limit);
                if (limit.startsWith("min") ? v > 0 : v < 1) {
                    problems.at(d, limit, "attribute '" + limit + "' of <distribution>: an open world (<world>) has no "
                            + "water or nutrient maps; leave out the limits");
                }
            }
        }
        for (Values p : root.children("plant")) {
            problems.at(p, "species", "<plant>: an open world (<world>) places no plants by hand; its tiles grow the "
                    + "<distribution>s");
        }
        if (!clean.getAsBoolean() || distributions.isEmpty()) {
            if (clean.getAsBoolean()) {
                problems.at(w, "tileSize", "<world>: an open world needs at least one <distribution> to grow its tiles");
            }
            return;
        }
        int[] speciesOf = new int[distributions.size()];
        for (int k = 0; k < speciesOf.length; k++) {
            for (int s = 0; s < species.size(); s++) {
                if (species.get(s).id().equals(distributions.get(k).species())) {
                    speciesOf[k] = s;
                }
            }
        }
        try {
            world.placer(root.longValue("seed"), distributions, speciesOf);
        } catch (IllegalArgumentException e) {
            problems.at(w, "tileSize", "<world>: " + e.getMessage());
        }
    }
}
