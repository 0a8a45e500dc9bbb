package org.jecosys.app;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_3;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_ESCAPE;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_F;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_H;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_LEFT_CONTROL;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_P;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_S;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_W;
import static org.lwjgl.glfw.GLFW.GLFW_MOUSE_BUTTON_LEFT;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.stream.Stream;
import org.jecosys.math.Progress;
import org.jecosys.math.ViewCamera;
import org.jecosys.render.RenderSettings;
import org.jecosys.scene.SceneDef;
import org.jecosys.scene.SceneFiles;
import org.jecosys.sim.Simulation;
import org.jecosys.wind.FlowDef;
import org.jecosys.wind.FlowKind;
import org.jecosys.wind.WindSource;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The viewer's input handling and saving, driven headless as GLFW's callbacks and the frame loop
 * would drive them (C1 copied into a temporary "shipped" scenes folder): a key tap shorter than a
 * frame is handled, F adds a flow under the pointer, a gizmo is picked and dragged, Ctrl+S over a
 * shipped scene asks first, Save As writes a new file in one step, numbers are saved as set, and
 * quitting with unsaved changes asks.
 */
class ViewerControlsTest {
    private static final int W = 640;
    private static final int H = 360;
    /** A frame at 10 fps, the meadow's rate on software GL where a 12 ms tap used to be missed. */
    private static final double DT = 0.1;

    @TempDir
    Path dir;

    private Path shipped;
    private Path file;
    private SceneDef def;
    private Simulation sim;
    private ViewerInput input;
    private FlyCamera fly;
    private SceneEditor editor;
    private ViewerControls controls;

    @BeforeEach
    void setUp() throws Exception {
        shipped = Files.createDirectories(dir.resolve("install/scenes"));
        file = shipped.resolve("c1.xml");
        Files.copy(Path.of("scenes/c1.xml"), file);
        def = SceneFiles.parse(file);
        sim = Simulation.create(def.simulationDef(), shipped, 1, Progress.NONE);
        ViewCamera camera = ViewCamera.of(def.camera(), sim.world().terrain().heightfield()
                .height(def.camera().x(), def.camera().z()), W / (double) H);
        fly = new FlyCamera(camera, def.camera(), sim.world().terrain().heightfield());
        input = new ViewerInput();
        editor = new SceneEditor(def, sim, RenderSettings.standalone());
        controls = new ViewerControls(def, sim, editor, new SceneSaver(file, shipped), fly, input);
    }

    @AfterEach
    void tearDown() {
        sim.close();
    }

    /** One frame as the viewer runs it: input, step, gizmos. The pointer at (sx, sy) pixels. */
    private void frame(double sx, double sy) {
        controls.frame(DT, sx, sy, W, H, false, false);
        sim.step(DT, fly.camera());
        controls.gizmos();
    }

    private void tap(int key, int mods) {
        input.key(key, ViewerInput.PRESS, mods);
        input.key(key, ViewerInput.RELEASE, mods);
    }

    @Test
    void aKeyTapShorterThanAFrameIsHandled() {
        assertFalse(fly.playing());
        tap(GLFW_KEY_P, 0); // pressed and released between two frames
        frame(W / 2.0, H / 2.0);
        assertTrue(fly.playing(), "P tapped between frames starts the camera path");
        tap(GLFW_KEY_P, 0);
        tap(GLFW_KEY_P, 0);
        frame(W / 2.0, H / 2.0);
        assertTrue(fly.playing(), "two taps in one frame toggle twice");
        tap(GLFW_KEY_P, 0);
        frame(W / 2.0, H / 2.0);
        assertFalse(fly.playing());
        // a walking key tapped between frames still walks for that frame
        double z = fly.camera().z();
        tap(GLFW_KEY_W, 0);
        frame(W / 2.0, H / 2.0);
        assertTrue(fly.camera().z() < z - 0.5 * FlyCamera.walkSpeed(sim.world().terrain().heightfield()) * DT,
                "W tapped between frames walks forward (-Z): " + z + " -> " + fly.camera().z());
        double after = fly.camera().z();
        frame(W / 2.0, H / 2.0);
        assertEquals(after, fly.camera().z(), 1e-12, "and stops once released");
        // keys typed into a text field of the panel do nothing
        tap(GLFW_KEY_P, 0);
        controls.frame(DT, W / 2.0, H / 2.0, W, H, true, false);
        assertFalse(fly.playing());
    }

