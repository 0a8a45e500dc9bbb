package org.jecosys.render.overlay;

import java.nio.FloatBuffer;
import org.jecosys.field.FieldDebugView;
import org.jecosys.math.Camera;
import org.jecosys.terrain.Heightfield;
import org.joml.Matrix4f;
import org.lwjgl.system.MemoryUtil;

/**
 * The triangles of {@link GizmoRenderer}, built on the CPU each frame (no GL here, so it is tested
 * without a context): per vertex a world position (metres) and a colour with alpha. Two sections:
 * the <em>ground</em> section (wind arrows, influence and core rings, direction glyphs), draped on
 * the terrain and depth-tested, and the <em>handle</em> section (pole, ground dot and head of each
 * gizmo), drawn on top of everything so a flow can always be seen and picked. Widths and handle sizes
 * are in pixels, turned into metres at each point from the camera's pixel footprint, so they read
 * the same near and far; radii and arrow lengths are in metres. Native storage, grown when a frame
 * needs more (the only allocation); freed by {@link #close()}. Render thread; not thread-safe.
 */
public final class GizmoMesh implements AutoCloseable {
    /** Floats per vertex: x, y, z, r, g, b, a. */
    public static final int FLOATS = 7;
    /** Radius of a gizmo's head, pixels. */
    public static final float HEAD_PX = 9f;
    /** Height of a gizmo's pole above its centre on the ground, pixels. */
    public static final float POLE_PX = 34f;
    /** Radius of the dot at a gizmo's centre on the ground, pixels. */
    public static final float DOT_PX = 6f;
    /** Width of an influence ring and of arrow shafts, pixels. */
    public static final float LINE_PX = 2.5f;
    /** Width of a wind arrow's shaft, pixels. */
    public static final float WIND_PX = 1.8f;
    /** Lift of ground lines above the terrain, pixels (at least {@link #MIN_LIFT} metres). */
    public static final float LIFT_PX = 1.5f;
    /** Smallest lift above the terrain, metres. */
    public static final double MIN_LIFT = 0.01;
    private static final int CIRCLE = 18;

    private final Heightfield ground;
    private final double cell;
    private final Matrix4f view = new Matrix4f();
    private FloatBuffer groundPart = MemoryUtil.memAllocFloat(4096 * FLOATS);
    private FloatBuffer handlePart = MemoryUtil.memAllocFloat(1024 * FLOATS);
    private Camera camera;
    private double perMetre;
    private double atEye;
    private float rightX;
    private float rightY;
    private float rightZ;
    private float upX;
    private float upY;
    private float upZ;
    private float red;
    private float green;
    private float blue;
    private float alpha;
    private FloatBuffer out;
    private boolean closed;

    public GizmoMesh(Heightfield ground) {
        this.ground = ground;
        this.cell = Math.max(1e-3, Math.min(ground.cellX(), ground.cellZ()));
    }

    /** The ground section of the last {@link #build}, position 0 to its limit. */
    public FloatBuffer groundPart() {
        return groundPart;
    }

    /** The handle section of the last {@link #build}, position 0 to its limit. */
    public FloatBuffer handlePart() {
        return handlePart;
    }

    /** Vertices of the ground section of the last build. */
    public int groundVertices() {
        return groundPart.limit() / FLOATS;
    }

    /** Vertices of the handle section of the last build. */
    public int handleVertices() {
        return handlePart.limit() / FLOATS;
    }

