package org.jecosys.app;

import java.io.PrintWriter;

/** Says clearly that a command's part is not in this build yet (exit code 3), after its input was checked. */
final class Unavailable {
    private Unavailable() {
    }

    static int say(PrintWriter err, String command, String what) {
        err.println("jecosys " + command + ": the input is valid, but " + what
                + " is not part of this build yet; see README.md, 'Status'.");
        err.flush();
        return ExitCodes.UNAVAILABLE;
    }
}
