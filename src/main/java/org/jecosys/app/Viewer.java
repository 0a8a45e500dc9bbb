package org.jecosys.app;

import java.nio.file.Path;
import org.jecosys.scene.SceneDef;

/** The desktop viewer (placeholder, filled in next). */
final class Viewer {
    private final SceneDef def;
    private final Path file;
    private final Path base;

    Viewer(SceneDef def, Path file, Path base) {
        this.def = def;
        this.file = file;
        this.base = base;
    }

    void run() throws java.io.IOException {
        throw new UnsupportedOperationException("viewer " + def.name() + file + base);
    }
}