    /**
     * Builds both sections for one frame. No allocation unless a section grows.
     *
     * @param gizmos         the gizmos, or null
     * @param wind           the force field's view for the wind arrows, or null for none
     * @param windScale      wind speed of the colour scale's top, m/s, &gt; 0
     * @param camera         the viewer
     * @param viewportHeight pixels, &gt; 0
     */
    public void build(Gizmos gizmos, FieldDebugView wind, double windScale, Camera camera, int viewportHeight) {
        this.camera = camera;
        this.perMetre = camera.viewHeightPerMetre() / viewportHeight;
        this.atEye = camera.viewHeightAtEye() / viewportHeight;
        camera.view(view);
        // camera right and up in world space: the rows of the view matrix's rotation
        rightX = view.m00();
        rightY = view.m10();
        rightZ = view.m20();
        upX = view.m01();
        upY = view.m11();
        upZ = view.m21();
        out = groundPart.clear();
        if (wind != null) {
            windArrows(wind, windScale);
        }
        int n = gizmos == null ? 0 : gizmos.size();
        for (int i = 0; i < n; i++) {
            ground(gizmos, i);
        }
        groundPart = out;
        groundPart.flip();
        out = handlePart.clear();
        // selected gizmos last, so their handles are on top
        for (int pass = 0; pass < 2; pass++) {
            for (int i = 0; i < n; i++) {
                if ((gizmos.highlight(i) == Gizmos.SELECTED) == (pass == 1)) {
                    handle(gizmos, i);
                }
            }
        }
        handlePart = out;
        handlePart.flip();
        this.camera = null;
    }

    /** Metres per pixel at world point (x, y, z). */
    public double pixel(double x, double y, double z) {
        double dx = x - camera.x();
        double dy = y - camera.y();
        double dz = z - camera.z();
        return atEye + Math.sqrt(dx * dx + dy * dy + dz * dz) * perMetre;
    }

    /**
     * The colour a gizmo of {@code kind} is drawn in: its kind's colour at full alpha when enabled
     * and fully active; fainter and greyer as the activation weight falls; grey and faint when off.
     */
    public static void shade(GizmoKind kind, boolean enabled, double weight, float[] rgba) {
        if (!enabled) {
            rgba[0] = 0.55f;
            rgba[1] = 0.55f;
            rgba[2] = 0.55f;
            rgba[3] = 0.55f;
            return;
        }
        float w = (float) Math.max(0, Math.min(1, weight));
        float grey = 0.5f;
        float keep = 0.35f + 0.65f * w;
        rgba[0] = grey + (kind.red() - grey) * keep;
        rgba[1] = grey + (kind.green() - grey) * keep;
        rgba[2] = grey + (kind.blue() - grey) * keep;
        rgba[3] = 0.45f + 0.55f * w;
    }

    /**
     * The colour of a wind speed on the overlay's scale: blue at 0, through cyan, green and yellow,
     * to red at {@code scale} and above.
     */
    public static void windColour(double speed, double scale, float[] rgb) {
        double t = Math.max(0, Math.min(1, speed / scale));
        // four stops: blue (0), cyan (1/3), yellow (2/3), red (1)
        double[] stops = WIND_STOPS;
        double f = t * 3;
        int k = Math.min(2, (int) f);
        double u = f - k;
        for (int c = 0; c < 3; c++) {
            rgb[c] = (float) (stops[3 * k + c] + (stops[3 * (k + 1) + c] - stops[3 * k + c]) * u);
        }
    }

    private static final double[] WIND_STOPS = {
        0.20, 0.35, 1.00,
        0.10, 0.85, 0.95,
        1.00, 0.90, 0.10,
        1.00, 0.15, 0.10};

    private final float[] rgba = new float[4];

    private void colour(float r, float g, float b, float a) {
        red = r;
        green = g;
        blue = b;
        alpha = a;
    }

