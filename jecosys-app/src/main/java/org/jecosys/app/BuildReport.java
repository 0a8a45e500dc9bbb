package org.jecosys.app;

import java.io.PrintWriter;
import org.jecosys.sim.World;

/** Prints what building a scene took and the distribution's warnings (e.g. a species that fits nowhere). */
final class BuildReport {
    private BuildReport() {
    }

    static void print(World world, PrintWriter out, PrintWriter err) {
        out.println("Built: " + world.buildSummary());
        out.flush();
        for (String w : world.layout().warnings()) {
            err.println("warning: " + w);
        }
        err.flush();
    }
}
