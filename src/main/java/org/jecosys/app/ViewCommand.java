package org.jecosys.app;

import java.util.concurrent.Callable;
import org.jecosys.scene.SceneDef;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code jecosys view [SCENE]}: the desktop viewer (the default command). */
@Command(name = "view", mixinStandardHelpOptions = true,
        description = {"Open the viewer on a scene (default " + SceneArgs.DEFAULT_SCENE + ").",
                "With no display, renders the scene headless to PNG files instead and says where."})
final class ViewCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;
    @Mixin
    Verbose verbose;
    @Parameters(arity = "0..1", paramLabel = "SCENE", defaultValue = SceneArgs.DEFAULT_SCENE,
            description = "Scene file (default: ${DEFAULT-VALUE}).")
    String scene;

    @Override
    public Integer call() {
        SceneDef def = SceneArgs.load(SceneArgs.resolve(scene), spec.commandLine().getErr());
        if (def == null) {
            return ExitCodes.BAD_INPUT;
        }
        spec.commandLine().getOut().println("Scene '" + def.name() + "' (" + scene + ") is valid.");
        spec.commandLine().getOut().flush();
        return Unavailable.say(spec.commandLine().getErr(), "view", "the OpenGL viewer");
    }
}