    private void windArrows(FieldDebugView view, double scale) {
        int nodes = view.nodeCount();
        for (int n = 0; n < nodes; n++) {
            if (!view.effective(n) || !view.visible(n)) {
                continue;
            }
            float wx = view.windX(n);
            float wz = view.windZ(n);
            double speed = Math.sqrt(wx * wx + wz * wz);
            if (speed < 1e-3) {
                continue;
            }
            double cx = 0.5 * (view.minX(n) + view.maxX(n));
            double cz = 0.5 * (view.minZ(n) + view.maxZ(n));
            double half = 0.5 * Math.min(view.maxX(n) - view.minX(n), view.maxZ(n) - view.minZ(n));
            double len = 1.6 * half * (0.25 + 0.75 * Math.min(1, speed / scale));
            windColour(speed, scale, rgba);
            colour(rgba[0], rgba[1], rgba[2], 0.9f);
            double dx = wx / speed;
            double dz = wz / speed;
            double x0 = cx - 0.5 * len * dx;
            double z0 = cz - 0.5 * len * dz;
            arrow(x0, z0, cx + 0.5 * len * dx, cz + 0.5 * len * dz, WIND_PX, 0.3 * len);
        }
    }

    /** The ground part of gizmo i: core and influence rings and the kind's direction glyph. */
    private void ground(Gizmos g, int i) {
        shade(g.kind(i), g.enabled(i), g.weight(i), rgba);
        float a = rgba[3];
        double x = g.x(i);
        double z = g.z(i);
        double r = g.influenceRadius(i);
        double core = g.coreRadius(i);
        double y = ground.height(x, z);
        double px = pixel(x, y, z);
        // the glyph's radius: the influence radius when it has one, else a size that reads on screen
        double rho = Double.isInfinite(r) ? Math.max(4 * core, 70 * px) : r;
        float line = g.highlight(i) == Gizmos.NORMAL ? LINE_PX : LINE_PX * 1.8f;
        colour(rgba[0], rgba[1], rgba[2], a);
        if (!Double.isInfinite(r)) {
            ring(x, z, r, line);
        }
        GizmoKind kind = g.kind(i);
        if (core > 0 && core < rho && kind != GizmoKind.UNIFORM && kind != GizmoKind.GUST) {
            colour(rgba[0], rgba[1], rgba[2], a * 0.6f);
            ring(x, z, core, line * 0.6f);
            colour(rgba[0], rgba[1], rgba[2], a);
        }
        switch (kind) {
            case UNIFORM, GUST -> {
                double d = g.direction(i);
                double dx = Math.cos(d);
                double dz = Math.sin(d);
                double len = Math.min(rho, 70 * px) * 1.2;
                arrow(x, z, x + dx * len, z + dz * len, line * 1.4f, 0.3 * len);
                if (kind == GizmoKind.GUST) {
                    for (int c = 1; c <= 2; c++) {
                        double t = 0.25 * c * len;
                        chevron(x + dx * t, z + dz * t, dx, dz, 0.15 * len, line);
                    }
                }
            }
            case SOURCE, AGENT, BLAST -> radial(x, z, rho, kind == GizmoKind.BLAST ? 8 : 6, true, line);
            case SINK -> radial(x, z, rho, 6, false, line);
            case VORTEX -> swirl(x, z, rho, g.spin(i), line);
            default -> {
                // RAIN and USER: the ring and the handle say it all
            }
        }
    }

    private void radial(double x, double z, double rho, int count, boolean outward, float line) {
        for (int k = 0; k < count; k++) {
            double t = 2 * Math.PI * (k + 0.5) / count;
            double c = Math.cos(t);
            double s = Math.sin(t);
            double r0 = 0.35 * rho;
            double r1 = 0.75 * rho;
            if (outward) {
                arrow(x + c * r0, z + s * r0, x + c * r1, z + s * r1, line, 0.12 * rho);
            } else {
                arrow(x + c * r1, z + s * r1, x + c * r0, z + s * r0, line, 0.12 * rho);
            }
        }
    }

