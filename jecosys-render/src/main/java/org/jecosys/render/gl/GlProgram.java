package org.jecosys.render.gl;

import static org.lwjgl.opengl.GL11C.glGetInteger;
import static org.lwjgl.opengl.GL20C.GL_COMPILE_STATUS;
import static org.lwjgl.opengl.GL20C.GL_CURRENT_PROGRAM;
import static org.lwjgl.opengl.GL20C.GL_FRAGMENT_SHADER;
import static org.lwjgl.opengl.GL20C.GL_LINK_STATUS;
import static org.lwjgl.opengl.GL20C.GL_VERTEX_SHADER;
import static org.lwjgl.opengl.GL20C.glAttachShader;
import static org.lwjgl.opengl.GL20C.glCompileShader;
import static org.lwjgl.opengl.GL20C.glCreateProgram;
import static org.lwjgl.opengl.GL20C.glCreateShader;
import static org.lwjgl.opengl.GL20C.glDeleteProgram;
import static org.lwjgl.opengl.GL20C.glDeleteShader;
import static org.lwjgl.opengl.GL20C.glDetachShader;
import static org.lwjgl.opengl.GL20C.glGetProgramInfoLog;
import static org.lwjgl.opengl.GL20C.glGetProgrami;
import static org.lwjgl.opengl.GL20C.glGetShaderInfoLog;
import static org.lwjgl.opengl.GL20C.glGetShaderi;
import static org.lwjgl.opengl.GL20C.glGetUniformLocation;
import static org.lwjgl.opengl.GL20C.glShaderSource;
import static org.lwjgl.opengl.GL20C.glUseProgram;
import static org.lwjgl.opengl.GL43C.GL_COMPUTE_SHADER;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;

/**
 * A linked shader program from {@code src/main/resources/org/jecosys/render/shaders/}. Compile and
 * link errors fail fast with the driver's log. Render thread only; look uniform locations up once
 * with {@link #uniform} at setup, not per frame.
 */
public final class GlProgram extends GlResource {
    private final String name;

    /**
     * Compiles and links {@code shaders/<vertex>} and {@code shaders/<fragment>}.
     *
     * @param tracker  counts the object
     * @param vertex   vertex shader resource name, e.g. {@code "plant.vert"}
     * @param fragment fragment shader resource name
     * @throws IllegalStateException with the driver's log when compiling or linking fails, or a
     *                               resource is missing
     */
    public GlProgram(GlTracker tracker, String vertex, String fragment) {
        this(tracker, new String[] {vertex, fragment}, new String[0], new String[0]);
    }

    /**
     * Compiles and links a program whose vertex shader's outputs are captured by transform feedback
     * (OpenGL 3.0+), interleaved in the order given; with no fragment shader when {@code fragment}
     * is null (the program is then used with rasterisation discarded). Render thread; allocates.
     *
     * @param tracker  counts the live GL objects
     * @param vertex   vertex shader resource name
     * @param fragment fragment shader resource name, or null for none
     * @param captured names of the vertex outputs written to the transform feedback buffer, in order
     *                 (none: an ordinary program)
     * @throws IllegalStateException when a shader does not compile or the program does not link
     */
    public GlProgram(GlTracker tracker, String vertex, String fragment, String... captured) {
        this(tracker, new String[] {vertex, fragment}, new String[0], captured.clone());
    }

    /**
     * Compiles and links a variant of {@code shaders/<vertex>} and {@code shaders/<fragment>}: each
     * name in {@code defines} is defined ({@code #define NAME}) in both shaders, right after their
     * {@code #version} line, for {@code #ifdef} in the source. Render thread; allocates.
     *
     * @param tracker  counts the object
     * @param vertex   vertex shader resource name
     * @param fragment fragment shader resource name
     * @param defines  preprocessor names to define, each a GLSL identifier
     * @return the linked program
     * @throws IllegalArgumentException when a define is not an identifier
     * @throws IllegalStateException    with the driver's log when compiling or linking fails
     */
    public static GlProgram variant(GlTracker tracker, String vertex, String fragment, String... defines) {
        return new GlProgram(tracker, new String[] {vertex, fragment}, checked(defines), new String[0]);
    }

    /**
     * Compiles and links a variant (as {@link #variant}) of a vertex shader with no fragment shader
     * whose outputs are captured by transform feedback, interleaved in the order given (as the
     * constructor with captured outputs). Render thread; allocates.
     *
     * @param tracker  counts the object
     * @param vertex   vertex shader resource name
     * @param defines  preprocessor names to define, each a GLSL identifier
     * @param captured names of the vertex outputs written to the transform feedback buffer, in order
     * @return the linked program
     * @throws IllegalArgumentException when a define is not an identifier
     * @throws IllegalStateException    with the driver's log when compiling or linking fails
     */
    public static GlProgram captureVariant(GlTracker tracker, String vertex, String[] defines, String... captured) {
        return new GlProgram(tracker, new String[] {vertex, null}, checked(defines), captured.clone());
    }

    /**
     * Compiles and links a compute program (OpenGL 4.3+) from {@code shaders/<compute>}, with each
     * name in {@code defines} defined after its {@code #version} line. Render thread; allocates.
     *
     * @param tracker counts the object
     * @param compute compute shader resource name, e.g. {@code "plant_resolve.comp"}
     * @param defines preprocessor names to define, each a GLSL identifier
     * @return the linked program
     * @throws IllegalArgumentException when a define is not an identifier
     * @throws IllegalStateException    with the driver's log when compiling or linking fails
     */
    public static GlProgram compute(GlTracker tracker, String compute, String... defines) {
        return new GlProgram(tracker, new String[] {null, null, compute}, checked(defines), new String[0]);
    }

