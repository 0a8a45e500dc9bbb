package org.jecosys.render;

import org.jecosys.sim.internal.DecisionWriter;
import org.jecosys.sim.internal.FrameWriter;
import java.util.Map;
import java.util.WeakHashMap;
import org.jecosys.math.Camera;
import org.jecosys.plant.SpeciesModel;
import org.jecosys.sim.DrawDecision;
import org.jecosys.sim.Frame;
import org.jecosys.sim.World;

/** Frames for rendering tests, built without the animation engine (through Frame.set). */
public final class TestFrames {
    private TestFrames() {
    }

    /** Every component at pose 0 and its rest heading: the plant's rest azimuth plus its slot's. */
    public static Frame rest(World world) {
        Frame f = new Frame(world.plantCount(), world.bendGeometry());
        for (int p = 0; p < world.plantCount(); p++) {
            SpeciesModel m = world.plants().species().get(world.plantSpecies(p));
            for (int s = 0; s < world.componentsOf(p); s++) {
                FrameWriter.set(f, world.firstComponent(p) + s, 0f, (float) (world.plantRestAzimuth(p) + m.slotAzimuth(s)));
            }
        }
        return f;
    }

    /** A travelling breeze along +X at time t (seconds): bend toward +X by a wave over x. */
    public static Frame wind(World world, double t) {
        Frame f = new Frame(world.plantCount(), world.bendGeometry());
        for (int p = 0; p < world.plantCount(); p++) {
            SpeciesModel m = world.plants().species().get(world.plantSpecies(p));
            double wave = 0.5 + 0.5 * Math.sin(1.7 * t - 0.6 * world.plantX(p) + 0.3 * world.plantZ(p));
            for (int s = 0; s < world.componentsOf(p); s++) {
                int poses = m.slotPoseTable(s, world.plantVariant(p)).poses();
                FrameWriter.set(f, world.firstComponent(p) + s, (float) (wave * (poses - 1) * 0.8), 0f);
            }
        }
        return f;
    }

    private static final Map<World, DrawDecision> DECISIONS = new WeakHashMap<>();

    /** {@link #rest(World)} decided for a camera (what the simulation's workers do for its frames). */
    public static Frame rest(World world, Camera camera) {
        return decide(world, rest(world), camera);
    }

    /** {@link #wind(World, double)} decided for a camera. */
    public static Frame wind(World world, double t, Camera camera) {
        return decide(world, wind(world, t), camera);
    }

    /** Makes the frame's visibility and level decision for a camera, with the species' own bands. */
    public static synchronized Frame decide(World world, Frame frame, Camera camera) {
        return DecisionWriter.decideAll(DECISIONS.computeIfAbsent(world, DrawDecision::of), camera, frame);
    }
}
