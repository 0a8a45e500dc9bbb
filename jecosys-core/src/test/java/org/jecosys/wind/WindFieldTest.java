package org.jecosys.wind;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.jecosys.math.Waypoint;
import org.joml.Vector2d;
import org.junit.jupiter.api.Test;

class WindFieldTest {

    private static FlowDef advectedSource(double x, double z) {
        return new FlowDef("s", FlowKind.SOURCE, true, x, z, 3, 0, 0.5, Double.POSITIVE_INFINITY,
                ActivationDef.ALWAYS, new MotionDef(MotionDef.Kind.ADVECTED, List.of(), 1, false), 8, 0.25, 0,
                        FlowDef.DEFAULT_GUST_STRENGTH, FlowDef.DEFAULT_TURBULENCE);
    }

    @Test
    void sourceAdvectedByUniformFlowMovesByUt() {
        double speed = 2.5;
        double dir = 0.6;
        WindField f = WindField.of(List.of(FlowDef.uniform("u", speed, dir), advectedSource(10, -4)));
        WindSource s = f.get(1);
        double dt = 1.0 / 60;
        int steps = 600;
        for (int i = 0; i < steps; i++) {
            f.advance(dt);
        }
        double t = steps * dt;
        assertEquals(10, f.time(), 1e-9);
        assertEquals(10 + speed * Math.cos(dir) * t, s.centreX(), 1e-6);
        assertEquals(-4 + speed * Math.sin(dir) * t, s.centreZ(), 1e-6);
    }

    @Test
    void advectedFlowIgnoresItselfAndInactiveFlows() {
        ActivationDef later = new ActivationDef(100, Double.POSITIVE_INFINITY, 0, 0);
        FlowDef u = new FlowDef("u", FlowKind.UNIFORM, true, 0, 0, 5, 0, 0.5, Double.POSITIVE_INFINITY, later,
                MotionDef.FIXED, 8, 0.25, 0, FlowDef.DEFAULT_GUST_STRENGTH, FlowDef.DEFAULT_TURBULENCE);
        WindField f = WindField.of(List.of(u, advectedSource(1, 1)));
        f.advance(1);
        assertEquals(1, f.get(1).centreX(), 0);
        assertEquals(1, f.get(1).centreZ(), 0);
    }

    @Test
    void pathMotionWalksTheWaypoints() {
        MotionDef path = new MotionDef(MotionDef.Kind.PATH,
                List.of(new Waypoint(0, 0, 0), new Waypoint(10, 0, 0), new Waypoint(10, 0, 10)), 2, false);
        FlowDef d = new FlowDef("p", FlowKind.VORTEX, true, 0, 0, 1, 0, 0.5, Double.POSITIVE_INFINITY,
                ActivationDef.ALWAYS, path, 8, 0.25, 0, FlowDef.DEFAULT_GUST_STRENGTH, FlowDef.DEFAULT_TURBULENCE);
        WindField f = WindField.of(List.of(d));
        WindSource s = f.get(0);
        assertEquals(0, s.centreX(), 0);
        f.advance(2.5);
        assertEquals(5, s.centreX(), 1e-9);
        assertEquals(0, s.centreZ(), 1e-9);
        f.advance(4);
        assertEquals(10, s.centreX(), 1e-9);
        assertEquals(3, s.centreZ(), 1e-9);
        f.advance(100);
        assertEquals(10, s.centreX(), 1e-9);
        assertEquals(10, s.centreZ(), 1e-9);

        MotionDef loop = new MotionDef(MotionDef.Kind.PATH, List.of(new Waypoint(0, 0, 0), new Waypoint(4, 0, 0)), 1, true);
        WindField g = WindField.of(List.of(new FlowDef("l", FlowKind.SOURCE, true, 0, 0, 1, 0, 0.5,
                Double.POSITIVE_INFINITY, ActivationDef.ALWAYS, loop, 8, 0.25, 0, FlowDef.DEFAULT_GUST_STRENGTH,
                FlowDef.DEFAULT_TURBULENCE)));
        g.advance(5);
        assertEquals(1, g.get(0).centreX(), 1e-9);
    }

