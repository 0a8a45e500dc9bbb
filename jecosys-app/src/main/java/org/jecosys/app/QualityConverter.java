package org.jecosys.app;

import org.jecosys.sim.DrawQuality;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.TypeConversionException;

/** Parses {@code low}, {@code medium} or {@code high} ({@link DrawQuality}). */
final class QualityConverter implements ITypeConverter<DrawQuality> {
    /** The option's description, shared by the commands that take it. */
    static final String DESCRIPTION = "Far-plant thinning preset: low (from 4 m down to 15%% of the plants beyond "
            + "16 m; for llvmpipe), medium (8 m, 35%% beyond 30 m) or high (none). Default: the scene's <field "
            + "thinStart thinEnd thinMinFraction>; the viewer picks low on a software renderer (llvmpipe).";

    @Override
    public DrawQuality convert(String value) {
        try {
            return DrawQuality.parse(value);
        } catch (IllegalArgumentException e) {
            throw new TypeConversionException(e.getMessage());
        }
    }
}
