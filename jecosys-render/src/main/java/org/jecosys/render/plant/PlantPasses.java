package org.jecosys.render.plant;

import static org.lwjgl.opengl.GL11C.GL_LINES;
import static org.lwjgl.opengl.GL11C.GL_TRIANGLES;
import static org.lwjgl.opengl.GL11C.GL_UNSIGNED_INT;
import static org.lwjgl.opengl.GL20C.glUniform1f;
import static org.lwjgl.opengl.GL20C.glUniform1i;
import static org.lwjgl.opengl.GL20C.glUniform2f;
import static org.lwjgl.opengl.GL20C.glUniform3f;
import static org.lwjgl.opengl.GL30C.glBindVertexArray;
import static org.lwjgl.opengl.GL31C.glDrawElementsInstanced;

import java.util.function.ToIntFunction;
import java.util.ArrayList;
import java.util.List;
import org.jecosys.render.gl.GlProgram;
import org.jecosys.render.gl.GlTracker;
import org.jecosys.render.gl.GlVertexArray;
import org.jecosys.render.ground.ShadowFit;

/**
 * The instanced draws of {@link PlantRenderer}: eight variants of the two draw programs, triangle
 * levels ({@code plant.vert}) and line levels ({@code plant_line.vert}), each with or without the
 * dither test of a transition band ({@code DITHER}) and the placement of flower parts
 * ({@code FLOWERS}), and the draws that use them. A list's plants drawn whole go through a program
 * without the dither test (on llvmpipe a shader that may discard turns the early depth test off),
 * the plants in a band through one with it ({@link PlantBatches#whole}); species without flower parts
 * take the programs without the flower placement.
 *
 * <p>Render thread. {@link #compile} and the constructor allocate; {@link #frame},
 * {@link #drawTriangles} and {@link #drawLines} do not. The programs belong to whoever compiled them.
 */
public final class PlantPasses {
    private static final int DITHER = 1;
    private static final int LINES = 2;
    private static final int FLOWERS = 4;
    /** Number of programs: every combination of {@code DITHER}, lines and {@code FLOWERS}. */
    public static final int COUNT = 8;

    /** Number of caster programs (for the sun's shadow map): with and without the dither test and flower parts. */
    public static final int CASTERS = 4;

    private final PlantUniforms[] passes = new PlantUniforms[COUNT];
    /** The caster programs, program k from {@link #compileCaster}{@code (t, k)}; null until {@link #useCasters}. */
    private PlantUniforms[] casters;
    /**
     * The triangle programs that read the shadow map, program k from {@link #compileReceiver}{@code (t, k)};
     * null until {@link #useCasters}.
     */
    private PlantUniforms[] receivers;
    /**
     * The triangle programs of a target without samples, which keep a fragment's opaque core or its
     * fringe ({@code SPLIT}), program k from {@link #compileSplit}{@code (t, k, false)}; null until
     * {@link #useSplit}.
     */
    private PlantUniforms[] split;
    /** As {@link #split}, reading the shadow map; null until {@link #useSplitReceivers}. */
    private PlantUniforms[] splitReceivers;
    /** Whether the triangle levels read the shadow map this frame ({@link #shadow}). */
    private boolean mapped;
    private final boolean[] flowers;
    /** What the caster programs draw with this frame: the sun's view ({@link #casterFrame}). */
    private final PassContext caster = new PassContext();
    private int draws;
    private long instances;
    /** What the last {@link #drawTrianglesCore} counted, taken back by the {@link #drawTrianglesAgain} after it. */
    private int coreDraws;
    private long coreInstances;
    /** Whether the draw under way is the core's pass: the plants listed without a core are left out. */
    private boolean coreOnly;
    private boolean leaveOutCoreless = true;

    /**
     * Compiles program {@code k} of {@link #COUNT} (bit 0: the dither test, bit 1: line levels, bit 2:
     * flower parts). Render thread; allocates.
     */
    public static GlProgram compile(GlTracker t, int k) {
        return compile(t, k, false);
    }

