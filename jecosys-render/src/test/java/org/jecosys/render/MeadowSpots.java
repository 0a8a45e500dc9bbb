package org.jecosys.render;

import org.jecosys.plant.ComponentType;
import org.jecosys.plant.PoseTable;
import org.jecosys.plant.SpeciesModel;
import org.jecosys.sim.World;
import org.joml.Vector3f;

/** Places in a built world for the look tests' cameras, found from the plant positions. */
final class MeadowSpots {
    private MeadowSpots() {
    }

    /** {@return the slot of the species' stalk, or -1 when it has none} */
    static int stalkSlot(SpeciesModel m) {
        for (int slot = 0; slot < m.slotCount(); slot++) {
            if (m.def().components().get(m.slotComponent(slot)).type() == ComponentType.STALK) {
                return slot;
            }
        }
        return -1;
    }

    /**
     * The world position of plant p's stalk tip at rest (where its head sits) in a frame of {@link
     * TestFrames#rest}: the tip of pose 0 turned by the slot's rest heading as plant.vert turns it
     * (local +X to world (cos a, 0, sin a)) and moved to the plant's base; for a plant without a stalk,
     * its base.
     *
     * @return dest
     */
    static Vector3f top(World world, int p, Vector3f dest) {
        SpeciesModel m = world.plants().species().get(world.plantSpecies(p));
        int slot = stalkSlot(m);
        if (slot < 0) {
            return dest.set(world.plantX(p), world.plantY(p), world.plantZ(p));
        }
        double rest = world.plantRestAzimuth(p);
        double cr = Math.cos(rest);
        double sr = Math.sin(rest);
        double bx = m.slotBaseX(slot);
        double bz = m.slotBaseZ(slot);
        double a = rest + m.slotAzimuth(slot);
        double c = Math.cos(a);
        double s = Math.sin(a);
        PoseTable t = m.slotPoseTable(slot, world.plantVariant(p));
        Vector3f tip = t.position(0, t.points() - 1, new Vector3f());
        return dest.set((float) (world.plantX(p) + bx * cr - bz * sr + tip.x * c - tip.z * s),
                world.plantY(p) + tip.y,
                (float) (world.plantZ(p) + bx * sr + bz * cr + tip.x * s + tip.z * c));
    }
}