    private static String[] checked(String[] defines) {
        for (String d : defines) {
            if (!d.matches("[A-Za-z_][A-Za-z0-9_]*")) {
                throw new IllegalArgumentException("shader define must be an identifier, got '" + d + "'");
            }
        }
        return defines.clone();
    }

    /** Stages by index in {@code shaders}: vertex, fragment, compute; null = none. */
    private static final int[] STAGES = {GL_VERTEX_SHADER, GL_FRAGMENT_SHADER, GL_COMPUTE_SHADER};

    private GlProgram(GlTracker tracker, String[] shaders, String[] defines, String[] captured) {
        super(tracker, glCreateProgram());
        StringBuilder label = new StringBuilder();
        for (String s : shaders) {
            if (s != null) {
                label.append(label.length() == 0 ? "" : "+").append(s);
            }
        }
        this.name = label + (defines.length == 0 ? "" : " " + String.join(",", defines));
        int[] made = new int[shaders.length];
        try {
            for (int k = 0; k < shaders.length; k++) {
                if (shaders[k] != null) {
                    made[k] = compile(STAGES[k], shaders[k], defines);
                    glAttachShader(id(), made[k]);
                }
            }
            if (captured.length > 0) {
                org.lwjgl.opengl.GL30C.glTransformFeedbackVaryings(id(), captured,
                        org.lwjgl.opengl.GL30C.GL_INTERLEAVED_ATTRIBS);
            }
            org.lwjgl.opengl.GL20C.glLinkProgram(id());
            if (glGetProgrami(id(), GL_LINK_STATUS) == 0) {
                throw new IllegalStateException("linking " + name + " failed: " + glGetProgramInfoLog(id()));
            }
            for (int shader : made) {
                if (shader != 0) {
                    glDetachShader(id(), shader);
                }
            }
        } catch (RuntimeException e) {
            close();
            throw e;
        } finally {
            for (int shader : made) {
                if (shader != 0) {
                    glDeleteShader(shader);
                }
            }
        }
    }

    /**
     * Reads a shader's source from the classpath, replacing each line {@code #include "name"} by the
     * text of the shader resource {@code name}, itself expanded the same way (at most 4 deep; a file
     * is included once, later includes of it are dropped). Allocates.
     */
    public static String source(String resource) {
        StringBuilder out = new StringBuilder(8192);
        expand(resource, out, new java.util.HashSet<>(), 0);
        return out.toString();
    }

    private static void expand(String resource, StringBuilder out, java.util.Set<String> seen, int depth) {
        String text = raw(resource);
        if (!text.contains("#include")) {
            out.append(text);
            return;
        }
        for (String line : text.split("\n", -1)) {
            String t = line.strip();
            if (t.startsWith("#include \"") && t.endsWith("\"") && t.length() > 11) {
                String name = t.substring(10, t.length() - 1);
                if (depth >= 4) {
                    throw new IllegalStateException("shader " + resource + ": includes nest deeper than 4");
                }
                if (seen.add(name)) {
                    expand(name, out, seen, depth + 1);
                    out.append('\n');
                }
            } else {
                out.append(line).append('\n');
            }
        }
    }

    private static String raw(String resource) {
        try (InputStream in = GlProgram.class.getResourceAsStream("/org/jecosys/render/shaders/" + resource)) {
            if (in == null) {
                throw new IllegalStateException("shader resource org/jecosys/render/shaders/" + resource + " is missing");
            }
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new UncheckedIOException("reading shader " + resource, e);
        }
    }

    /** The expanded source with {@code #define}s after its first line (the {@code #version}). */
    public static String variantSource(String resource, String... defines) {
        String text = source(resource);
        if (defines.length == 0) {
            return text;
        }
        int eol = text.indexOf('\n');
        StringBuilder out = new StringBuilder(text.length() + 32 * defines.length);
        out.append(text, 0, eol + 1);
        for (String d : defines) {
            out.append("#define ").append(d).append('\n');
        }
        return out.append(text, eol + 1, text.length()).toString();
    }

    private static int compile(int type, String resource, String[] defines) {
        int s = glCreateShader(type);
        glShaderSource(s, variantSource(resource, defines));
        glCompileShader(s);
        if (glGetShaderi(s, GL_COMPILE_STATUS) == 0) {
            String log = glGetShaderInfoLog(s);
            glDeleteShader(s);
            throw new IllegalStateException("compiling shader " + resource + " failed: " + log);
        }
        return s;
    }

    /** Makes it the current program. */
    public void use() {
        glUseProgram(id());
    }

    /**
     * The location of an active uniform. Setup time, not per frame.
     *
     * @param uniform the uniform's name in the shaders
     * @return its location, &gt;= 0
     * @throws IllegalStateException when the program has no such active uniform
     */
    public int uniform(String uniform) {
        int loc = glGetUniformLocation(id(), uniform);
        if (loc < 0) {
            throw new IllegalStateException(name + " has no active uniform '" + uniform + "'");
        }
        return loc;
    }

    /**
     * The location of a uniform the linker may have dropped (a shared include a program uses only
     * in part), or -1, which {@code glUniform*} ignores. Render thread; no allocation.
     *
     * @param uniform the uniform's name
     * @return its location, or -1 when the program has no such active uniform
     */
    public int optionalUniform(String uniform) {
        return glGetUniformLocation(id(), uniform);
    }

    @Override
    public void delete(int name) {
        // a program in use is only flagged for deletion and lives on until another is used: leave none in use
        if (glGetInteger(GL_CURRENT_PROGRAM) == name) {
            glUseProgram(0);
        }
        glDeleteProgram(name);
    }
}
