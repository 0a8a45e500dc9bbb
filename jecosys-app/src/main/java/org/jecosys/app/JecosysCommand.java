package org.jecosys.app;

import java.io.IOException;
import java.io.InputStream;
import java.util.Properties;
import picocli.CommandLine.Command;

/** The top-level {@code jecosys} command; {@code view} runs when no command is named. */
@Command(name = "jecosys", mixinStandardHelpOptions = true, versionProvider = JecosysCommand.Version.class,
        description = {"JEcoSys: interactive meadows bending in wind and under agents, in real time.",
                "A port of Endo, Morimoto, Fabris, CGI 2005. With no command, runs 'view' on scenes/meadow.xml."},
        subcommands = {ViewCommand.class, CheckCommand.class, SimulateCommand.class, RenderCommand.class,
                BenchCommand.class, GalleryCommand.class},
        footer = {"", "Exit codes: 0 ok, 1 runtime failure, 2 bad input."})
final class JecosysCommand implements Runnable {
    @Override
    public void run() {
        // picocli prints usage for a bare 'jecosys' only if view were not the default; nothing to do here
    }

    /** Reads the version Maven wrote into version.properties. */
    static final class Version implements picocli.CommandLine.IVersionProvider {
        @Override
        public String[] getVersion() throws IOException {
            Properties p = new Properties();
            try (InputStream in = JecosysCommand.class.getResourceAsStream("version.properties")) {
                if (in != null) {
                    p.load(in);
                }
            }
            return new String[] {"jecosys " + p.getProperty("version", "unknown") + " (Java "
                    + System.getProperty("java.version") + ")"};
        }
    }
}
