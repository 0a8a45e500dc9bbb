package org.jecosys.app;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;

/** {@code jecosys gallery --out DIR [--size WxH]}: the fixed set of views of docs/gallery, headless. */
@Command(name = "gallery", mixinStandardHelpOptions = true,
        description = {"Render the gallery headless: a fixed set of views of the shipped scenes (meadow default, "
                + "close-up at 1 m, from above, back-lit; the rose at its three levels of detail; c1, c2, c3) "
                + "to PNG files with fixed names. Deterministic: fixed scene time and seeds."})
final class GalleryCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;
    @Mixin
    Verbose verbose;
    @Option(names = "--out", paramLabel = "DIR", required = true, description = "Folder for the PNG files "
            + "(created if missing; files of the same names are replaced, never through a link).")
    Path out;
    @Option(names = "--size", paramLabel = "WxH", converter = Size.Converter.class,
            description = "Image size in pixels, each side 16 to 8192 (default: 960x540).")
    Size size;
    @Option(names = "--scenes", paramLabel = "DIR", description = "Folder holding meadow.xml, rose.xml, c1.xml, "
            + "c2.xml and c3.xml (default: scenes, in the working folder or the installation).")
    String scenes = "scenes";

    @Override
    public Integer call() {
        Path dir = SceneArgs.resolve(scenes);
        OutputPlan plan = new OutputPlan(spec.commandLine()).filesIn("--out", out, Gallery.FILES);
        for (String name : Gallery.SCENES) {
            if (!Files.isRegularFile(dir.resolve(name))) {
                throw new ParameterException(spec.commandLine(), "--scenes " + scenes + ": no " + name + " in "
                        + dir.toAbsolutePath());
            }
            plan.input(dir.resolve(name), "a scene file the gallery reads");
        }
        plan.check();
        int w = size == null ? Gallery.WIDTH : size.width();
        int h = size == null ? Gallery.HEIGHT : size.height();
        try {
            Gallery.render(dir, out, w, h, spec.commandLine().getOut(), spec.commandLine().getErr());
        } catch (Gallery.BadScene e) {
            return ExitCodes.BAD_INPUT;
        } catch (IOException e) {
            spec.commandLine().getErr().println("jecosys gallery: " + e.getMessage());
            spec.commandLine().getErr().flush();
            return ExitCodes.FAILURE;
        }
        return ExitCodes.OK;
    }
}