    /**
     * Compiles program {@code k} as {@link #compile(GlTracker, int)}, its triangle levels reading the
     * components' images when {@code textured} ({@code TEXTURED}: a layer per vertex, sampled along the
     * part). Render thread; allocates.
     */
    public static GlProgram compile(GlTracker t, int k, boolean textured) {
        List<String> d = new ArrayList<>(3);
        if ((k & DITHER) != 0) {
            d.add("DITHER");
        }
        if ((k & FLOWERS) != 0) {
            d.add("FLOWERS");
        }
        if (textured && (k & LINES) == 0) {
            d.add("TEXTURED");
        }
        String[] defines = d.toArray(new String[0]);
        return (k & LINES) != 0
                ? GlProgram.variant(t, "plant_line.vert", "plant_line.frag", defines)
                : GlProgram.variant(t, "plant.vert", "plant.frag", defines);
    }

    /**
     * Compiles caster program {@code k} of {@link #CASTERS} (bit 0: the dither test, bit 1: flower
     * parts): {@code plant.vert} with {@code SHADOW_CASTER}, depth only. Render thread; allocates.
     */
    public static GlProgram compileCaster(GlTracker t, int k, boolean textured) {
        return GlProgram.variant(t, "plant.vert", "plant_caster.frag", textured(mapDefines("SHADOW_CASTER", k),
                textured));
    }

    /** The defines with {@code TEXTURED} added when {@code textured}. */
    private static String[] textured(String[] defines, boolean textured) {
        if (!textured) {
            return defines;
        }
        String[] more = java.util.Arrays.copyOf(defines, defines.length + 1);
        more[defines.length] = "TEXTURED";
        return more;
    }

    /** The defines of a shadow-map program: {@code role}, then DITHER for bit 0 and FLOWERS for bit 1 of k. */
    private static String[] mapDefines(String role, int k) {
        List<String> d = new ArrayList<>(3);
        d.add(role);
        if ((k & 1) != 0) {
            d.add("DITHER");
        }
        if ((k & 2) != 0) {
            d.add("FLOWERS");
        }
        return d.toArray(new String[0]);
    }

    /**
     * Compiles receiver program {@code k} of {@link #CASTERS} (bit 0: the dither test, bit 1: flower
     * parts): the triangle levels' programs with {@code SHADOW_MAP}, which read the sun's shadow map per
     * fragment. Render thread; allocates.
     */
    public static GlProgram compileReceiver(GlTracker t, int k, boolean textured) {
        return GlProgram.variant(t, "plant.vert", "plant.frag", textured(mapDefines("SHADOW_MAP", k), textured));
    }

    /**
     * Compiles split program {@code k} of {@link #CASTERS} (bit 0: the dither test, bit 1: flower parts),
     * with the shadow map read or not: the triangle levels' programs with {@code SPLIT}, which keep
     * either the opaque core of the plants or their fringe ({@code uSplit}). Render thread; allocates.
     */
    public static GlProgram compileSplit(GlTracker t, int k, boolean shadowMap, boolean textured) {
        String[] d = textured(mapDefines("SPLIT", k), textured);
        if (shadowMap) {
            String[] more = java.util.Arrays.copyOf(d, d.length + 1);
            more[d.length] = "SHADOW_MAP";
            d = more;
        }
        return GlProgram.variant(t, "plant.vert", "plant.frag", d);
    }

    /** Takes the {@link #CASTERS} split programs into use ({@link #compileSplit}, no shadow map). Render thread; allocates. */
    public void useSplit(GlProgram[] programs) {
        split = uniformsOf(programs);
    }

    /** Takes the {@link #CASTERS} split programs that read the shadow map into use. Render thread; allocates. */
    public void useSplitReceivers(GlProgram[] programs) {
        splitReceivers = uniformsOf(programs);
    }

    /** {@return whether the split programs the next draw needs are in use: with the shadow map's when it is read} */
    public boolean hasSplit() {
        return split != null && (!mapped || splitReceivers != null);
    }

    /** {@return whether {@link #useSplit} was called} */
    public boolean hasPlainSplit() {
        return split != null;
    }

    /** {@return whether {@link #useSplitReceivers} was called} */
    public boolean hasSplitReceivers() {
        return splitReceivers != null;
    }

