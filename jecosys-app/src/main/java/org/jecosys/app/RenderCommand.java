package org.jecosys.app;

import java.nio.file.Path;
import java.util.concurrent.Callable;
import org.jecosys.scene.Scene;
import org.jecosys.scene.SceneDef;
import org.jecosys.sim.DrawQuality;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code jecosys render SCENE --frames N --out DIR}: headless rendering to PNG files. */
@Command(name = "render", mixinStandardHelpOptions = true,
        description = {"Render frames headless (no X server: GLFW's null platform with EGL, e.g. Mesa llvmpipe) "
                + "and write PNG files."})
final class RenderCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;
    @Mixin
    Verbose verbose;
    @Mixin
    SceneImages images;
    @Parameters(index = "0", paramLabel = "SCENE", description = "Scene file.")
    String scene;
    @Option(names = "--frames", paramLabel = "N", required = true, description = "Frames to render, 1 to 100000.")
    int frames;
    @Option(names = "--out", paramLabel = "DIR", required = true, description = "Folder for the PNG files "
            + "(created if missing; files of the same names are replaced, never through a link).")
    Path out;
    @Option(names = "--size", paramLabel = "WxH", converter = Size.Converter.class,
            description = "Image size in pixels, each side 16 to 8192 (default: the scene's render size).")
    Size size;
    @Option(names = "--maps", description = "Also write the water, nutrient and species maps (water.png, "
            + "nutrients.png, species.png) to DIR: why plants grow where they do.")
    boolean maps;
    @Option(names = "--gif", paramLabel = "FILE", description = "Also assemble the frames into a looping animated "
            + "GIF (30 frames per second).")
    Path gif;
    @Option(names = "--quality", paramLabel = "LEVEL", converter = QualityConverter.class,
            description = QualityConverter.DESCRIPTION)
    DrawQuality quality;

    @Override
    public Integer call() {
        if (frames < 1 || frames > 100_000) {
            throw new ParameterException(spec.commandLine(), "--frames must be in [1, 100000], got " + frames);
        }
        OutputPlan plan = new OutputPlan(spec.commandLine())
                .filesIn("--out", out, HeadlessRender.outputNames(frames, maps))
                .file("--gif", gif);
        Path file = SceneArgs.resolve(scene);
        plan.input(file, "the scene file this run reads").check();
        Scene loaded = SceneArgs.load(file, images.of(file, plan), spec.commandLine().getErr());
        if (loaded == null) {
            return ExitCodes.BAD_INPUT;
        }
        SceneDef def = loaded.def();
        if (maps && def.isOpenWorld()) {
            throw new picocli.CommandLine.ParameterException(spec.commandLine(), "--maps needs a scene of one square: "
                    + file + " is an open world (<world>), whose plants exist only around the camera");
        }
        plan.checkImages();
        plan.createFolders();
        int w = size == null ? def.render().width() : size.width();
        int h = size == null ? def.render().height() : size.height();
        try {
            HeadlessRender.run(loaded, quality, frames, out, w, h, maps, frames == 1, spec.commandLine().getOut(),
                    new ConsoleProgress(spec.commandLine().getErr(), ConsoleProgress.stderrIsTerminal()));
            if (gif != null) {
                java.util.List<Path> pngs = new java.util.ArrayList<>();
                for (int i = 1; i <= frames; i++) {
                    pngs.add(out.resolve(HeadlessRender.frameName(i)));
                }
                GifWriter.write(pngs, gif, 3);
                spec.commandLine().getOut().println("Wrote " + gif.toAbsolutePath());
                spec.commandLine().getOut().flush();
            }
        } catch (java.io.IOException e) {
            spec.commandLine().getErr().println("jecosys render: " + e.getMessage());
            spec.commandLine().getErr().flush();
            return ExitCodes.FAILURE;
        }
        return ExitCodes.OK;
    }
}
