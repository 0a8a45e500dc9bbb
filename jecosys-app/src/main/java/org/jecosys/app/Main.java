package org.jecosys.app;

import java.io.PrintStream;
import java.io.PrintWriter;
import java.util.Arrays;
import picocli.CommandLine;

/**
 * The {@code jecosys} command line. Exit codes: 0 success, 1 a runtime failure, 2 bad input
 * (flags or scene files). Errors print one clear
 * message; a stack trace only with {@code --verbose}.
 */
public final class Main {
    private Main() {
    }

    /** Runs the CLI and exits the JVM with its exit code. */
    public static void main(String[] args) {
        System.exit(run(args, System.out, System.err));
    }

    /**
     * Runs the CLI without exiting, for tests and embedding.
     *
     * @return the exit code
     */
    public static int run(String[] args, PrintStream out, PrintStream err) {
        CommandLine cl = commandLine(out, err);
        if (args.length > 0 && !args[0].startsWith("-") && !cl.getSubcommands().containsKey(args[0])
                && !looksLikeAScene(args[0])) {
            cl.getErr().println("jecosys: unknown command '" + args[0] + "'; the commands are: "
                    + String.join(", ", cl.getSubcommands().keySet())
                    + " (a scene file, an existing file or a name ending in .xml, opens the viewer)");
            cl.getErr().println("Run 'jecosys --help' for usage.");
            cl.getErr().flush();
            return ExitCodes.BAD_INPUT;
        }
        return cl.execute(withDefaultCommand(cl, args));
    }

    static CommandLine commandLine(PrintStream out, PrintStream err) {
        CommandLine cl = new CommandLine(new JecosysCommand());
        cl.setCaseInsensitiveEnumValuesAllowed(true);
        cl.getSubcommands().get("view").getCommandSpec().usageMessage().footer(ViewCommand.controlsHelp());
        cl.setOut(new PrintWriter(out, true));
        cl.setErr(new PrintWriter(err, true));
        cl.setExecutionExceptionHandler((ex, line, parsed) -> {
            boolean verbose = Arrays.asList(parsed.originalArgs()).contains("--verbose");
            line.getErr().println("jecosys: error: " + (ex.getMessage() == null ? ex.toString() : ex.getMessage()));
            if (verbose) {
                ex.printStackTrace(line.getErr());
            } else {
                line.getErr().println("(run with --verbose for details)");
            }
            line.getErr().flush();
            return ExitCodes.FAILURE;
        });
        return cl;
    }

    /**
     * {@code view} is the default command: no arguments, or a first argument that is a scene file (an
     * existing file, or a name ending in {@code .xml}). Any other first word is not taken as a scene:
     * picocli reports it as an unknown command and lists the commands.
     */
    static String[] withDefaultCommand(CommandLine cl, String[] args) {
        if (args.length == 0) {
            return new String[] {"view"};
        }
        String first = args[0];
        if (!first.startsWith("-") && !cl.getSubcommands().containsKey(first) && looksLikeAScene(first)) {
            String[] out = new String[args.length + 1];
            out[0] = "view";
            System.arraycopy(args, 0, out, 1, args.length);
            return out;
        }
        return args;
    }

    private static boolean looksLikeAScene(String arg) {
        if (arg.toLowerCase(java.util.Locale.ROOT).endsWith(".xml")) {
            return true;
        }
        try {
            return java.nio.file.Files.isRegularFile(SceneArgs.resolve(arg));
        } catch (java.nio.file.InvalidPathException e) {
            return false;
        }
    }
}
