package com.example.meadowgame;

import org.jecosys.wind.AbstractWindSource;
import org.jecosys.wind.ActivationDef;
import org.joml.Vector2d;

/**
 * The game's own wind flow, which the scene format does not know: a breeze whose direction turns
 * slowly around the compass (one turn a minute) and whose strength fades to zero at its radius. The
 * library's force field evaluates it like its built-in flows.
 */
public final class Breeze extends AbstractWindSource {
    private final double speed;
    private final double radius;

    /**
     * A breeze centred on (x, z).
     *
     * @param id     the flow's id
     * @param x      centre X, metres
     * @param z      centre Z, metres
     * @param radius influence radius, metres
     * @param speed  wind speed at the centre, m/s
     */
    public Breeze(String id, double x, double z, double radius, double speed) {
        super(id, x, z, radius, ActivationDef.ALWAYS);
        this.speed = speed;
        this.radius = radius;
    }

    @Override
    protected void flow(double x, double z, double time, Vector2d dest) {
        double heading = 2 * Math.PI * time / 60;
        double dx = x - centreX();
        double dz = z - centreZ();
        double fade = Math.max(0, 1 - Math.sqrt(dx * dx + dz * dz) / radius);
        dest.set(speed * fade * Math.cos(heading), speed * fade * Math.sin(heading));
    }
}
