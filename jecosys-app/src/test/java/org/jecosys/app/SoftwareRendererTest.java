package org.jecosys.app;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** The viewer thins far plants by itself (as --quality low) on software rasterisers only. */
class SoftwareRendererTest {
    @Test
    void softwareRasterisersAreRecognisedAndGpusAreNot() {
        assertTrue(Viewer.softwareRenderer("llvmpipe (LLVM 15.0.6, 256 bits) / 4.5 (Core Profile) Mesa 22.3.6"));
        assertTrue(Viewer.softwareRenderer("softpipe / 3.3 (Core Profile) Mesa 23.1"));
        assertTrue(Viewer.softwareRenderer("Google SwiftShader / 4.5"));
        assertFalse(Viewer.softwareRenderer("NVIDIA H100 80GB HBM3/PCIe/SSE2 / 3.3.0 NVIDIA 580.65"));
        assertFalse(Viewer.softwareRenderer("AMD Radeon RX 7900 XTX (radeonsi, navi31, LLVM 17.0.6) / 4.6"));
    }
}
