package org.jecosys.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import org.jecosys.math.Progress;
import org.jecosys.plant.SpeciesDef;
import org.jecosys.sim.World;
import org.jecosys.terrain.DistributionDef;
import org.jecosys.terrain.Heightfield;
import org.jecosys.terrain.PlantLayout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** Each shipped scene builds and produces exactly its declared plant counts (paper Table 4). */
class ShippedScenesTest {
    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"c1.xml", "c2.xml", "c3.xml", "rose.xml", "meadow.xml", "large.xml"})
    void buildsWithExactlyTheDeclaredCounts(String name) throws Exception {
        Path file = Path.of("scenes", name);
        SceneDef scene = SceneFiles.parse(file);
        World world = World.build(scene.simulationDef(), file.getParent(), 2, Progress.NONE);
        PlantLayout layout = world.layout();
        assertEquals(List.of(), layout.warnings(), "no warnings");
        int expectedPlants = scene.placements().size();
        for (int d = 0; d < scene.distributions().size(); d++) {
            DistributionDef def = scene.distributions().get(d);
            assertEquals(def.count(), layout.placed(d), def.species() + " in " + name);
            expectedPlants += def.count();
        }
        assertEquals(expectedPlants, world.plantCount());
        int components = 0;
        Heightfield hf = world.terrain().heightfield();
        for (int p = 0; p < world.plantCount(); p++) {
            SpeciesDef species = scene.species().get(world.plantSpecies(p));
            components += species.componentsPerPlant();
            assertEquals(species.componentsPerPlant(), world.componentsOf(p));
            assertTrue(hf.contains(world.plantX(p), world.plantZ(p)));
            assertEquals(hf.height(world.plantX(p), world.plantZ(p)), world.plantY(p), 1e-4);
        }
        assertEquals(components, world.componentCount());
    }

    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"c1.xml:50:15:15", "c2.xml:75:0:0", "c3.xml:0:100:100"})
    void paperScenesHoldTable4(String spec) throws Exception {
        String[] p = spec.split(":");
        SceneDef scene = SceneFiles.parse(Path.of("scenes", p[0]));
        int[] want = {Integer.parseInt(p[1]), Integer.parseInt(p[2]), Integer.parseInt(p[3])};
        String[] names = {"grass tuft A", "yellow flower B", "purple flower C"};
        for (int i = 0; i < 3; i++) {
            int count = 0;
            for (DistributionDef d : scene.distributions()) {
                if (scene.speciesById(d.species()).name().equals(names[i])) {
                    count += d.count();
                }
            }
            assertEquals(want[i], count, names[i] + " in " + p[0]);
        }
    }
}