    @Test
    void agentsFollowTheGameAndCanBeRemoved() {
        WindField f = new WindField();
        WindSource agent = f.attachAgent(FlowDef.point("car", FlowKind.SOURCE, 0, 0, 4));
        Vector2d v = new Vector2d();
        agent.setCentre(20, 20);
        f.advance(0.016);
        f.velocity(22, 20, v);
        assertEquals(4 / (2 * Math.PI) / 2, v.x, 1e-12);
        assertTrue(f.remove(agent));
        assertEquals(0, f.velocity(22, 20, v).length(), 0);
        assertFalse(f.remove(agent));
        assertThrows(IllegalArgumentException.class, () -> f.attachAgent(new FlowDef("x", FlowKind.SOURCE, true, 0, 0,
                1, 0, 0.5, Double.POSITIVE_INFINITY, ActivationDef.ALWAYS,
                new MotionDef(MotionDef.Kind.ADVECTED, List.of(), 1, false), 8, 0.25, 0,
                        FlowDef.DEFAULT_GUST_STRENGTH, FlowDef.DEFAULT_TURBULENCE)));
    }

    @Test
    void duplicateIdsAreRejected() {
        WindField f = new WindField();
        f.add(FlowDef.uniform("u", 1, 0));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> f.add(FlowDef.uniform("u", 2, 0)));
        assertTrue(e.getMessage().contains("'u'"));
    }

    @Test
    void blastAndRainHelpersStartNowAndAreRemovedWhenOver() {
        WindField f = new WindField();
        f.advance(3);
        WindSource b = f.blast("boom", 0, 0, 50, 0.5);
        WindSource r = f.rain("shower", 0, 0, 20, 1, 1, 2, 1.0, 5);
        assertEquals(2, f.size());
        f.advance(0.1);
        Vector2d v = new Vector2d();
        assertTrue(b.velocity(2, 0, f.time(), v).x > 0);
        f.advance(0.5);
        assertEquals(1, f.size());
        assertSame(r, f.get(0));
        f.advance(0.5);
        assertEquals(0, f.size());
    }

    @Test
    void activeCountFollowsWindowsAndSwitches() {
        WindField f = WindField.of(List.of(FlowDef.uniform("a", 1, 0), new FlowDef("b", FlowKind.UNIFORM, true, 0, 0, 1,
                0, 0.5, Double.POSITIVE_INFINITY, new ActivationDef(1, 1, 0, 0), MotionDef.FIXED, 8, 0.25, 0,
                        FlowDef.DEFAULT_GUST_STRENGTH, FlowDef.DEFAULT_TURBULENCE)));
        assertEquals(1, f.activeCount());
        f.advance(1.5);
        assertEquals(2, f.activeCount());
        f.get(0).setEnabled(false);
        assertEquals(1, f.activeCount());
        f.advance(1);
        assertEquals(0, f.activeCount());
    }

    @Test
    void gustTravelIsTheGustsMeanWind() {
        FlowDef east = FlowDef.builder("east", FlowKind.GUST).strength(4).direction(0).build();
        FlowDef north = FlowDef.builder("north", FlowKind.GUST).strength(2).direction(Math.PI / 2).build();
        WindField f = WindField.of(List.of(FlowDef.uniform("steady", 3, 1.0), east));
        Vector2d v = f.gustTravel(new Vector2d(9, 9));
        assertEquals(4, v.x, 1e-12, "one gust flow: its mean wind; the uniform flow does not travel");
        assertEquals(0, v.y, 1e-12);
        f.add(north);
        f.gustTravel(v);
        assertEquals(2, v.x, 1e-12, "two: the mean of their winds");
        assertEquals(1, v.y, 1e-12);
        f.get(1).setEnabled(false);
        f.get(2).setEnabled(false);
        f.gustTravel(v);
        assertEquals(0, v.x, 0.0, "none active: zero");
        assertEquals(0, v.y, 0.0);
    }
}