    private static PlantUniforms[] uniformsOf(GlProgram[] programs) {
        PlantUniforms[] u = new PlantUniforms[CASTERS];
        for (int k = 0; k < CASTERS; k++) {
            u[k] = new PlantUniforms(programs[k]);
        }
        return u;
    }

    /**
     * Takes the shadow map's programs into use: {@link #CASTERS} casters (program {@code k} from
     * {@link #compileCaster}{@code (t, k)}) and as many receivers ({@link #compileReceiver}). Render
     * thread; allocates.
     */
    public void useCasters(GlProgram[] casterPrograms, GlProgram[] receiverPrograms) {
        PlantUniforms[] c = new PlantUniforms[CASTERS];
        PlantUniforms[] r = new PlantUniforms[CASTERS];
        for (int k = 0; k < CASTERS; k++) {
            c[k] = new PlantUniforms(casterPrograms[k]);
            r[k] = new PlantUniforms(receiverPrograms[k]);
        }
        casters = c;
        receivers = r;
    }

    /** {@return whether {@link #useCasters} was called} */
    public boolean hasCasters() {
        return casters != null;
    }

    /**
     * Sets the caster programs' per-frame values: as {@link #frame} with the sun's view-projection, a
     * point far toward the sun as the eye, and a pixel of one map texel at any distance (the view's
     * haze colour and frame); thin parts at least one texel wide, flower parts at their real size and
     * untilted, no thinning widening. No allocation.
     */
    void casterFrame(PlantLook look, ShadowFit at, PassContext view) {
        PassContext c = caster;
        c.viewProj = at.viewProjection();
        c.setEye((float) at.sunward(0), (float) at.sunward(1), (float) at.sunward(2));
        c.setFog(view.fogR, view.fogG, view.fogB, 0f, 1f);
        c.setLight(0f, 1f, 0f);
        c.setPixel((float) at.texelMetres(), 0f);
        c.frame = view.frame;
        for (PlantUniforms u : casters) {
            u.program.use();
            u.frame(look, c, 1f);
            glUniform1f(u.minPixels, 1f);
            glUniform1f(u.headPixels, 0f);
            glUniform1f(u.flowerTilt, 0f);
            glUniform3f(u.thin, 0f, 1f, 1f);
        }
    }

    /**
     * Draws the triangle levels' lists with the caster programs (as {@link #drawTriangles}, into the bound shadow
     * map). Counts no draws. No allocation.
     */
    public void drawCasters(PlantBatches batches, GlVertexArray[] vaos, int[] indexCount, PlantLook look,
                            int levelMask) {
        int draws0 = draws;
        long instances0 = instances;
        draw(casters, false, batches, vaos, indexCount, look, levelMask);
        draws = draws0;
        instances = instances0;
    }

    /**
     * Looks up the programs' uniforms (and leaves the last one in use).
     *
     * @param programs the {@link #COUNT} programs, program {@code k} from {@link #compile}{@code (t, k)}
     * @param flowers  per species: whether it has flower parts
     */
    public PlantPasses(GlProgram[] programs, boolean[] flowers) {
        for (int k = 0; k < COUNT; k++) {
            passes[k] = new PlantUniforms(programs[k]);
        }
        this.flowers = flowers.clone();
    }

    /**
     * Sets this frame's uniforms on every program: the camera, light and haze, the size of a pixel
     * ({@code x + distance * y} metres), the frame's distance thinning and whether the target is
     * multisampled (then no soft edge: the samples smooth the outline). Coverage is kept in alpha, for
     * blending or alpha-to-coverage. No allocation.
     */
    void frame(PlantLook look, PassContext context) {
        float alphaFloor = 0f; // coverage in alpha: to samples when multisampled, blended otherwise
        for (PlantUniforms u : passes) {
            u.program.use();
            u.frame(look, context, alphaFloor);
        }
        frame(receivers, look, context, alphaFloor);
        frame(split, look, context, alphaFloor);
        frame(splitReceivers, look, context, alphaFloor);
    }

    private static void frame(PlantUniforms[] programs, PlantLook look, PassContext context, float alphaFloor) {
        if (programs != null) {
            for (PlantUniforms u : programs) {
                u.program.use();
                u.frame(look, context, alphaFloor);
            }
        }
    }

