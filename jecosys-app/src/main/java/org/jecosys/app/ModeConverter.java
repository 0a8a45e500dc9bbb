package org.jecosys.app;

import org.jecosys.anim.AnimationMode;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.TypeConversionException;

/** Parses {@code static}, {@code random} or {@code constraint} (paper Table 7's S1, S2, S3). */
final class ModeConverter implements ITypeConverter<AnimationMode> {
    @Override
    public AnimationMode convert(String value) {
        for (AnimationMode m : AnimationMode.values()) {
            if (m.xmlName().equalsIgnoreCase(value)) {
                return m;
            }
        }
        throw new TypeConversionException("'" + value + "' is not a mode; expected static, random or constraint");
    }
}
