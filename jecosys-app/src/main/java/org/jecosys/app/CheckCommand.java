package org.jecosys.app;

import java.io.PrintWriter;
import java.util.List;
import java.util.concurrent.Callable;
import java.nio.file.Path;
import org.jecosys.scene.Scene;
import org.jecosys.scene.SceneDef;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code jecosys check SCENE...}: validates scene files; exit 0 when all are valid, 2 otherwise. */
@Command(name = "check", mixinStandardHelpOptions = true,
        description = {"Validate scene files. Prints FILE: ok for each valid file and FILE:LINE:COL: message for "
                + "each problem.", "Exit 0 when all are valid, 2 otherwise."})
final class CheckCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;
    @Mixin
    Verbose verbose;
    @Mixin
    SceneImages images;
    @Parameters(arity = "1..*", paramLabel = "SCENE", description = "Scene files to validate.")
    List<String> scenes;

    @Override
    public Integer call() {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        int bad = 0;
        for (String s : scenes) {
            Path file = SceneArgs.resolve(s);
            Scene loaded = SceneArgs.load(file, images.of(file), err);
            if (loaded == null) {
                bad++;
                continue;
            }
            SceneDef scene = loaded.def();
            long plants = scene.placements().size(); // 256 distributions of 10,000,000 overflow an int
            for (var d : scene.distributions()) {
                plants += Math.max(d.count(), 0);
            }
            String kind = scene.isOpenWorld() ? "an open world of " + metres(scene.world().tileSize()) + " m tiles within "
                    + metres(scene.world().radius()) + " m, " : "";
            out.println(s + ": ok (" + kind + scene.species().size() + " species, " + scene.distributions().size()
                    + " distributions, " + plants + " plants by count, " + scene.flows().size() + " flows)");
        }
        out.flush();
        if (bad > 0) {
            err.println(bad + " of " + scenes.size() + " scene files are invalid");
            err.flush();
            return ExitCodes.BAD_INPUT;
        }
        return ExitCodes.OK;
    }

    /** A length as written in a scene: no trailing ".0". */
    private static String metres(double v) {
        return v == Math.rint(v) && Math.abs(v) < 1e15 ? Long.toString((long) v) : Double.toString(v);
    }
}