    /**
     * Sets the sun's shadow map of the look (after {@link #frame}): while one is drawn this frame the
     * triangle levels are drawn by the receiver programs, which read it. No allocation.
     */
    public void shadow(PlantLook look) {
        mapped = look.shadow.drawn() && receivers != null;
        if (mapped) {
            for (PlantUniforms u : receivers) {
                u.program.use();
                u.shadow(look);
            }
            if (splitReceivers != null) {
                for (PlantUniforms u : splitReceivers) {
                    u.program.use();
                    u.shadow(look);
                }
            }
        }
    }

    /**
     * Draws the triangle levels' lists (through the receiver programs while a shadow map is read): per
     * list one instanced draw of its plants drawn whole, then one of its plants in a transition band;
     * leaves no vertex array bound. No allocation.
     *
     * @param batches    the frame's lists
     * @param vaos       per list: its level's mesh
     * @param indexCount per list: the mesh's index count
     * @param look       the plants' look (dry tips per species)
     * @param levelMask  bit l set: draw level l
     * @see #draws()
     */
    public void drawTriangles(PlantBatches batches, GlVertexArray[] vaos, int[] indexCount, PlantLook look,
                              int levelMask) {
        draw(mapped ? receivers : passes, false, batches, vaos, indexCount, look, levelMask);
    }

    /**
     * As {@link #drawTriangles}, with the split programs ({@link #hasSplit}): the plants' opaque core
     * ({@code core}) or their fringe; {@code overSamples}: the fringe drawn on pixel centres over a core
     * drawn on a multisampled target's samples without the soft edge, which keeps every fragment whose
     * coverage, the soft edge left out, is short of the core's ({@code uSplit} 3). The caller sets the
     * depth mask, blending and the soft edge. The fringe's draws are not counted ({@link #draws()} and
     * {@link #instances()} count each list once). No allocation.
     */
    public void drawTrianglesSplit(boolean core, boolean overSamples, PlantBatches batches, GlVertexArray[] vaos,
                                   int[] indexCount, PlantLook look, int levelMask) {
        PlantUniforms[] programs = mapped ? splitReceivers : split;
        for (PlantUniforms u : programs) {
            u.program.use();
            glUniform1f(u.split, core ? 1f : overSamples ? 3f : 2f);
        }
        int draws0 = draws;
        long instances0 = instances;
        draw(programs, false, batches, vaos, indexCount, look, levelMask);
        if (!core) {
            draws = draws0;
            instances = instances0;
        }
    }

    /**
     * Sets the alpha at or above which the triangle levels' programs write a fragment as opaque and below
     * which they write nothing, through alpha-to-coverage: the core's pass on a multisampled target
     * ({@code uCoreCut}, plant.frag); 0 turns it off. No allocation.
     *
     * @param cut in [0, 1]
     */
    public void setCoreCut(float cut) {
        setCoreCut(passes, cut);
        setCoreCut(receivers, cut);
    }

    /**
     * Sets the soft edge of blades and stems, pixels ({@code uFeather}), on every triangle program made
     * (ordinary and split): above 0 for a pass rasterised on pixel centres ({@link PlantUniforms#FEATHER}
     * on a target without samples, 0.7 for the fringe of a multisampled one), 0 for one on a
     * multisampled target's samples. Each frame's {@code frame} call sets it back from the target. No
     * allocation.
     *
     * @param feather pixels, 0 or more
     */
    public void setFeather(float feather) {
        setFeather(passes, feather);
        setFeather(receivers, feather);
        setFeather(split, feather);
        setFeather(splitReceivers, feather);
    }

    private static void setFeather(PlantUniforms[] programs, float feather) {
        set(programs, u -> u.feather, feather);
    }

    private static void setCoreCut(PlantUniforms[] programs, float cut) {
        set(programs, u -> u.coreCut, cut);
    }

    /** Sets a float uniform on every program made that has it (location at or above 0); no allocation. */
    private static void set(PlantUniforms[] programs, ToIntFunction<PlantUniforms> location, float value) {
        if (programs != null) {
            for (PlantUniforms u : programs) {
                int at = location.applyAsInt(u);
                if (at >= 0) {
                    u.program.use();
                    glUniform1f(at, value);
                }
            }
        }
    }

