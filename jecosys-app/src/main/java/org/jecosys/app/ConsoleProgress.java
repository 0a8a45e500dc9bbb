package org.jecosys.app;

import java.io.PrintWriter;
import org.jecosys.math.Progress;

/**
 * A console progress bar for long generation steps: nothing for a step that ends within a second;
 * after that one line per step, redrawn in place ({@code \r}) on a terminal, or a single final line
 * when the output is not a terminal. Called on the generating thread.
 */
final class ConsoleProgress implements Progress {
    private static final long DELAY_NANOS = 1_000_000_000L;
    private final PrintWriter err;
    private final boolean tty;
    private String step;
    private long started;
    private boolean shown;
    private int lastPercent = -1;

    ConsoleProgress(PrintWriter err, boolean tty) {
        this.err = err;
        this.tty = tty;
    }

    /** Whether standard error is probably a terminal. */
    static boolean stderrIsTerminal() {
        return System.console() != null && System.getenv("TERM") != null;
    }

    @Override
    public void report(String name, long done, long total) {
        long now = System.nanoTime();
        if (!name.equals(step)) {
            step = name;
            started = now;
            shown = false;
            lastPercent = -1;
        }
        boolean finished = done >= total;
        if (now - started < DELAY_NANOS && !shown) {
            return;
        }
        int percent = (int) (100 * done / Math.max(1, total));
        if (tty) {
            if (percent != lastPercent) {
                int w = percent / 5;
                err.print("\r" + name + " [" + "#".repeat(w) + " ".repeat(20 - w) + "] " + percent + "%");
                if (finished) {
                    err.println();
                }
                err.flush();
            }
        } else if (finished) {
            err.println(name + ": done in " + String.format("%.1f s", (now - started) / 1e9));
            err.flush();
        }
        shown = true;
        lastPercent = percent;
    }
}
