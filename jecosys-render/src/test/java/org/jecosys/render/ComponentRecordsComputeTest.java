package org.jecosys.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.FloatBuffer;
import org.junit.jupiter.api.Test;
import org.lwjgl.system.MemoryUtil;
import org.jecosys.render.plant.PlantRenderer;
import org.junit.jupiter.api.Tag;

/**
 * {@link ComponentRecordsTest} on the OpenGL 4.3 path (skipped on an older context): the records
 * stored by the compute shader; and they are the transform-feedback path's records, value for value.
 */
@Tag("lwjgl-compat")
class ComponentRecordsComputeTest extends ComponentRecordsTest {
    @Override
    ResolvePath path() {
        return ResolvePath.COMPUTE;
    }

    @Test
    void theComputePathStoresTheRecordsTheTransformFeedbackPathCaptures() {
        assertEquals(ResolvePath.COMPUTE, ResolvePath.best(gl.capabilities()), "the best path of a 4.3 context");
        assertEquals(ResolvePath.COMPUTE, ResolvePath.best(gl.capabilities(), "NVIDIA H100 80GB HBM3/PCIe/SSE2"));
        assertEquals(ResolvePath.COMPUTE, ResolvePath.best(gl.capabilities(), null));
        assertEquals(ResolvePath.TRANSFORM_FEEDBACK, ResolvePath.best(gl.capabilities(),
                "llvmpipe (LLVM 15.0.6, 256 bits)"), "a software rasteriser resolves faster by transform feedback");
        FloatBuffer other = MemoryUtil.memAllocFloat(rec.capacity());
        try (PlantRenderer feedback = new PlantRenderer(gl, world, ResolvePath.TRANSFORM_FEEDBACK)) {
            feedback.setWholePlantsBelow(0); // as the compared renderer: the same lists
            draw(feedback);
            feedback.readRecords(other);
            draw();
            renderer.readRecords(rec);
            assertEquals(rec.limit(), other.limit());
            assertTrue(rec.limit() > 1000, "records compared: " + rec.limit() / PlantRenderer.RECORD_FLOATS);
            int differ = 0;
            float worst = 0;
            for (int i = 0; i < rec.limit(); i++) {
                float a = rec.get(i);
                float b = other.get(i);
                if (Float.floatToIntBits(a) != Float.floatToIntBits(b)) {
                    differ++;
                    worst = Math.max(worst, Math.abs(a - b) / Math.max(1f, Math.abs(b)));
                }
            }
            System.out.printf("resolve paths: %d of %d record values differ, largest relative difference %.2e%n",
                    differ, rec.limit(), worst);
            assertTrue(worst <= 1e-6f, "largest difference " + worst + " over " + differ + " values");
        } finally {
            MemoryUtil.memFree((java.nio.Buffer) other);
        }
    }
}
