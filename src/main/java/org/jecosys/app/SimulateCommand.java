package org.jecosys.app;

import java.nio.file.Path;
import java.util.concurrent.Callable;
import org.jecosys.anim.AnimationMode;
import org.jecosys.scene.SceneDef;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code jecosys simulate SCENE}: runs the simulation headless and reports speed and a state hash. */
@Command(name = "simulate", mixinStandardHelpOptions = true,
        description = {"Run the simulation headless (no rendering) and print components, plants, steps, median ms "
                + "per step, component updates per second, allocated bytes per step and a state hash."})
final class SimulateCommand implements Callable<Integer> {
    /** on or off. */
    enum OnOff { on, off }

    @Spec
    CommandSpec spec;
    @Mixin
    Verbose verbose;
    @Parameters(index = "0", paramLabel = "SCENE", description = "Scene file.")
    String scene;
    @Option(names = "--steps", paramLabel = "N", defaultValue = "600", description = "Fixed steps to run, "
            + "1 to 10000000 (default ${DEFAULT-VALUE}).")
    int steps;
    @Option(names = "--dt", paramLabel = "S", description = "Step length in seconds, 1e-5 to 1 (default: the "
            + "scene's fixedStep).")
    Double dt;
    @Option(names = "--threads", paramLabel = "T", description = "Animation workers, 1 to 256 (default: the "
            + "scene's setting, else the available processors).")
    Integer threads;
    @Option(names = "--mode", paramLabel = "MODE", converter = ModeConverter.class, description = "static, random or constraint (default: the "
            + "scene's).")
    AnimationMode mode;
    @Option(names = "--field", paramLabel = "on|off", description = "Force field on or off (default: the scene's).")
    OnOff field;
    @Option(names = "--json", paramLabel = "FILE", description = "Also write the results and field counters as JSON.")
    Path json;
    @Option(names = "--dump", paramLabel = "FILE.csv", description = "Write the final state, one row per component.")
    Path dump;

    @Override
    public Integer call() {
        if (steps < 1 || steps > 10_000_000) {
            throw new ParameterException(spec.commandLine(), "--steps must be in [1, 10000000], got " + steps);
        }
        if (dt != null && !(dt >= 1e-5 && dt <= 1)) {
            throw new ParameterException(spec.commandLine(), "--dt must be in [1e-5, 1] seconds, got " + dt);
        }
        if (threads != null && (threads < 1 || threads > 256)) {
            throw new ParameterException(spec.commandLine(), "--threads must be in [1, 256], got " + threads);
        }
        SceneDef def = SceneArgs.load(SceneArgs.resolve(scene), spec.commandLine().getErr());
        if (def == null) {
            return ExitCodes.BAD_INPUT;
        }
        return Unavailable.say(spec.commandLine().getErr(), "simulate", "the animation engine");
    }
}
