package org.jecosys.bench;

import java.nio.file.Path;
import java.util.List;

/** Tables 1-4: primitive counts, level-of-detail bands and scene contents, with a chart of Table 2. */
final class ModelSection implements Section {
    private final Path scenes;

    ModelSection(Path scenes) {
        this.scenes = scenes;
    }

    @Override
    public String name() {
        return "Tables 1-4 (models and scenes)";
    }

    @Override
    public List<String> charts() {
        return List.of("table1.png", "table2.png");
    }

    @Override
    public void run(Mode mode, Report report) throws Exception {
        ModelTables m = new ModelTables(scenes);
        Table t1 = m.table1();
        Table t2 = m.table2();
        report.add(t1);
        report.add(t2);
        report.add(m.table3());
        report.add(m.table4());
        report.saveChart("table2.png", png -> Charts.bars(t2, 0, List.of("LOD1 paper", "LOD1 here", "LOD2 paper", "LOD2 here", "LOD3 paper", "LOD3 here"),
                "primitives", png));
        report.saveChart("table1.png", png -> Charts.bars(t1, 0, List.of("paper", "here"), "primitives", png));
    }
}