    /** Three arcs at 0.6 rho turning with the spin (+1: the sense of y x (p - c)), each with a head. */
    private void swirl(double x, double z, double rho, int spin, float line) {
        double r = 0.6 * rho;
        int sense = spin >= 0 ? 1 : -1;
        for (int k = 0; k < 3; k++) {
            double t0 = 2 * Math.PI * k / 3;
            int steps = 10;
            double span = Math.toRadians(80);
            double px0 = 0;
            double pz0 = 0;
            for (int s = 0; s <= steps; s++) {
                // angle measured so that increasing it moves along y x (p - c): (dz, -dx)
                double t = t0 - sense * span * s / steps;
                double px1 = x + r * Math.cos(t);
                double pz1 = z + r * Math.sin(t);
                if (s > 0) {
                    ribbon(px0, pz0, px1, pz1, line);
                }
                px0 = px1;
                pz0 = pz1;
            }
            double t = t0 - sense * span;
            // tangent of travel at the arc's end
            double tx = sense * Math.sin(t);
            double tz = -sense * Math.cos(t);
            head(px0, pz0, tx, tz, 0.15 * rho);
        }
    }

    private void ring(double x, double z, double r, float line) {
        int n = (int) Math.max(48, Math.min(512, Math.ceil(2 * Math.PI * r / (1.5 * cell))));
        double x0 = x + r;
        double z0 = z;
        for (int k = 1; k <= n; k++) {
            double t = 2 * Math.PI * k / n;
            double x1 = x + r * Math.cos(t);
            double z1 = z + r * Math.sin(t);
            segment(x0, z0, x1, z1, line);
            x0 = x1;
            z0 = z1;
        }
    }

    /** An arrow on the ground from (x0, z0) to (x1, z1), its head {@code head} metres long. */
    private void arrow(double x0, double z0, double x1, double z1, float line, double head) {
        double dx = x1 - x0;
        double dz = z1 - z0;
        double len = Math.sqrt(dx * dx + dz * dz);
        if (len < 1e-6) {
            return;
        }
        dx /= len;
        dz /= len;
        double h = Math.min(head, 0.6 * len);
        ribbon(x0, z0, x1 - dx * h * 0.5, z1 - dz * h * 0.5, line);
        head(x1, z1, dx, dz, h);
    }

    /** A flat triangle on the ground with its tip at (x, z) pointing along unit (dx, dz). */
    private void head(double x, double z, double dx, double dz, double h) {
        double bx = x - dx * h;
        double bz = z - dz * h;
        double w = 0.45 * h;
        vertexOnGround(x, z);
        vertexOnGround(bx - dz * w, bz + dx * w);
        vertexOnGround(bx + dz * w, bz - dx * w);
    }

    private void chevron(double x, double z, double dx, double dz, double size, float line) {
        double bx = x - dx * size;
        double bz = z - dz * size;
        segment(bx - dz * size, bz + dx * size, x, z, line);
        segment(x, z, bx + dz * size, bz - dx * size, line);
    }

    /** A draped line from (x0, z0) to (x1, z1), cut into pieces of about 1.5 terrain cells. */
    private void ribbon(double x0, double z0, double x1, double z1, float line) {
        double dx = x1 - x0;
        double dz = z1 - z0;
        int n = (int) Math.max(1, Math.min(64, Math.ceil(Math.sqrt(dx * dx + dz * dz) / (1.5 * cell))));
        for (int k = 0; k < n; k++) {
            segment(x0 + dx * k / n, z0 + dz * k / n, x0 + dx * (k + 1) / n, z0 + dz * (k + 1) / n, line);
        }
    }

    /** One straight quad on the ground, {@code line} pixels wide at its ends. */
    private void segment(double x0, double z0, double x1, double z1, float line) {
        double dx = x1 - x0;
        double dz = z1 - z0;
        double len = Math.sqrt(dx * dx + dz * dz);
        if (len < 1e-9) {
            return;
        }
        double nx = -dz / len;
        double nz = dx / len;
        double y0 = ground.height(x0, z0);
        double y1 = ground.height(x1, z1);
        double w0 = 0.5 * line * pixel(x0, y0, z0);
        double w1 = 0.5 * line * pixel(x1, y1, z1);
        vertexOnGround(x0 + nx * w0, z0 + nz * w0);
        vertexOnGround(x1 + nx * w1, z1 + nz * w1);
        vertexOnGround(x1 - nx * w1, z1 - nz * w1);
        vertexOnGround(x0 + nx * w0, z0 + nz * w0);
        vertexOnGround(x1 - nx * w1, z1 - nz * w1);
        vertexOnGround(x0 - nx * w0, z0 - nz * w0);
    }

