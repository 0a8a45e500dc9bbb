package org.jecosys.app;

import org.jecosys.anim.AnimationMode;
import org.jecosys.field.FieldDebugView;
import org.jecosys.field.QuadtreeForceField;
import org.jecosys.math.Noise;
import org.jecosys.math.ViewCamera;
import org.jecosys.plant.SpeciesModel;
import org.jecosys.scene.SceneDef;
import org.jecosys.sim.Frame;
import org.jecosys.sim.World;
import org.jecosys.terrain.Heightfield;
import org.jecosys.wind.WindField;
import org.joml.Vector2d;

/**
 * A stand-in for the {@code Simulation} facade (being built on another branch) so the viewer and
 * {@code jecosys render} show moving plants now: the scene's real wind field and LOD quadtree force
 * field (paper §3), and a kinematic bend per component in place of the dynamic constraint (§4.2) —
 * each component leans toward the wind of its node by an amount growing with the wind speed, with a
 * per-plant flutter. Replace with {@code Simulation.step} once it lands.
 *
 * <p>Render thread (single owner); {@link #step} allocates nothing.
 */
final class PreviewAnimation {
    private final World world;
    private final WindField wind;
    private final QuadtreeForceField field;
    private final Vector2d tmp = new Vector2d();
    private AnimationMode mode;
    private boolean fieldOn;
    private double time;
    private long fieldNanos;
    private long animNanos;
    private int animated;

    PreviewAnimation(SceneDef def, World world) {
        this.world = world;
        this.wind = WindField.of(def.flows());
        Heightfield h = world.terrain().heightfield();
        float[] xs = new float[world.plantCount()];
        float[] zs = new float[world.plantCount()];
        for (int p = 0; p < xs.length; p++) {
            xs[p] = world.plantX(p);
            zs[p] = world.plantZ(p);
        }
        this.field = QuadtreeForceField.build(def.field(), h.minX(), h.minZ(), h.maxX(), h.maxZ(), h.minHeight(),
                h.maxHeight() + 1.0, wind, xs, zs);
        this.mode = def.animation().mode();
        this.fieldOn = def.field().enabled();
    }

    AnimationMode mode() {
        return mode;
    }

    void mode(AnimationMode mode) {
        this.mode = mode;
    }

    boolean fieldOn() {
        return fieldOn;
    }

    void fieldOn(boolean on) {
        this.fieldOn = on;
    }

    WindField wind() {
        return wind;
    }

    FieldDebugView fieldView() {
        return field.debugView();
    }

    double fieldMillis() {
        return fieldNanos / 1e6;
    }

    double animationMillis() {
        return animNanos / 1e6;
    }

    int componentsAnimated() {
        return animated;
    }

    /** Advances time by dt seconds and writes the frame for the camera. No allocation. */
    void step(double dt, ViewCamera camera, Frame dest) {
        time += dt;
        wind.advance(dt);
        long t0 = System.nanoTime();
        if (fieldOn) {
            field.update(camera);
        }
        long t1 = System.nanoTime();
        animated = 0;
        for (int p = 0, n = world.plantCount(); p < n; p++) {
            SpeciesModel m = world.plants().species().get(world.plantSpecies(p));
            float x = world.plantX(p);
            float z = world.plantZ(p);
            double wx = 0;
            double wz = 0;
            if (mode != AnimationMode.STATIC) {
                if (fieldOn) {
                    if (field.isVisible(p)) {
                        field.wind(p, tmp);
                        wx = tmp.x;
                        wz = tmp.y;
                    }
                } else {
                    // the paper's Table 6 "field off": random animation only
                    wx = 3 * Noise.value3(7, x * 0.3, z * 0.3, time * 0.5);
                    wz = 3 * Noise.value3(9, x * 0.3, z * 0.3, time * 0.5);
                }
            }
            double speed = Math.sqrt(wx * wx + wz * wz);
            double lean = speed / (speed + 4.0);
            double flutter = mode == AnimationMode.STATIC ? 0
                    : 0.12 * lean * Math.sin(7.0 * time + 13.7 * ((p * 0.618034) % 1.0) * 6.283);
            if (mode == AnimationMode.RANDOM) {
                lean = 0.35 * (0.5 + 0.5 * Math.sin(2.1 * time + p * 1.3));
            }
            double windAz = Math.atan2(wz, wx);
            int first = world.firstComponent(p);
            for (int s = 0, k = world.componentsOf(p); s < k; s++) {
                double rest = world.plantRestAzimuth(p) + m.slotAzimuth(s);
                double diff = Math.IEEEremainder(windAz - rest, 2 * Math.PI);
                float az = (float) (rest + (speed > 1e-6 ? diff * Math.min(1.0, lean * 1.6) : 0));
                int poses = m.slotPoseTable(s, world.plantVariant(p)).poses();
                float coord = (float) Math.max(0, Math.min(poses - 1, (lean + flutter) * (poses - 1)));
                dest.set(first + s, coord, az);
            }
            animated += mode == AnimationMode.STATIC ? 0 : world.componentsOf(p);
        }
        long t2 = System.nanoTime();
        fieldNanos = t1 - t0;
        animNanos = t2 - t1;
    }
}
