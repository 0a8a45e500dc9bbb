package org.jecosys.render.plant;

import java.nio.IntBuffer;
import java.util.List;
import org.jecosys.plant.SpeciesModel;
import org.jecosys.sim.World;
import org.jecosys.render.RenderSettings;
import org.jecosys.render.ground.PatchNoise;

/**
 * Each component's colour variation, worked out on the CPU once and again only when the look it
 * comes from changes ({@link PlantLook#version}), instead of in every frame's resolve pass: it
 * depends on nothing that moves. Per component: a hue turn and a brightness factor drawn from seeded
 * hashes of its plant (named by the plant's first component) and, a third as much, of the component
 * itself, and the dryness of the ground patch its root stands on ({@link RenderSettings#patchLevel},
 * the noise the terrain shows). {@code plant_resolve.glsl} reads the result.
 *
 * <p>Packing, 2 ints per component (an RG32UI buffer texture): the hue turn in radians as float
 * bits; the brightness factor times 32768 in the low 16 bits (it lies in [0.3, 1.8], and 1 stays
 * exact) and the dryness times 65535 in the high 16 bits.
 *
 * <p>GL-free; any single thread. {@link #bake} allocates nothing.
 */
public final class ComponentLooks {
    private final World world;
    /** Per species, per slot: the slot at the root of its chain of parents. */
    private final int[][] rootSlot;

    /** For a world's plants. Build time; allocates. */
    public ComponentLooks(World world) {
        this.world = world;
        List<SpeciesModel> models = world.plants().species();
        rootSlot = new int[models.size()][];
        for (int s = 0; s < rootSlot.length; s++) {
            SpeciesModel m = models.get(s);
            rootSlot[s] = new int[m.slotCount()];
            for (int slot = 0; slot < m.slotCount(); slot++) {
                int r = slot;
                while (m.slotParent(r) >= 0) {
                    r = m.slotParent(r);
                }
                rootSlot[s][slot] = r;
            }
        }
    }

    /**
     * Writes every component's packed look, component after component, from {@code dest}'s position
     * 0; leaves its position at the end. No allocation.
     *
     * @param look the variation, patches and seed
     * @param dest room for 2 ints per component of the world
     */
    public void bake(PlantLook look, IntBuffer dest) {
        List<SpeciesModel> models = world.plants().species();
        float inv = 1f / look.patchScale();
        float strength = look.patchStrength();
        int seed = look.seed();
        dest.clear();
        for (int p = 0, plants = world.plantCount(); p < plants; p++) {
            int s = world.plantSpecies(p);
            SpeciesModel m = models.get(s);
            int first = world.firstComponent(p);
            int ph = hash(first * 0x9e3779b9 ^ seed);
            float hueSd = look.hue(s);
            float valueSd = look.value(s);
            double rest = world.plantRestAzimuth(p);
            float rc = (float) Math.cos(rest);
            float rs = (float) Math.sin(rest);
            for (int slot = 0, slots = m.slotCount(); slot < slots; slot++) {
                int ch = hash(ph ^ (slot + 1) * 0x85ebca6b);
                float hue = hueSd * (spread(ph, 0) + 0.35f * spread(ch, 0));
                float value = Math.max(0.3f, Math.min(1.8f, 1f + valueSd * (spread(ph, 10) + 0.3f * spread(ch, 10))));
                float dry = 0f;
                if (strength > 0f) {
                    int r = rootSlot[s][slot];
                    float ox = (float) m.slotBaseX(r);
                    float oz = (float) m.slotBaseZ(r);
                    float x = world.plantX(p) + (ox * rc - oz * rs);
                    float z = world.plantZ(p) + (ox * rs + oz * rc);
                    dry = strength * PatchNoise.level(x * inv, z * inv, seed);
                }
                dest.put(Float.floatToRawIntBits(hue))
                        .put(Math.round(value * 32768f) | Math.round(dry * 65535f) << 16);
            }
        }
    }

    /** {@return the hue turn, radians, of a packed look} */
    public static float hue(int packedHue) {
        return Float.intBitsToFloat(packedHue);
    }

    /** {@return the brightness factor of a packed look} */
    public static float value(int packed) {
        return (packed & 0xFFFF) / 32768f;
    }

    /** {@return the patch dryness of a packed look} */
    public static float dryness(int packed) {
        return (packed >>> 16) / 65535f;
    }

    /** A 32-bit integer hash (xor-shift and multiply), as unsigned arithmetic. */
    public static int hash(int x) {
        x ^= x >>> 16;
        x *= 0x7feb352d;
        x ^= x >>> 15;
        x *= 0x846ca68b;
        x ^= x >>> 16;
        return x;
    }

    /** A spread of standard deviation 1 from 10 bits of {@code h}: uniform on [-sqrt 3, sqrt 3]. */
    public static float spread(int h, int shift) {
        return ((h >>> shift & 1023) / 1023f - 0.5f) * 3.4641016f;
    }
}