    @Test
    void fAddsTheChosenFlowUnderThePointerScaledToTheScene() {
        tap(GLFW_KEY_3, 0); // sink
        tap(GLFW_KEY_F, 0);
        frame(W / 2.0, H * 0.7);
        String id = controls.selected();
        assertNotNull(id, controls.message());
        FlowDef f = editor.flow(id);
        assertEquals(FlowKind.SINK, f.kind());
        double[] hit = new double[2];
        assertTrue(new Picker(sim.world().terrain().heightfield()).ground(fly.camera(), 300, W / 2.0, H * 0.7, W, H,
                hit));
        assertEquals(hit[0], f.x(), 0.006, "at the pointer, to the centimetre");
        assertEquals(hit[1], f.z(), 0.006);
        assertEquals(Decimals.round(f.x(), 2), f.x(), 0);
        assertEquals(FlowDefaults.of(sim.world().terrain().heightfield(), def.flows()).radius(), f.influenceRadius());
        assertTrue(sim.inspect().windField().indexOf(id) >= 0, "live after the step");
        assertTrue(editor.dirty());
    }

    @Test
    void aGizmoIsPickedAndDraggedAcrossTheGround() {
        tap(GLFW_KEY_F, 0); // a source at the pointer
        frame(W * 0.4, H * 0.75);
        String id = controls.selected();
        FlowDef before = editor.flow(id);
        controls.select(null);
        frame(W * 0.9, H * 0.9);
        Picker picker = new Picker(sim.world().terrain().heightfield());
        double[] at = new double[3];
        picker.project(fly.camera(), before.x(), sim.world().terrain().heightfield().height(before.x(), before.z()),
                before.z(), W, H, at);
        frame(at[0], at[1]);
        assertNotNull(controls.hovered(), "the pointer over the gizmo's centre hovers it");
        input.mouseButton(GLFW_MOUSE_BUTTON_LEFT, ViewerInput.PRESS, 0);
        frame(at[0], at[1]);
        assertEquals(id, controls.selected(), "pressing on the gizmo selects its flow");
        frame(at[0] + 60, at[1] - 20);
        frame(at[0] + 120, at[1] - 40);
        input.mouseButton(GLFW_MOUSE_BUTTON_LEFT, ViewerInput.RELEASE, 0);
        frame(at[0] + 120, at[1] - 40);
        FlowDef after = editor.flow(id);
        double[] hit = new double[2];
        assertTrue(picker.ground(fly.camera(), 300, at[0] + 120, at[1] - 40, W, H, hit));
        assertEquals(hit[0], after.x(), 0.05, "dropped under the pointer");
        assertEquals(hit[1], after.z(), 0.05);
        assertTrue(Math.hypot(after.x() - before.x(), after.z() - before.z()) > 0.5, "moved");
        WindSource live = sim.inspect().windField().get(sim.inspect().windField().indexOf(id));
        assertEquals(after.x(), live.centreX(), 1e-9, "the running flow is where the scene says");
        // a click on the ground (not on a gizmo) deselects and pushes plants only while held
        input.mouseButton(GLFW_MOUSE_BUTTON_LEFT, ViewerInput.PRESS, 0);
        input.mouseButton(GLFW_MOUSE_BUTTON_LEFT, ViewerInput.RELEASE, 0);
        frame(W * 0.1, H * 0.95);
        assertNull(controls.selected());
        assertEquals(-1, sim.inspect().windField().indexOf(ViewerControls.DRAG_AGENT));
    }

    @Test
    void savingOverAShippedSceneAsksFirst() throws Exception {
        byte[] original = Files.readAllBytes(file);
        tap(GLFW_KEY_F, 0);
        frame(W / 2.0, H * 0.7);
        input.key(GLFW_KEY_LEFT_CONTROL, ViewerInput.PRESS, ViewerInput.MOD_CONTROL);
        tap(GLFW_KEY_S, ViewerInput.MOD_CONTROL);
        input.key(GLFW_KEY_LEFT_CONTROL, ViewerInput.RELEASE, 0);
        double z = fly.camera().z();
        frame(W / 2.0, H * 0.7);
        assertEquals(z, fly.camera().z(), 1e-12, "the S of Ctrl+S does not walk");
        SceneSaver.Plan plan = controls.pendingSave();
        assertNotNull(plan, "Ctrl+S over a shipped scene waits for confirmation");
        assertTrue(plan.question().contains("shipped"), plan.question());
        assertArrayEquals(original, Files.readAllBytes(file), "nothing written before confirming");
        controls.cancelSave();
        assertNull(controls.pendingSave());
        assertArrayEquals(original, Files.readAllBytes(file), "nor after cancelling");
        assertTrue(editor.dirty());
        controls.save();
        controls.confirmSave();
        assertFalse(editor.dirty(), controls.message());
        SceneDef saved = SceneFiles.parse(file);
        assertEquals(def.flows().size() + 1, saved.flows().size(), "the added flow is in the file");
    }

