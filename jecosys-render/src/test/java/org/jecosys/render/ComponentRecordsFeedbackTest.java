package org.jecosys.render;

import org.jecosys.render.plant.ResolvePath;

/** {@link ComponentRecordsTest} on the OpenGL 3.3 path: the records captured by transform feedback. */
class ComponentRecordsFeedbackTest extends ComponentRecordsTest {
    @Override
    ResolvePath path() {
        return ResolvePath.TRANSFORM_FEEDBACK;
    }
}
