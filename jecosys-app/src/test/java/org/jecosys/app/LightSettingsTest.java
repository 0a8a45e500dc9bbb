package org.jecosys.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import org.jecosys.math.Progress;
import org.jecosys.math.Rgb;
import org.jecosys.render.RenderSettings;
import org.jecosys.scene.RenderDef;
import org.jecosys.scene.SceneDef;
import org.jecosys.scene.SceneFiles;
import org.jecosys.sim.Simulation;
import org.junit.jupiter.api.Test;

/**
 * The app's mapping from a scene's light and patches to the renderer's settings, and the viewer's
 * sun sliders saved back into the scene (an unmoved sun keeps the file's exact angles).
 */
class LightSettingsTest {
    @Test
    void sceneLightReachesTheRenderSettings() {
        RenderDef.Light light = new RenderDef.Light(Math.toRadians(-40), Math.toRadians(20), new Rgb(1, 0.8f, 0.6f),
                1.25, new Rgb(0.1f, 0.2f, 0.7f), new Rgb(0.3f, 0.3f, 0.4f), 0.65, 8, 80, 1, 0);
        RenderDef def = RenderDef.builder().size(640, 360).sky(new Rgb(0.7f, 0.8f, 0.9f)).light(light)
                .patches(new RenderDef.Patches(25, 0.7, 42)).build();
        RenderSettings s = HeadlessRender.settings(def);
        assertEquals(Math.toRadians(-40), s.lighting().sunAzimuth(), 1e-12);
        assertEquals(Math.toRadians(20), s.lighting().sunElevation(), 1e-12);
        assertEquals(light.sunColour(), s.lighting().sunColour());
        assertEquals(1.25f, s.lighting().sunIntensity());
        assertEquals(light.skyZenith(), s.lighting().skyZenith());
        assertEquals(light.ambient(), s.lighting().ambient());
        assertEquals(0.65f, s.contactShadow());
        assertEquals(8, s.lighting().fogStart());
        assertEquals(80, s.lighting().fogEnd());
        assertEquals(25, s.patchScale());
        assertEquals(0.7f, s.patchStrength());
        assertEquals(42, s.patchSeed());
        assertEquals(def.sky(), s.lighting().sky());
    }

    @Test
    void sunSlidersAreSavedWithTheScene() throws Exception {
        SceneDef def = SceneFiles.parse(Path.of("scenes", "c1.xml"));
        try (Simulation sim = Simulation.create(def.simulationDef(), Path.of("scenes"), 1, Progress.NONE)) {
            RenderSettings settings = HeadlessRender.settings(def.render());
            SceneEditor editor = new SceneEditor(def, sim, settings);
            assertEquals(def.render(), editor.snapshot().render(), "an untouched sun saves the file's light exactly");
            editor.setSun(settings.lighting().sunAzimuth(), settings.lighting().sunElevation());
            assertFalse(editor.dirty(), "the same sun is no change");
            editor.setSun(Math.toRadians(-60), Math.toRadians(25));
            assertTrue(editor.dirty());
            RenderDef.Light saved = editor.snapshot().render().light();
            assertEquals(Math.toRadians(-60), saved.sunAzimuth(), 1e-9);
            assertEquals(Math.toRadians(25), saved.sunElevation(), 1e-9);
            assertEquals(def.render().light().contactShadow(), saved.contactShadow());
            assertEquals(def.render().patches(), editor.snapshot().render().patches());
            SceneDef back = SceneFiles.parse(SceneFiles.toXml(editor.snapshot()).getBytes(
                    java.nio.charset.StandardCharsets.UTF_8), "saved.xml", Path.of("scenes"));
            assertEquals(editor.snapshot().render(), back.render(), "the saved file reads back the same sun");
        }
    }
}
