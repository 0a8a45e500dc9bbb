package org.jecosys.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** {@code jecosys view --help} lists the viewer's controls, over a scene of one square and over an open world. */
class ViewHelpTest {
    @Test
    void viewHelpListsTheControls() {
        CliTest.Result r = CliTest.run("view", "--help");
        assertEquals(0, r.code(), r.err());
        assertTrue(r.out().contains("Controls in the viewer:"), r.out());
        for (String c : ViewerControls.CONTROLS) {
            assertTrue(r.out().contains(c), c + " in\n" + r.out());
        }
        assertTrue(r.out().contains("Controls over an open world"), r.out());
        for (String c : OpenWorldControls.CONTROLS) {
            assertTrue(r.out().contains(c), c + " in\n" + r.out());
        }
        for (String key : new String[] {"Ctrl", "Shift", "frame the whole scene", "Ctrl+S", "shipped scene", "F12"}) {
            assertTrue(r.out().contains(key), key);
        }
    }
}
