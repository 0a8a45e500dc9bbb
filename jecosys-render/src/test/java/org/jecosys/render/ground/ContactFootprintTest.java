package org.jecosys.render.ground;

import static org.junit.jupiter.api.Assertions.assertTrue;

import org.jecosys.render.RenderScenes;
import org.jecosys.scene.SceneDef;
import org.jecosys.sim.World;
import org.junit.jupiter.api.Test;

/**
 * Issue 25, "Done when": contact darkening is sized to what casts it. In C3 (thin flowers) the ground
 * the plants darken covers at most 3 times the area of the plants' footprints. The footprint of a plant
 * is the outline of everything it has seen from straight above (the convex hull of its rest pose
 * projected on the ground, {@link Footprint}); the ground counts as darkened where the terrain shader
 * makes it at least 2% darker than without contact shadow ({@code contactShadow * occlusion >= 0.02}:
 * the shader multiplies the lit soil by {@code 1 - contactShadow * occlusion}, so this is the picture's
 * own darkening before haze), integrated over the occlusion map's texels.
 */
class ContactFootprintTest {
    /** Least relative darkening counted as darkened ground. */
    private static final double VISIBLE = 0.02;

    @Test
    void c3DarkensLittleMoreThanItsPlantsFootprints() {
        SceneDef def = RenderScenes.load("c3.xml");
        World world = RenderScenes.build(def);
        double shadow = def.render().light().contactShadow();
        ContactOcclusion map = ContactOcclusion.of(world);
        double texel = map.texelX * map.texelZ;
        double darkened = 0;
        for (float o : map.occlusion) {
            if (shadow * o >= VISIBLE) {
                darkened += texel;
            }
        }
        double footprints = 0;
        for (int p = 0; p < world.plantCount(); p++) {
            footprints += Footprint.of(world.plants().species().get(world.plantSpecies(p)), world.plantVariant(p)).area();
        }
        double ratio = darkened / footprints;
        System.out.printf("[look] c3: darkened ground %.3f m2, plants' footprints %.3f m2 (%d plants): %.2fx (<= 3)%n",
                darkened, footprints, world.plantCount(), ratio);
        assertTrue(footprints > 0, "the plants have footprints");
        assertTrue(ratio <= 3, String.format("c3's plants darken %.2fx the area of their footprints, want <= 3", ratio));
    }

    @Test
    void aWideTuftDarkensAWideSpotAndAThinFlowerASmallOne() {
        World world = RenderScenes.build(RenderScenes.load("c1.xml"));
        double tuft = 0;
        double flower = 0;
        for (int v = 0; v < world.plants().species().get(0).variants(); v++) {
            tuft = Math.max(tuft, Footprint.of(world.plants().species().get(0), v).area());
        }
        for (int v = 0; v < world.plants().species().get(1).variants(); v++) {
            flower = Math.max(flower, Footprint.of(world.plants().species().get(1), v).area());
        }
        System.out.printf("[look] c1 footprints: grass tuft %.4f m2, yellow flower %.4f m2%n", tuft, flower);
        assertTrue(tuft > 10 * flower, "a 25-leaf tuft's footprint is many times a flower's: " + tuft + " vs " + flower);
    }
}
