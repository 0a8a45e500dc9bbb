package org.jecosys.render;

import org.jecosys.render.GlContext.DebugOutput;
import java.nio.ByteBuffer;
import org.jecosys.math.Camera;
import org.jecosys.math.ViewCamera;
import org.jecosys.render.ImageMetrics.Img;
import org.jecosys.sim.Frame;
import org.jecosys.sim.World;
import org.joml.Matrix4f;
import org.joml.Vector4f;
import org.lwjgl.system.MemoryUtil;
import org.jecosys.render.gl.GlFramebuffer;
import org.jecosys.render.gl.Pixels;

/**
 * Headless pictures of one world for the look tests: a GL context, a framebuffer and a scene
 * renderer, and the four renders a vegetation mask needs. Render thread = the test's thread.
 */
final class Shots implements AutoCloseable {
    /** Largest channel difference (0..255) still counted as "the same pixel" in vegetation masks. */
    static final int TOLERANCE = 3;

    final int width;
    final int height;
    final World world;
    final GlContext gl;
    /** Multisampled as shipped ({@link #SAMPLES}); the colour renders. */
    final GlFramebuffer fb;
    /** Single-sampled: the depth reads of {@link #groundDistance}. */
    final GlFramebuffer depthFb;
    /** Samples per pixel of the colour renders: the library's default anti-aliasing. */
    static final int SAMPLES = 4;
    final SceneRenderer renderer;
    private final ByteBuffer px;

    Shots(World world, RenderSettings settings, int width, int height) {
        this.world = world;
        this.width = width;
        this.height = height;
        px = MemoryUtil.memAlloc(4 * width * height);
        gl = GlContext.headless(DebugOutput.ON);
        fb = new GlFramebuffer(gl.tracker(), width, height, SAMPLES);
        depthFb = new GlFramebuffer(gl.tracker(), width, height);
        renderer = new SceneRenderer(gl, world, settings);
    }

    /** One render with plants and terrain switched as given. */
    Img render(Frame frame, Camera camera, boolean plants, boolean terrain) {
        fb.bind();
        renderer.drawPlants = plants;
        renderer.drawTerrain = terrain;
        try {
            renderer.render(frame, camera, width, height);
        } finally {
            renderer.drawPlants = true;
            renderer.drawTerrain = true;
        }
        fb.resolve();
        Pixels.read(width, height, px);
        gl.debug().check("rendering a look-test picture");
        return Img.of(px, width, height);
    }

    /** The frames a still view gathers with temporal accumulation in the look tests: the whole jitter pattern. */
    static final int ACCUMULATED = 16;

    /**
     * The picture a view held still for {@link #ACCUMULATED} frames shows with temporal accumulation on
     * ({@link GlFramebuffer#setAccumulation}): each frame drawn with the framebuffer's jittered camera. The
     * accumulation is off again afterwards.
     */
    Img accumulated(Frame frame, Camera camera) {
        fb.setAccumulation(ACCUMULATED);
        try {
            for (int i = 0; i < ACCUMULATED - 1; i++) {
                fb.bind();
                renderer.render(frame, fb.jittered(camera, true), width, height);
                fb.resolve();
            }
            return render(frame, fb.jittered(camera, true), true, true);
        } finally {
            fb.setAccumulation(0);
        }
    }

    /**
     * Distance from the eye to what each pixel of the terrain alone shows (the depth buffer of a
     * render without plants, unprojected), metres; infinity where the sky is. Allocates.
     */
    double[] groundDistance(Frame frame, Camera camera) {
        return distance(frame, camera, false);
    }

    /**
     * Distance from the eye to what each pixel of the whole scene shows (plants, cover and terrain),
     * metres; infinity where the sky is. Allocates.
     */
    double[] sceneDistance(Frame frame, Camera camera) {
        return distance(frame, camera, true);
    }

    private double[] distance(Frame frame, Camera camera, boolean plants) {
        double[] p = points(frame, camera, plants);
        double[] d = new double[width * height];
        for (int i = 0; i < d.length; i++) {
            d[i] = Double.isNaN(p[3 * i]) ? Double.POSITIVE_INFINITY : Math.sqrt(
                    sq(p[3 * i] - camera.x()) + sq(p[3 * i + 1] - camera.y()) + sq(p[3 * i + 2] - camera.z()));
        }
        return d;
    }

    private static double sq(double v) {
        return v * v;
    }