    private void vertexOnGround(double x, double z) {
        double y = ground.height(x, z);
        double lift = Math.max(MIN_LIFT, LIFT_PX * pixel(x, y, z));
        vertex(x, y + lift, z);
    }

    /** The handle of gizmo i: a pole from its centre on the ground to a round head, and a dot at the centre. */
    private void handle(Gizmos g, int i) {
        shade(g.kind(i), g.enabled(i), g.weight(i), rgba);
        double x = g.x(i);
        double z = g.z(i);
        double y = ground.height(x, z);
        double px = pixel(x, y, z);
        double top = y + POLE_PX * px;
        int h = g.highlight(i);
        float outline = h == Gizmos.SELECTED ? 1f : h == Gizmos.HOVERED ? 0.75f : 0.05f;
        float grow = h == Gizmos.NORMAL ? 0f : 1.5f;
        float a = Math.max(0.6f, rgba[3]);
        colour(outline, outline, outline, a);
        pole(x, y, z, top, (3.5f + grow) * px);
        disc(x, y, z, (DOT_PX + 1.5f + grow) * px);
        disc(x, top, z, (HEAD_PX + 1.5f + grow) * px);
        colour(rgba[0], rgba[1], rgba[2], a);
        pole(x, y, z, top, 2f * px);
        disc(x, y, z, DOT_PX * px);
        disc(x, top, z, HEAD_PX * px);
    }

    /** A camera-facing quad from (x, y0, z) up to (x, y1, z), {@code width} metres wide. */
    private void pole(double x, double y0, double z, double y1, double width) {
        double w = 0.5 * width;
        double ax = rightX * w;
        double ay = rightY * w;
        double az = rightZ * w;
        vertex(x - ax, y0 - ay, z - az);
        vertex(x + ax, y0 + ay, z + az);
        vertex(x + ax, y1 + ay, z + az);
        vertex(x - ax, y0 - ay, z - az);
        vertex(x + ax, y1 + ay, z + az);
        vertex(x - ax, y1 - ay, z - az);
    }

    /** A camera-facing disc of radius {@code r} metres around (x, y, z). */
    private void disc(double x, double y, double z, double r) {
        double px0 = x + rightX * r;
        double py0 = y + rightY * r;
        double pz0 = z + rightZ * r;
        for (int k = 1; k <= CIRCLE; k++) {
            double t = 2 * Math.PI * k / CIRCLE;
            double c = Math.cos(t) * r;
            double s = Math.sin(t) * r;
            double px1 = x + rightX * c + upX * s;
            double py1 = y + rightY * c + upY * s;
            double pz1 = z + rightZ * c + upZ * s;
            vertex(x, y, z);
            vertex(px0, py0, pz0);
            vertex(px1, py1, pz1);
            px0 = px1;
            py0 = py1;
            pz0 = pz1;
        }
    }

    private void vertex(double x, double y, double z) {
        if (out.remaining() < FLOATS) {
            int pos = out.position();
            FloatBuffer bigger = MemoryUtil.memRealloc(out, Math.max(out.capacity() * 2, 64 * FLOATS));
            bigger.limit(bigger.capacity()).position(pos);
            if (out == groundPart) {
                groundPart = bigger;
            } else {
                handlePart = bigger;
            }
            out = bigger;
        }
        out.put((float) x).put((float) y).put((float) z).put(red).put(green).put(blue).put(alpha);
    }

    /** Frees the native storage. Idempotent. */
    @Override
    public void close() {
        if (!closed) {
            closed = true;
            MemoryUtil.memFree((java.nio.Buffer) groundPart);
            MemoryUtil.memFree((java.nio.Buffer) handlePart);
        }
    }
}
