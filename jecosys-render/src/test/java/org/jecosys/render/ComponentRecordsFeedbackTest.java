package org.jecosys.render;

import org.junit.jupiter.api.Tag;

/** {@link ComponentRecordsTest} on the OpenGL 3.3 path: the records captured by transform feedback. */
@Tag("lwjgl-compat")
class ComponentRecordsFeedbackTest extends ComponentRecordsTest {
    @Override
    ResolvePath path() {
        return ResolvePath.TRANSFORM_FEEDBACK;
    }
}