    @Test
    void saveAsWritesANewFileInOneStepAndAsksBeforeReplacingAnother() throws Exception {
        byte[] original = Files.readAllBytes(file);
        Path mine = Files.createDirectories(dir.resolve("work"));
        Path target = mine.resolve("mine.xml");
        editor.setLodEdge(0, 0, 7.25f);
        controls.saveAs(target.toString());
        assertNull(controls.pendingSave(), "a new file outside the shipped folder needs no confirmation");
        assertTrue(Files.isRegularFile(target), controls.message());
        assertEquals(SceneFiles.toXml(SceneSaver.relocate(editor.snapshot(), shipped, mine)),
                Files.readString(target), "the whole scene, as SceneFiles writes it");
        try (Stream<Path> files = Files.list(mine)) {
            assertEquals(1, files.count(), "no temporary file left beside it");
        }
        assertArrayEquals(original, Files.readAllBytes(file), "Save As leaves the shipped scene as it was");
        assertEquals(target.toAbsolutePath().normalize(), controls.saver().file(), "the new file is now the open one");
        assertFalse(editor.dirty());
        // Save now writes the new file without asking; Save As over an existing other file asks
        editor.setLodEdge(0, 0, 7.5f);
        controls.save();
        assertNull(controls.pendingSave());
        assertEquals(7.5, SceneFiles.parse(target).species().get(0).lods().get(0).maxDistance());
        Path other = Files.writeString(mine.resolve("other.xml"), "keep me");
        controls.saveAs(other.toString());
        assertNotNull(controls.pendingSave());
        assertTrue(controls.pendingSave().question().contains("exists"), controls.pendingSave().question());
        tap(GLFW_KEY_ESCAPE, 0);
        frame(W / 2.0, H / 2.0);
        assertNull(controls.pendingSave(), "Escape cancels");
        assertEquals("keep me", Files.readString(other));
        controls.saveAs(mine.resolve("no/such/folder/x.xml").toString());
        assertTrue(controls.message().contains("does not exist"), controls.message());
    }

    @Test
    void aSavedNumberEqualsTheOneSet() throws Exception {
        Path target = dir.resolve("numbers.xml");
        editor.setLodEdge(0, 1, 43.146f); // as the LOD slider sets it: a float
        editor.setLodTransition(0.35f);
        String breeze = editor.flowIds().get(0);
        editor.setFlow(breeze, editor.flow(breeze).toBuilder().strength(Decimals.ofFloat(2.7f))
                .direction(Math.toRadians(Decimals.ofFloat(33.5f))).build());
        controls.saveAs(target.toString());
        String xml = Files.readString(target);
        assertTrue(xml.contains("maxDistance=\"43.146\""), xml);
        assertFalse(xml.contains("43.14599"), xml);
        assertTrue(xml.contains("lodTransition=\"0.35\""), xml);
        assertTrue(xml.contains("strength=\"2.7\""), xml);
        assertTrue(xml.contains("direction=\"33.5\""), xml);
        SceneDef back = SceneFiles.parse(target);
        assertEquals(43.146, back.species().get(0).lods().get(1).maxDistance());
        assertEquals(0.35, back.render().lodTransition());
        assertEquals(2.7, back.flows().get(0).strength());
    }

    @Test
    void quittingWithUnsavedChangesAsksAndHKeyFramesTheScene() {
        tap(GLFW_KEY_ESCAPE, 0);
        frame(W / 2.0, H / 2.0);
        assertTrue(controls.quit(), "nothing changed: Escape quits at once");
        ViewerControls again = new ViewerControls(def, sim, editor, new SceneSaver(file, shipped), fly, input);
        editor.setLodEdge(0, 0, 6f);
        tap(GLFW_KEY_H, 0);
        tap(GLFW_KEY_ESCAPE, 0);
        again.frame(DT, W / 2.0, H / 2.0, W, H, false, false);
        assertFalse(again.quit());
        assertTrue(again.quitAsked(), "unsaved changes: asks first");
        again.answerQuit(false);
        assertTrue(again.quit());
        double[] screen = new double[3];
        new Picker(sim.world().terrain().heightfield()).project(fly.camera(), 0, 0, 0, W, H, screen);
        assertTrue(screen[2] > 0 && screen[0] > 0 && screen[0] < W && screen[1] > 0 && screen[1] < H,
                "H framed the scene: its middle is in view");
    }
}
