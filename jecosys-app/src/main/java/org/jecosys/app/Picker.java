package org.jecosys.app;

import org.jecosys.math.Camera;
import org.jecosys.render.overlay.GizmoRenderer;
import org.jecosys.render.overlay.Gizmos;
import org.jecosys.terrain.Heightfield;
import org.joml.Matrix4f;
import org.joml.Vector4f;
import org.jecosys.render.gl.Pixels;

/**
 * What is under the mouse pointer: the terrain point ({@link #ground}) and the gizmo whose handle
 * (the dot at its centre, its pole and its head, as {@link GizmoRenderer} draws them) is nearest on
 * screen ({@link #gizmo}). Pixels are measured from the viewport's top-left corner, as GLFW reports
 * the cursor. Pure projection arithmetic, no GL, so tests drive it headless. Render thread; no
 * allocation (the temporaries are fields).
 */
final class Picker {
    /** How far from a handle the pointer may be and still pick it, pixels. */
    static final double SLOP = 4;

    private final Heightfield ground;
    private final Matrix4f viewProj = new Matrix4f();
    private final Matrix4f inverse = new Matrix4f();
    private final Vector4f a = new Vector4f();
    private final Vector4f b = new Vector4f();
    private final double[] screen = new double[3];

    Picker(Heightfield ground) {
        this.ground = ground;
    }

    /**
     * The terrain point under pixel (sx, sy) into {@code hit} (x, z, metres): the first point along
     * the pointer's ray below the ground, within the camera's far distance.
     *
     * @return false when the ray leaves the terrain or the far distance before meeting the ground
     */
    boolean ground(Camera camera, double far, double sx, double sy, int width, int height, double[] hit) {
        camera.viewProjection(inverse).invert();
        float nx = (float) (2 * sx / width - 1);
        float ny = (float) (1 - 2 * sy / height);
        inverse.transform(a.set(nx, ny, -1, 1));
        inverse.transform(b.set(nx, ny, 1, 1));
        a.div(a.w);
        b.div(b.w);
        double dx = b.x - a.x;
        double dy = b.y - a.y;
        double dz = b.z - a.z;
        double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
        dx /= len;
        dy /= len;
        dz /= len;
        double step = Math.max(0.002, 0.25 * Math.min(ground.cellX(), ground.cellZ()));
        double prevT = 0;
        for (double t = 0; t < far; t += step + t * 0.004) {
            double x = a.x + dx * t;
            double y = a.y + dy * t;
            double z = a.z + dz * t;
            if (ground.contains(x, z) && y <= ground.height(x, z)) {
                // refine between the last point above and this one
                double lo = prevT;
                double hi = t;
                for (int i = 0; i < 20; i++) {
                    double m = 0.5 * (lo + hi);
                    double mx = a.x + dx * m;
                    double mz = a.z + dz * m;
                    if (a.y + dy * m <= ground.height(mx, mz)) {
                        hi = m;
                    } else {
                        lo = m;
                    }
                }
                hit[0] = a.x + dx * hi;
                hit[1] = a.z + dz * hi;
                return true;
            }
            prevT = t;
        }
        return false;
    }

    /**
     * Projects world point (x, y, z) to viewport pixels from the top-left into {@code dest[0..1]},
     * with {@code dest[2]} its clip w (&le; 0 behind the eye).
     */
    void project(Camera camera, double x, double y, double z, int width, int height, double[] dest) {
        camera.viewProjection(viewProj).transform(a.set((float) x, (float) y, (float) z, 1));
        dest[2] = a.w;
        dest[0] = (a.x / a.w * 0.5 + 0.5) * width;
        dest[1] = (0.5 - a.y / a.w * 0.5) * height;
    }

    /**
     * The gizmo whose handle is under pixel (sx, sy): within {@link GizmoRenderer#HEAD_PX} plus
     * {@link #SLOP} pixels of its head, or of the pole from its centre on the ground up to the head;
     * the nearest on screen when several are.
     *
     * @return the gizmo's index in {@code gizmos}, or -1
     */
    int gizmo(Gizmos gizmos, Camera camera, double sx, double sy, int width, int height) {
        int best = -1;
        double bestD = GizmoRenderer.HEAD_PX + SLOP;
        for (int i = 0; i < gizmos.size(); i++) {
            double x = gizmos.x(i);
            double z = gizmos.z(i);
            project(camera, x, ground.height(x, z), z, width, height, screen);
            if (screen[2] <= 0) {
                continue;
            }
            double px = screen[0];
            double py = screen[1];
            double top = py - GizmoRenderer.POLE_PX;
            // distance to the segment from the centre up to the head's centre (screen y grows downward)
            double cy = Math.max(top, Math.min(py, sy));
            double d = Math.hypot(sx - px, sy - cy);
            if (d <= bestD) {
                bestD = d;
                best = i;
            }
        }
        return best;
    }
}
