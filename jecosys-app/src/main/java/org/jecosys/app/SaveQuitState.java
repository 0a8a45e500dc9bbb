package org.jecosys.app;

import java.io.IOException;
import java.nio.file.Path;
import java.util.function.Consumer;

/**
 * The save and quit dialogues' state of {@link ViewerControls}: a save that needs confirmation
 * ({@link SceneSaver.Plan#confirm()}) waits in {@link #pendingSave()} until {@link #confirmSave()} or
 * {@link #cancelSave()}; quitting with unsaved changes asks first ({@link #quitAsked()}) and may save
 * before it quits. Holds the pending plan and the quit flags; reports to the user through the
 * controls' message. Render thread (the viewer's stepping thread); allocates on saves.
 */
final class SaveQuitState {
    private final SceneEditor editor;
    private final SceneSaver saver;
    private final Consumer<String> message;
    private boolean quitAsked;
    private boolean quit;
    private boolean saveThenQuit;
    private SceneSaver.Plan pending;

    /**
     * Dialogue state for a scene.
     *
     * @param editor  the scene's editor (what is saved, whether it is dirty)
     * @param saver   where it saves
     * @param message sets the message shown to the user
     */
    SaveQuitState(SceneEditor editor, SceneSaver saver, Consumer<String> message) {
        this.editor = editor;
        this.saver = saver;
        this.message = message;
    }

    /** Saves to the open file (Save); asks first when {@link SceneSaver#plan()} says so. */
    void save() {
        plan(saver.plan());
    }

    /**
     * Saves to another file (Save As); asks first when it exists or is a shipped scene.
     *
     * @param path the file, as typed
     */
    void saveAs(String path) {
        String p = path == null ? "" : path.trim();
        if (p.isEmpty()) {
            message.accept("type the file to save to");
            return;
        }
        try {
            plan(saver.plan(Path.of(p)));
        } catch (IllegalArgumentException e) { // InvalidPathException included
            message.accept("cannot save: " + e.getMessage());
        }
    }

    private void plan(SceneSaver.Plan plan) {
        if (plan.confirm()) {
            pending = plan;
            message.accept("");
        } else {
            write(plan);
        }
    }

    /** Writes the save that was waiting for confirmation. */
    void confirmSave() {
        SceneSaver.Plan p = pending;
        pending = null;
        if (p != null) {
            write(p);
        }
    }

    /** Drops the save that was waiting for confirmation. */
    void cancelSave() {
        pending = null;
        saveThenQuit = false;
        message.accept("not saved");
    }

    private void write(SceneSaver.Plan plan) {
        try {
            saver.write(plan, editor.snapshot());
            editor.saved();
            message.accept("saved " + plan.target());
            if (saveThenQuit) {
                quit = true;
            }
        } catch (IOException | RuntimeException e) {
            message.accept(e.getMessage());
            saveThenQuit = false;
        }
    }

    /** Asks to quit: at once when nothing is unsaved, else {@link #quitAsked()} until answered. */
    void requestQuit() {
        if (editor.dirty()) {
            quitAsked = true;
        } else {
            quit = true;
        }
    }

    /**
     * Answers the unsaved-changes question.
     *
     * @param save true: save (asking again if the file is shipped), then quit; false: quit without saving
     */
    void answerQuit(boolean save) {
        quitAsked = false;
        if (save) {
            saveThenQuit = true;
            save();
        } else {
            quit = true;
        }
    }

    /** Keeps the viewer open: the unsaved-changes question was cancelled. */
    void cancelQuit() {
        quitAsked = false;
    }

    /** {@return the save waiting for confirmation, or null} */
    SceneSaver.Plan pendingSave() {
        return pending;
    }

    /** {@return whether the unsaved-changes question is open} */
    boolean quitAsked() {
        return quitAsked;
    }

    /** {@return whether the viewer should close now} */
    boolean quit() {
        return quit;
    }
}
