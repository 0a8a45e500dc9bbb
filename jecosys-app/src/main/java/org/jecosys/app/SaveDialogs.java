package org.jecosys.app;

import imgui.ImGui;
import imgui.flag.ImGuiCol;
import imgui.flag.ImGuiCond;
import imgui.flag.ImGuiWindowFlags;
import imgui.type.ImString;
import java.nio.file.Path;

/**
 * The panel's save section (ImGui): the open file and whether it has unsaved changes, Save, a path
 * field with Save As, and the two confirmations: before a save that {@link SceneSaver} says needs
 * one (a shipped scene, an existing other file, a file changed on disk), and before quitting with
 * unsaved changes. The decisions and the writing are {@link ViewerControls}' and {@link SceneSaver}'s.
 * Render thread; allocates labels.
 */
final class SaveDialogs {
    static final String CONFIRM = "Save over this file?";
    static final String UNSAVED = "Unsaved changes";

    private final ViewerControls controls;
    private final ImString path = new ImString(1024);

    SaveDialogs(ViewerControls controls) {
        this.controls = controls;
        path.set(suggestion(controls.saver()).toString());
    }

    /**
     * The file Save As offers first: next to the open scene with {@code -edited} before
     * {@code .xml}, or in the working folder when the open scene is a shipped one.
     */
    static Path suggestion(SceneSaver saver) {
        Path file = saver.file();
        String name = file.getFileName().toString();
        String stem = name.endsWith(".xml") ? name.substring(0, name.length() - 4) : name;
        Path dir = saver.isShipped(file) ? Path.of("").toAbsolutePath() : file.getParent();
        Path p = dir.resolve(stem + "-edited.xml");
        return saver.isShipped(p) ? p : p.normalize();
    }

    /** The section's widgets, inside the panel. */
    void section() {
        SceneSaver saver = controls.saver();
        ImGui.textWrapped(ViewerPanel.safe("Scene file: " + saver.file()
                + (controls.editor().dirty() ? "  (unsaved changes)" : "")));
        if (saver.isShipped(saver.file())) {
            ImGui.pushStyleColor(ImGuiCol.Text, 1f, 0.8f, 0.3f, 1f);
            ImGui.textWrapped("A scene shipped with JEcoSys: Save asks first; Save As keeps it as it is.");
            ImGui.popStyleColor();
        }
        if (ImGui.button("Save (Ctrl+S)")) {
            controls.save();
        }
        ImGui.pushItemWidth(-90);
        ImGui.inputText("##saveas", path);
        ImGui.popItemWidth();
        ImGui.sameLine();
        if (ImGui.button("Save As")) {
            controls.saveAs(path.get());
        }
    }

    /** The confirmations, at the top level of the frame (outside any window). */
    void modals() {
        if (controls.pendingSave() != null) {
            if (!ImGui.isPopupOpen(CONFIRM)) {
                ImGui.openPopup(CONFIRM);
            }
            ImGui.setNextWindowSize(460, 0, ImGuiCond.Always);
            if (ImGui.beginPopupModal(CONFIRM, ImGuiWindowFlags.NoResize)) {
                ImGui.textWrapped(ViewerPanel.safe(controls.pendingSave().question()));
                ImGui.textWrapped(ViewerPanel.safe("Saving writes " + controls.pendingSave().target()
                        + " in one step (a temporary file moved over it)."));
                if (ImGui.button("Save anyway")) {
                    controls.confirmSave();
                    ImGui.closeCurrentPopup();
                }
                ImGui.sameLine();
                if (ImGui.button("Cancel (Esc)") || controls.pendingSave() == null) {
                    if (controls.pendingSave() != null) {
                        controls.cancelSave();
                    }
                    ImGui.closeCurrentPopup();
                }
                ImGui.endPopup();
            }
        } else if (controls.quitAsked()) {
            if (!ImGui.isPopupOpen(UNSAVED)) {
                ImGui.openPopup(UNSAVED);
            }
            ImGui.setNextWindowSize(460, 0, ImGuiCond.Always);
            if (ImGui.beginPopupModal(UNSAVED, ImGuiWindowFlags.NoResize)) {
                ImGui.textWrapped(ViewerPanel.safe("Save the changes to " + controls.saver().file().getFileName()
                        + " before closing?"));
                if (ImGui.button("Save and quit")) {
                    controls.answerQuit(true);
                    ImGui.closeCurrentPopup();
                }
                ImGui.sameLine();
                if (ImGui.button("Quit without saving")) {
                    controls.answerQuit(false);
                    ImGui.closeCurrentPopup();
                }
                ImGui.sameLine();
                if (ImGui.button("Cancel") || !controls.quitAsked()) {
                    controls.cancelQuit();
                    ImGui.closeCurrentPopup();
                }
                ImGui.endPopup();
            }
        }
    }
}
