package org.jecosys.sim;

import java.util.Locale;
import org.jecosys.field.ForceFieldDef;
import org.jecosys.math.Require;

/**
 * Presets of the draw decision's distance thinning ({@link Simulation#setThinning}), for the
 * command line's {@code --quality} and for games: how many far plants a slow GPU (a software
 * rasteriser such as llvmpipe) is asked to draw. The animation is the same at every quality.
 * Immutable; any thread.
 */
public enum DrawQuality {
    /** Thinning from 4 m, down to 15% of the plants from 16 m: for llvmpipe (software rendering). */
    LOW(4, 16, 0.15),
    /** Thinning from 8 m, down to 35% of the plants from 30 m: for weak GPUs. */
    MEDIUM(8, 30, 0.35),
    /** No thinning: every plant the field finds visible is drawn (GPUs). */
    HIGH(ForceFieldDef.DEFAULT_THIN_START, ForceFieldDef.DEFAULT_THIN_END, 1);

    private final double start;
    private final double end;
    private final double minFraction;

    DrawQuality(double start, double end, double minFraction) {
        this.start = start;
        this.end = end;
        this.minFraction = minFraction;
    }

    /** {@return where thinning starts, metres} */
    public double thinStart() {
        return start;
    }

    /** {@return where the kept share reaches {@link #thinMinFraction()}, metres} */
    public double thinEnd() {
        return end;
    }

    /** {@return the share of plants drawn at and beyond {@link #thinEnd()}; 1 for none} */
    public double thinMinFraction() {
        return minFraction;
    }

    /** {@return the lower-case name used on the command line: low, medium or high} */
    public String xmlName() {
        return name().toLowerCase(Locale.ROOT);
    }

    /**
     * Queues this preset's thinning on {@code sim} ({@link Simulation#setThinning}). Any thread;
     * allocates a command.
     *
     * @param sim the simulation
     */
    public void applyTo(Simulation sim) {
        Require.nonNull("sim", sim);
        sim.setThinning(start, end, minFraction);
    }

    /**
     * The preset with this name, ignoring case.
     *
     * @param name low, medium or high
     * @return the preset
     * @throws IllegalArgumentException when the name is none of them
     */
    public static DrawQuality parse(String name) {
        Require.nonNull("name", name);
        for (DrawQuality q : values()) {
            if (q.xmlName().equalsIgnoreCase(name.strip())) {
                return q;
            }
        }
        throw new IllegalArgumentException("'" + name + "' is not a quality; expected low, medium or high");
    }
}