    /**
     * The world point each pixel shows (x, y, z per pixel, rows from the bottom; NaN where the sky is), from
     * the depth buffer of a render with the plants on or off. The horizon skirt lies just inside the far
     * plane along its ray. Allocates.
     */
    double[] points(Frame frame, Camera camera, boolean plants) {
        depthFb.bind();
        renderer.drawPlants = plants;
        try {
            renderer.render(frame, camera, width, height);
        } finally {
            renderer.drawPlants = true;
        }
        java.nio.FloatBuffer depth = MemoryUtil.memAllocFloat(width * height);
        try {
            org.lwjgl.opengl.GL11C.glReadPixels(0, 0, width, height, org.lwjgl.opengl.GL11C.GL_DEPTH_COMPONENT,
                    org.lwjgl.opengl.GL11C.GL_FLOAT, depth);
            gl.debug().check("reading depth");
            Matrix4f inv = camera.viewProjection(new Matrix4f()).invert();
            org.joml.Vector3f p = new org.joml.Vector3f();
            double[] out = new double[3 * width * height];
            for (int y = 0; y < height; y++) {
                for (int x = 0; x < width; x++) {
                    int i = y * width + x;
                    float z = depth.get(i);
                    if (z >= 1f) {
                        out[3 * i] = Double.NaN;
                        out[3 * i + 1] = Double.NaN;
                        out[3 * i + 2] = Double.NaN;
                        continue;
                    }
                    inv.transformProject((float) (2 * (x + 0.5) / width - 1), (float) (2 * (y + 0.5) / height - 1),
                            2 * z - 1, p);
                    out[3 * i] = p.x;
                    out[3 * i + 1] = p.y;
                    out[3 * i + 2] = p.z;
                }
            }
            return out;
        } finally {
            MemoryUtil.memFree((java.nio.Buffer) depth);
        }
    }

    /** The full picture and its vegetation mask ({@link ImageMetrics#vegetation}). */
    record View(Img full, Img ground, boolean[] vegetation) {
    }

    View view(Frame frame, Camera camera) {
        Img full = render(frame, camera, true, true);
        Img ground = render(frame, camera, false, true);
        Img plants = render(frame, camera, true, false);
        Img empty = render(frame, camera, false, false);
        return new View(full, ground, ImageMetrics.vegetation(full, ground, plants, empty, TOLERANCE));
    }

    /**
     * Projects a world point to window pixels (GL order: x right, y up from the bottom row).
     *
     * @return {x, y, distance along the view} or null behind the eye
     */
    static double[] project(Camera camera, double x, double y, double z, int width, int height) {
        Matrix4f vp = camera.viewProjection(new Matrix4f());
        Vector4f v = vp.transform(new Vector4f((float) x, (float) y, (float) z, 1f));
        if (v.w <= 1e-6f) {
            return null;
        }
        return new double[] {(v.x / v.w + 1) * 0.5 * width, (v.y / v.w + 1) * 0.5 * height, v.w};
    }

    /**
     * 15 m up and oblique: over the middle of the terrain, 10 m back along +Z, looking at the ground 30 m
     * ahead (issue 41's view from above; 50 degrees high, near 0.05 m, far 1000 m).
     */
    static ViewCamera fromAbove(org.jecosys.terrain.Heightfield hf, int width, int height) {
        double cx = hf.minX() + hf.sizeX() / 2;
        double cz = hf.minZ() + hf.sizeZ() / 2;
        double gy = hf.height(cx, cz);
        return lookAt(cx, gy + 15, cz + 10, cx, gy, cz - 30, Math.toRadians(50), width / (double) height, 0.05, 1000);
    }

    /** A camera at an eye point looking at a target point, with the given lens. */
    static ViewCamera lookAt(double ex, double ey, double ez, double tx, double ty, double tz, double fovY,
                             double aspect, double near, double far) {
        double dx = tx - ex;
        double dy = ty - ey;
        double dz = tz - ez;
        double yaw = Math.atan2(dx, -dz);
        double pitch = Math.atan2(dy, Math.hypot(dx, dz));
        ViewCamera camera = new ViewCamera();
        camera.setPosition(ex, ey, ez);
        camera.setOrientation(yaw, pitch);
        camera.setLens(fovY, aspect, near, far);
        return camera;
    }

    @Override
    public void close() {
        try {
            renderer.close();
            fb.close();
            depthFb.close();
            gl.close();
        } finally {
            MemoryUtil.memFree((java.nio.Buffer) px);
        }
    }
}
