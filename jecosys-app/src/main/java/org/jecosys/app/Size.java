package org.jecosys.app;

import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.TypeConversionException;

/** An image size {@code WxH} in pixels, each side in [16, 8192]. */
record Size(int width, int height) {
    static final int MIN = 16;
    static final int MAX = 8192;

    /** Parses {@code WxH}. */
    static final class Converter implements ITypeConverter<Size> {
        @Override
        public Size convert(String value) {
            String[] parts = value.toLowerCase(java.util.Locale.ROOT).split("x", -1);
            if (parts.length != 2) {
                throw new TypeConversionException("'" + value + "' is not WIDTHxHEIGHT, e.g. 1280x720");
            }
            try {
                int w = Integer.parseInt(parts[0]);
                int h = Integer.parseInt(parts[1]);
                if (w < MIN || w > MAX || h < MIN || h > MAX) {
                    throw new TypeConversionException("'" + value + "': each side must be in [" + MIN + ", " + MAX
                            + "] pixels");
                }
                return new Size(w, h);
            } catch (NumberFormatException e) {
                throw new TypeConversionException("'" + value + "' is not WIDTHxHEIGHT, e.g. 1280x720");
            }
        }
    }
}
