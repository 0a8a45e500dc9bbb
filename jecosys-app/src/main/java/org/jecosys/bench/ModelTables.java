package org.jecosys.bench;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import org.jecosys.math.Progress;
import org.jecosys.plant.LodDef;
import org.jecosys.plant.Primitive;
import org.jecosys.plant.SpeciesDef;
import org.jecosys.plant.SpeciesModel;
import org.jecosys.scene.SceneDef;
import org.jecosys.scene.SceneFiles;
import org.jecosys.scene.SceneLoadException;
import org.jecosys.sim.World;

/**
 * The paper's model tables, regenerated from the shipped scenes: Table 1 (the rose's primitives
 * per level), Table 2 (plants A, B, C per level), Table 3 (the level-of-detail bands in use) and
 * Table 4 (the contents of scenes C1-C3, counted from the built scenes). Pure computation; any
 * thread; allocates.
 */
public final class ModelTables {
    private final Path scenes;

    /** Tables from the scene files in {@code scenes} (rose.xml, c1.xml, c2.xml, c3.xml). */
    public ModelTables(Path scenes) {
        this.scenes = scenes;
    }

    private SceneDef load(String name) throws SceneLoadException {
        return SceneFiles.parse(scenes.resolve(name));
    }

    /** Primitives of each level of one species, as built from its Def. */
    static int[] primitives(SpeciesDef def, long seed) {
        SpeciesModel m = SpeciesModel.build(def, seed);
        int[] out = new int[m.levels()];
        for (int l = 0; l < out.length; l++) {
            out[l] = m.primitiveCount(l);
        }
        return out;
    }

    private static String kind(SpeciesDef def, int level) {
        return def.lods().get(level).primitive() == Primitive.TRIANGLES ? "triangles" : "lines";
    }

    /** Table 1: the rose. */
    public Table table1() throws SceneLoadException {
        SceneDef scene = load("rose.xml");
        SpeciesDef rose = scene.speciesById("rose");
        int[] here = primitives(rose, scene.seed());
        Table t = new Table("table1", "Table 1: rose model complexity per level of detail",
                List.of("level", "primitive", "paper", "here"));
        for (int l = 0; l < here.length; l++) {
            t.row(String.valueOf((char) ('a' + l)), kind(rose, l), l < 3 ? PaperNumbers.TABLE1_ROSE[l] : null, here[l]);
        }
        return t.note("From scenes/rose.xml, species 'rose', counted on the built meshes.");
    }

    /** Table 2: plants A, B, C. */
    public Table table2() throws SceneLoadException {
        SceneDef scene = load("c1.xml");
        String[] ids = {"grassA", "flowerB", "flowerC"};
        Table t = new Table("table2", "Table 2: geometrical complexity of plants A, B, C",
                List.of("plant", "components", "LOD1 paper", "LOD1 here", "LOD2 paper", "LOD2 here", "LOD3 paper",
                        "LOD3 here"));
        for (int i = 0; i < ids.length; i++) {
            SpeciesDef s = scene.speciesById(ids[i]);
            int[] here = primitives(s, scene.seed());
            int[] paper = PaperNumbers.TABLE2[i];
            t.row(PaperNumbers.TABLE2_NAMES[i], s.componentsPerPlant(), paper[0], here[0], paper[1], here[1],
                    paper[2], here[2]);
        }
        return t.note("LOD1 and LOD2 count triangles, LOD3 lines; from the species of scenes/c1.xml.");
    }

    /** Table 3: the bands of every species in the paper's scenes. */
    public Table table3() throws SceneLoadException {
        SceneDef scene = load("c1.xml");
        Table t = new Table("table3", "Table 3: levels of detail",
                List.of("level", "paper band (m)", "paper primitive", "here band (m)", "here primitive", "species"));
        SpeciesDef first = scene.species().get(0);
        for (int l = 0; l < first.lods().size(); l++) {
            LodDef lod = first.lods().get(l);
            double from = l == 0 ? 0 : first.lods().get(l - 1).maxDistance();
            String band = fmt(from) + " to " + (lod.maxDistance() == Double.POSITIVE_INFINITY ? "beyond"
                    : fmt(lod.maxDistance()));
            StringBuilder same = new StringBuilder();
            for (SpeciesDef s : scene.species()) {
                if (s.lods().size() > l && s.lods().get(l).equals(lod)) {
                    same.append(same.length() == 0 ? "" : ", ").append(s.id());
                }
            }
            String[] paper = l < 3 ? PaperNumbers.TABLE3[l] : new String[] {"-", "-", "-"};
            t.row("LOD" + (l + 1), paper[0] + " to " + (paper[1].equals("-") ? "beyond" : paper[1]), paper[2], band,
                    lod.primitive() == Primitive.TRIANGLES ? "triangle" : "line", same.toString());
        }
        return t.note("The renderer dithers between levels over the scene's lodTransition band (no popping).");
    }

    /** Table 4: plants of A, B, C counted in the built scenes C1-C3. */
    public Table table4() throws SceneLoadException, IOException {
        Table t = new Table("table4", "Table 4: test scenes",
                List.of("scene", "A paper", "A here", "B paper", "B here", "C paper", "C here", "components"));
        String[] ids = {"grassA", "flowerB", "flowerC"};
        for (int s = 0; s < 3; s++) {
            String file = "c" + (s + 1) + ".xml";
            SceneDef scene = load(file);
            World world = World.build(scene.simulationDef(), scenes, 1, Progress.NONE);
            int[] counts = new int[3];
            for (int p = 0; p < world.plantCount(); p++) {
                String id = scene.species().get(world.plantSpecies(p)).id();
                for (int i = 0; i < 3; i++) {
                    if (ids[i].equals(id)) {
                        counts[i]++;
                    }
                }
            }
            int[] paper = PaperNumbers.TABLE4[s];
            t.row(PaperNumbers.SCENES[s], paper[0], counts[0], paper[1], counts[1], paper[2], counts[2],
                    world.componentCount());
        }
        return t.note("Counted on the scenes after competitive distribution (paper section 4.3).");
    }

    private static String fmt(double d) {
        return d == Math.rint(d) ? Long.toString((long) d) : Double.toString(d);
    }
}
