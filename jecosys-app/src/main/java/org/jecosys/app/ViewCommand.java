package org.jecosys.app;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import org.jecosys.render.GlContext;
import org.jecosys.scene.Scene;
import org.jecosys.scene.SceneDef;
import org.jecosys.sim.DrawQuality;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code jecosys view [SCENE]}: the desktop viewer (the default command). */
@Command(name = "view", mixinStandardHelpOptions = true,
        description = {"Open the viewer on a scene (default " + SceneArgs.DEFAULT_SCENE + ").",
                "With no display, renders the scene headless to PNG files instead and says where."})
final class ViewCommand implements Callable<Integer> {
    /** System property: folder of the no-display fallback's PNG files (default {@code jecosys-frames}). */
    static final String FALLBACK_OUT = "jecosys.fallback.out";
    /** System property: frames the no-display fallback renders (default 30, one second). */
    static final String FALLBACK_FRAMES = "jecosys.fallback.frames";

    @Spec
    CommandSpec spec;

    /** The usage footer: the viewer's controls ({@link ViewerControls#CONTROLS}), one per line. */
    static String[] controlsHelp() {
        int n = ViewerControls.CONTROLS.length;
        int m = OpenWorldControls.CONTROLS.length;
        String[] out = new String[n + m + 4];
        out[0] = "";
        out[1] = "Controls in the viewer:";
        for (int i = 0; i < n; i++) {
            out[i + 2] = "  " + ViewerControls.CONTROLS[i];
        }
        out[n + 2] = "";
        out[n + 3] = "Controls over an open world (a scene with <world>):";
        for (int i = 0; i < m; i++) {
            out[n + 4 + i] = "  " + OpenWorldControls.CONTROLS[i];
        }
        return out;
    }
    @Mixin
    Verbose verbose;
    @Mixin
    SceneImages images;
    @Parameters(arity = "0..1", paramLabel = "SCENE", defaultValue = SceneArgs.DEFAULT_SCENE,
            description = "Scene file (default: ${DEFAULT-VALUE}).")
    String scene;
    @Option(names = "--quality", paramLabel = "LEVEL", converter = QualityConverter.class,
            description = QualityConverter.DESCRIPTION)
    DrawQuality quality;

    @Override
    public Integer call() {
        Path file = SceneArgs.resolve(scene);
        boolean headless = !GlContext.hasDisplay();
        Path out = Path.of(System.getProperty(FALLBACK_OUT, "jecosys-frames"));
        int frames = Integer.getInteger(FALLBACK_FRAMES, 30);
        OutputPlan plan = new OutputPlan(spec.commandLine());
        if (headless) {
            plan.filesIn("-D" + FALLBACK_OUT, out, HeadlessRender.outputNames(frames, true))
                    .input(file, "the scene file this run reads").check();
        }
        Scene loaded = SceneArgs.load(file, images.of(file, plan), spec.commandLine().getErr());
        if (loaded == null) {
            return ExitCodes.BAD_INPUT;
        }
        SceneDef def = loaded.def();
        spec.commandLine().getOut().println("Scene '" + def.name() + "' (" + scene + ") is valid.");
        spec.commandLine().getOut().flush();
        try {
            if (headless) {
                plan.checkImages();
                plan.createFolders();
                spec.commandLine().getOut().println("No display (DISPLAY and WAYLAND_DISPLAY are unset): rendering "
                        + frames + " frames headless to " + out.toAbsolutePath() + " instead of opening the viewer.");
                spec.commandLine().getOut().flush();
                if (def.isOpenWorld()) {
                    PrintWriter log = spec.commandLine().getOut();
                    OpenWorldFrames.run(loaded, quality, frames, out, def.render().width(), def.render().height(),
                            false, log);
                    return ExitCodes.OK;
                }
                HeadlessRender.run(loaded, quality, frames, out, def.render().width(), def.render().height(), true,
                        false, spec.commandLine().getOut(),
                        new ConsoleProgress(spec.commandLine().getErr(), ConsoleProgress.stderrIsTerminal()));
                return ExitCodes.OK;
            }
            if (def.isOpenWorld()) {
                new OpenWorldViewer(loaded, quality).run();
                return ExitCodes.OK;
            }
            new Viewer(loaded, file, quality).run(new ConsoleProgress(spec.commandLine().getErr(),
                    ConsoleProgress.stderrIsTerminal()));
            return ExitCodes.OK;
        } catch (IOException e) {
            spec.commandLine().getErr().println("jecosys view: " + e.getMessage());
            spec.commandLine().getErr().flush();
            return ExitCodes.FAILURE;
        }
    }
}