    /** Sets whether {@link #drawTrianglesCore} leaves out the plants listed without a core. */
    public void setLeaveOutCoreless(boolean on) {
        leaveOutCoreless = on;
    }

    /**
     * As {@link #drawTriangles}, the core's pass of a multisampled target, without the whole plants each
     * list holds first as having no core ({@link PlantBatches#coreless}); what it counts is taken back by
     * the fringe's pass after it ({@link #drawTrianglesAgain}), so that each list counts once. No
     * allocation.
     */
    public void drawTrianglesCore(PlantBatches batches, GlVertexArray[] vaos, int[] indexCount, PlantLook look,
                                  int levelMask) {
        int draws0 = draws;
        long instances0 = instances;
        coreOnly = leaveOutCoreless;
        drawTriangles(batches, vaos, indexCount, look, levelMask);
        coreOnly = false;
        coreDraws = draws - draws0;
        coreInstances = instances - instances0;
    }

    /**
     * As {@link #drawTriangles}, drawn a second time in a frame (the fringe's pass after
     * {@link #drawTrianglesCore}), so that {@link #draws()} and {@link #instances()} count each list once.
     * No allocation.
     */
    public void drawTrianglesAgain(PlantBatches batches, GlVertexArray[] vaos, int[] indexCount, PlantLook look,
                                   int levelMask) {
        drawTriangles(batches, vaos, indexCount, look, levelMask);
        draws -= coreDraws;
        instances -= coreInstances;
        coreDraws = 0;
        coreInstances = 0;
    }

    /** As {@link #drawTriangles}, the line levels' lists. No allocation. */
    public void drawLines(PlantBatches batches, GlVertexArray[] vaos, int[] indexCount, PlantLook look,
                          int levelMask) {
        draw(passes, true, batches, vaos, indexCount, look, levelMask);
    }

    private void draw(PlantUniforms[] programs, boolean lines, PlantBatches batches, GlVertexArray[] vaos,
                      int[] indexCount, PlantLook look, int levelMask) {
        for (int k = 0; k < 4; k++) {
            boolean dither = (k & 1) != 0;
            boolean flowerPass = (k & 2) != 0;
            PlantUniforms u = programs == passes
                    ? passes[(lines ? LINES : 0) | (dither ? DITHER : 0) | (flowerPass ? FLOWERS : 0)]
                    : programs[(dither ? 1 : 0) | (flowerPass ? 2 : 0)];
            boolean inUse = false;
            for (int s = 0; s < batches.speciesCount(); s++) {
                if (flowers[s] != flowerPass) {
                    continue;
                }
                for (int l = 0, levels = batches.levels(s); l < levels; l++) {
                    int li = batches.list(s, l);
                    int whole = batches.whole(li);
                    int first = dither ? whole : coreOnly ? batches.coreless(li) : 0;
                    int n = dither ? batches.count(li) - whole : whole - first;
                    if (n == 0 || indexCount[li] == 0 || (levelMask >> l & 1) == 0 || batches.lines(li) != lines) {
                        continue;
                    }
                    if (!inUse) {
                        u.program.use();
                        inUse = true;
                    }
                    glUniform1i(u.slotCount, batches.slots(s));
                    glUniform1f(u.dryTips, look.dryTips(s));
                    glUniform1i(u.componentBase, batches.componentOffset(li) + first * batches.slots(s));
                    vaos[li].bind();
                    glDrawElementsInstanced(lines ? GL_LINES : GL_TRIANGLES, indexCount[li], GL_UNSIGNED_INT, 0L, n);
                    draws++;
                    instances += n;
                }
            }
        }
        glBindVertexArray(0);
    }

    /** Starts counting the draws and instances of a frame anew. */
    public void resetCounts() {
        draws = 0;
        instances = 0;
    }

    /** {@return the instanced draw calls issued since {@link #resetCounts}} */
    public int draws() {
        return draws;
    }

    /** {@return the instances (plants at a level) drawn since {@link #resetCounts}} */
    public long instances() {
        return instances;
    }
}
