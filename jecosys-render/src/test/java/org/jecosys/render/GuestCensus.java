package org.jecosys.render;

import static org.lwjgl.opengl.GL11C.glGetFloatv;
import static org.lwjgl.opengl.GL11C.glGetInteger;
import static org.lwjgl.opengl.GL11C.glIsEnabled;

import java.nio.FloatBuffer;
import java.util.LinkedHashMap;
import java.util.Map;
import org.lwjgl.opengl.GL;
import org.lwjgl.opengl.GL11C;
import org.lwjgl.opengl.GL12C;
import org.lwjgl.opengl.GL13C;
import org.lwjgl.opengl.GL14C;
import org.lwjgl.opengl.GL15C;
import org.lwjgl.opengl.GL20C;
import org.lwjgl.opengl.GL21C;
import org.lwjgl.opengl.GL30C;
import org.lwjgl.opengl.GL31C;
import org.lwjgl.opengl.GL32C;
import org.lwjgl.opengl.GL33C;
import org.lwjgl.opengl.GL43C;
import org.lwjgl.system.MemoryStack;

/**
 * A census of the GL state a host (a game, an engine's state cache) relies on, read from the driver:
 * every binding, capability and value that a renderer could change, well beyond what the library's
 * renderers touch, so that a leak anywhere shows. {@link #take()} reads it; {@link #hostile()} sets
 * each settable entry to a value no renderer would choose, as a careless or unusual host might leave
 * it. Render thread; allocates.
 */
final class GuestCensus {
    private GuestCensus() {
    }

    private static final int[] INTS = {GL20C.GL_CURRENT_PROGRAM, GL30C.GL_VERTEX_ARRAY_BINDING,
        GL15C.GL_ARRAY_BUFFER_BINDING, GL15C.GL_ELEMENT_ARRAY_BUFFER_BINDING, GL31C.GL_TEXTURE_BUFFER,
        GL21C.GL_PIXEL_UNPACK_BUFFER_BINDING, GL21C.GL_PIXEL_PACK_BUFFER_BINDING, GL31C.GL_UNIFORM_BUFFER_BINDING,
        GL31C.GL_COPY_READ_BUFFER, GL31C.GL_COPY_WRITE_BUFFER,
        GL30C.GL_TRANSFORM_FEEDBACK_BUFFER_BINDING, GL30C.GL_RENDERBUFFER_BINDING, GL30C.GL_DRAW_FRAMEBUFFER_BINDING,
        GL30C.GL_READ_FRAMEBUFFER_BINDING, GL13C.GL_ACTIVE_TEXTURE, GL11C.GL_DEPTH_FUNC, GL11C.GL_DEPTH_WRITEMASK,
        GL14C.GL_BLEND_SRC_RGB, GL14C.GL_BLEND_DST_RGB, GL14C.GL_BLEND_SRC_ALPHA, GL14C.GL_BLEND_DST_ALPHA,
        GL20C.GL_BLEND_EQUATION_RGB, GL20C.GL_BLEND_EQUATION_ALPHA, GL11C.GL_CULL_FACE_MODE, GL11C.GL_FRONT_FACE,
        GL11C.GL_POLYGON_MODE, GL11C.GL_STENCIL_FUNC, GL11C.GL_STENCIL_REF, GL11C.GL_STENCIL_VALUE_MASK,
        GL11C.GL_STENCIL_FAIL, GL11C.GL_STENCIL_PASS_DEPTH_FAIL, GL11C.GL_STENCIL_PASS_DEPTH_PASS,
        GL11C.GL_STENCIL_WRITEMASK, GL20C.GL_STENCIL_BACK_FUNC, GL20C.GL_STENCIL_BACK_WRITEMASK,
        GL11C.GL_STENCIL_CLEAR_VALUE, GL11C.GL_LOGIC_OP_MODE, GL32C.GL_PROVOKING_VERTEX,
        GL31C.GL_PRIMITIVE_RESTART_INDEX, GL11C.GL_PACK_ALIGNMENT, GL11C.GL_PACK_ROW_LENGTH,
        GL11C.GL_UNPACK_ALIGNMENT, GL11C.GL_UNPACK_ROW_LENGTH, GL11C.GL_UNPACK_SKIP_PIXELS, GL11C.GL_UNPACK_SKIP_ROWS,
        GL12C.GL_UNPACK_IMAGE_HEIGHT, GL12C.GL_UNPACK_SKIP_IMAGES, GL20C.GL_DRAW_BUFFER0, GL11C.GL_READ_BUFFER};
    private static final String[] INT_NAMES = {"program", "vertex array", "array buffer", "element buffer",
        "texture buffer", "pixel unpack buffer", "pixel pack buffer", "uniform buffer", "copy read buffer",
        "copy write buffer", "transform feedback buffer", "renderbuffer", "draw framebuffer", "read framebuffer",
        "active texture", "depth func", "depth mask", "blend src rgb", "blend dst rgb", "blend src alpha",
        "blend dst alpha", "blend equation rgb", "blend equation alpha", "cull face mode", "front face",
        "polygon mode", "stencil func", "stencil ref", "stencil value mask", "stencil fail", "stencil depth fail",
        "stencil depth pass", "stencil write mask", "stencil back func", "stencil back write mask",
        "stencil clear", "logic op", "provoking vertex", "primitive restart index", "pack alignment",
        "pack row length", "unpack alignment", "unpack row length", "unpack skip pixels", "unpack skip rows",
        "unpack image height", "unpack skip images", "draw buffer 0", "read buffer"};
    private static final int[] FLOATS = {GL11C.GL_POLYGON_OFFSET_FACTOR, GL11C.GL_POLYGON_OFFSET_UNITS,
        GL11C.GL_LINE_WIDTH, GL11C.GL_POINT_SIZE, GL13C.GL_SAMPLE_COVERAGE_VALUE, GL11C.GL_DEPTH_CLEAR_VALUE};
    private static final String[] FLOAT_NAMES = {"polygon offset factor", "polygon offset units", "line width",
        "point size", "sample coverage value", "depth clear"};
    private static final int[] VECTORS = {GL11C.GL_DEPTH_RANGE, GL14C.GL_BLEND_COLOR, GL11C.GL_COLOR_CLEAR_VALUE,
        GL11C.GL_VIEWPORT, GL11C.GL_SCISSOR_BOX, GL11C.GL_COLOR_WRITEMASK};
    private static final String[] VECTOR_NAMES = {"depth range", "blend colour", "clear colour", "viewport",
        "scissor box", "colour mask"};
    private static final int[] CAPS = {GL11C.GL_DEPTH_TEST, GL11C.GL_CULL_FACE, GL11C.GL_BLEND, GL11C.GL_SCISSOR_TEST,
        GL11C.GL_STENCIL_TEST, GL11C.GL_POLYGON_OFFSET_FILL, GL11C.GL_POLYGON_OFFSET_LINE,
        GL11C.GL_POLYGON_OFFSET_POINT, GL32C.GL_PROGRAM_POINT_SIZE, GL13C.GL_SAMPLE_ALPHA_TO_COVERAGE,
        GL13C.GL_SAMPLE_ALPHA_TO_ONE, GL13C.GL_SAMPLE_COVERAGE, GL32C.GL_SAMPLE_MASK, GL13C.GL_MULTISAMPLE,
        GL30C.GL_FRAMEBUFFER_SRGB, GL11C.GL_COLOR_LOGIC_OP, GL31C.GL_PRIMITIVE_RESTART, GL32C.GL_DEPTH_CLAMP,
        GL11C.GL_DITHER, GL11C.GL_LINE_SMOOTH, GL11C.GL_POLYGON_SMOOTH, GL30C.GL_RASTERIZER_DISCARD,
        GL32C.GL_TEXTURE_CUBE_MAP_SEAMLESS, GL30C.GL_CLIP_DISTANCE0, GL30C.GL_CLIP_DISTANCE0 + 1,
        GL30C.GL_CLIP_DISTANCE0 + 2, GL30C.GL_CLIP_DISTANCE0 + 3, GL30C.GL_CLIP_DISTANCE0 + 4,
        GL30C.GL_CLIP_DISTANCE0 + 5, GL30C.GL_CLIP_DISTANCE0 + 6, GL30C.GL_CLIP_DISTANCE0 + 7};
    private static final String[] CAP_NAMES = {"depth test", "cull face", "blend", "scissor test", "stencil test",
        "polygon offset fill", "polygon offset line", "polygon offset point", "program point size",
        "alpha to coverage", "alpha to one", "sample coverage", "sample mask", "multisample", "framebuffer sRGB",
        "colour logic op", "primitive restart", "depth clamp", "dither", "line smooth", "polygon smooth",
        "rasterizer discard", "seamless cube maps", "clip distance 0", "clip distance 1", "clip distance 2",
        "clip distance 3", "clip distance 4", "clip distance 5", "clip distance 6", "clip distance 7"};
    /** Texture units whose bindings are counted. */
    static final int UNITS = 16;

    /** {@return every entry of the census, by name} */
    static Map<String, String> take() {
        Map<String, String> s = new LinkedHashMap<>();
        for (int i = 0; i < INTS.length; i++) {
            s.put(INT_NAMES[i], Integer.toString(glGetInteger(INTS[i])));
        }
        try (MemoryStack stack = MemoryStack.stackPush()) {
            FloatBuffer f = stack.mallocFloat(16);
            for (int i = 0; i < FLOATS.length; i++) {
                glGetFloatv(FLOATS[i], f.clear());
                s.put(FLOAT_NAMES[i], Float.toString(f.get(0)));
            }
            for (int i = 0; i < VECTORS.length; i++) {
                f.clear();
                for (int k = 0; k < 4; k++) {
                    f.put(k, Float.NaN);
                }
                glGetFloatv(VECTORS[i], f);
                s.put(VECTOR_NAMES[i], f.get(0) + "," + f.get(1) + "," + f.get(2) + "," + f.get(3));
            }
        }
        for (int i = 0; i < CAPS.length; i++) {
            s.put(CAP_NAMES[i], Boolean.toString(glIsEnabled(CAPS[i])));
        }
        s.put("transform feedback buffer 0", Integer.toString(GL30C.glGetIntegeri(
                GL30C.GL_TRANSFORM_FEEDBACK_BUFFER_BINDING, 0)));
        s.put("transform feedback buffer 0 start", Long.toString(GL32C.glGetInteger64i(
                GL30C.GL_TRANSFORM_FEEDBACK_BUFFER_START, 0)));
        s.put("uniform buffer 0", Integer.toString(GL30C.glGetIntegeri(GL31C.GL_UNIFORM_BUFFER_BINDING, 0)));
        if (GL.getCapabilities().OpenGL43) {
            s.put("shader storage buffer", Integer.toString(glGetInteger(GL43C.GL_SHADER_STORAGE_BUFFER_BINDING)));
            s.put("shader storage buffer 0", Integer.toString(GL30C.glGetIntegeri(
                    GL43C.GL_SHADER_STORAGE_BUFFER_BINDING, 0)));
        }
        int active = glGetInteger(GL13C.GL_ACTIVE_TEXTURE);
        for (int u = 0; u < UNITS; u++) {
            GL13C.glActiveTexture(GL13C.GL_TEXTURE0 + u);
            s.put("unit " + u + " buffer texture", Integer.toString(glGetInteger(GL31C.GL_TEXTURE_BINDING_BUFFER)));
            s.put("unit " + u + " 2D texture", Integer.toString(glGetInteger(GL11C.GL_TEXTURE_BINDING_2D)));
            s.put("unit " + u + " sampler", Integer.toString(glGetInteger(GL33C.GL_SAMPLER_BINDING)));
        }
        GL13C.glActiveTexture(active);
        return s;
    }

    /**
     * A host that left unusual values everywhere: its own program, vertex array, buffers on every
     * target, textures and sampler objects on every unit, blending subtracting, a partial colour mask,
     * polygon offset and line mode, a stencil test that fails everything, sRGB writes, a logic op,
     * sample mask and coverage, primitive restart, clip distances, odd pixel-store settings and a
     * bound unpack buffer. {@link #close()} deletes its objects and puts the defaults back.
     */
    static final class Hostile implements AutoCloseable {
        private final int program = GL20C.glCreateProgram();
        private final int vao = GL30C.glGenVertexArrays();
        private final int[] buffers = new int[8];
        private final int[] textures = new int[2 * UNITS];
        private final int[] samplers = new int[UNITS];

        Hostile(boolean breakDrawing) {
            GL15C.glGenBuffers(buffers);
            GL11C.glGenTextures(textures);
            GL33C.glGenSamplers(samplers);
            GL30C.glBindVertexArray(vao);
            GL15C.glBindBuffer(GL15C.GL_ELEMENT_ARRAY_BUFFER, buffers[0]);
            GL15C.glBufferData(GL15C.GL_ELEMENT_ARRAY_BUFFER, 64, GL15C.GL_STATIC_DRAW);
            int[] targets = {GL15C.GL_ARRAY_BUFFER, GL31C.GL_TEXTURE_BUFFER, GL21C.GL_PIXEL_UNPACK_BUFFER,
                GL21C.GL_PIXEL_PACK_BUFFER, GL31C.GL_UNIFORM_BUFFER, GL31C.GL_COPY_READ_BUFFER,
                GL31C.GL_COPY_WRITE_BUFFER};
            for (int i = 0; i < targets.length; i++) {
                GL15C.glBindBuffer(targets[i], buffers[1 + i]);
                GL15C.glBufferData(targets[i], 1 << 16, GL15C.GL_STATIC_DRAW);
            }
            GL30C.glBindBufferRange(GL30C.GL_TRANSFORM_FEEDBACK_BUFFER, 0, buffers[3], 256, 1024);
            GL30C.glBindBufferBase(GL31C.GL_UNIFORM_BUFFER, 0, buffers[5]);
            if (GL.getCapabilities().OpenGL43) {
                GL30C.glBindBufferRange(GL43C.GL_SHADER_STORAGE_BUFFER, 0, buffers[6], 0, 64);
                GL15C.glBindBuffer(GL43C.GL_SHADER_STORAGE_BUFFER, buffers[7]);
            }
            GL15C.glBindBuffer(GL30C.GL_TRANSFORM_FEEDBACK_BUFFER, buffers[4]);
            for (int u = 0; u < UNITS; u++) {
                GL13C.glActiveTexture(GL13C.GL_TEXTURE0 + u);
                GL11C.glBindTexture(GL31C.GL_TEXTURE_BUFFER, textures[2 * u]);
                GL31C.glTexBuffer(GL31C.GL_TEXTURE_BUFFER, GL30C.GL_R32F, buffers[2]);
                GL11C.glBindTexture(GL11C.GL_TEXTURE_2D, textures[2 * u + 1]);
                GL33C.glSamplerParameteri(samplers[u], GL11C.GL_TEXTURE_MIN_FILTER, GL11C.GL_NEAREST);
                GL33C.glSamplerParameteri(samplers[u], GL11C.GL_TEXTURE_MAG_FILTER, GL11C.GL_NEAREST);
                GL33C.glSamplerParameteri(samplers[u], GL11C.GL_TEXTURE_WRAP_S, GL13C.GL_CLAMP_TO_BORDER);
                GL33C.glBindSampler(u, samplers[u]);
            }
            GL13C.glActiveTexture(GL13C.GL_TEXTURE0 + 11);
            GL20C.glUseProgram(0);
            GL11C.glEnable(GL11C.GL_BLEND);
            GL14C.glBlendFuncSeparate(GL11C.GL_ONE, GL11C.GL_ONE, GL11C.GL_ZERO, GL11C.GL_DST_ALPHA);
            GL20C.glBlendEquationSeparate(GL14C.GL_FUNC_REVERSE_SUBTRACT, GL14C.GL_MAX);
            GL14C.glBlendColor(0.1f, 0.2f, 0.3f, 0.4f);
            GL11C.glEnable(GL11C.GL_CULL_FACE);
            GL11C.glCullFace(GL11C.GL_FRONT);
            GL11C.glFrontFace(GL11C.GL_CW);
            GL11C.glDepthFunc(GL11C.GL_GREATER);
            GL11C.glDepthMask(false);
            GL11C.glDisable(GL11C.GL_DEPTH_TEST);
            GL11C.glEnable(GL11C.GL_POLYGON_OFFSET_FILL);
            GL11C.glEnable(GL11C.GL_POLYGON_OFFSET_LINE);
            GL11C.glPolygonOffset(4f, 8f);
            GL11C.glLineWidth(1f);
            GL20C.glStencilFuncSeparate(GL11C.GL_FRONT_AND_BACK, GL11C.GL_NEVER, 7, 0x3f);
            GL20C.glStencilOpSeparate(GL11C.GL_FRONT_AND_BACK, GL11C.GL_INCR, GL11C.GL_DECR, GL11C.GL_INVERT);
            GL11C.glStencilMask(0x0f);
            GL11C.glClearStencil(3);
            GL11C.glClearDepth(0.75);
            GL11C.glLogicOp(GL11C.GL_XOR);
            GL32C.glProvokingVertex(GL32C.GL_FIRST_VERTEX_CONVENTION);
            GL31C.glPrimitiveRestartIndex(12345);
            GL11C.glPixelStorei(GL11C.GL_PACK_ALIGNMENT, 2);
            GL11C.glPixelStorei(GL11C.GL_PACK_ROW_LENGTH, 17);
            GL11C.glPixelStorei(GL11C.GL_UNPACK_ALIGNMENT, 8);
            GL11C.glPixelStorei(GL11C.GL_UNPACK_ROW_LENGTH, 13);
            GL11C.glPixelStorei(GL11C.GL_UNPACK_SKIP_PIXELS, 2);
            GL11C.glPixelStorei(GL11C.GL_UNPACK_SKIP_ROWS, 3);
            GL11C.glPixelStorei(GL12C.GL_UNPACK_IMAGE_HEIGHT, 5);
            GL11C.glPixelStorei(GL12C.GL_UNPACK_SKIP_IMAGES, 1);
            GL13C.glSampleCoverage(0.3f, true);
            GL11C.glEnable(GL30C.GL_FRAMEBUFFER_SRGB);
            GL11C.glEnable(GL31C.GL_PRIMITIVE_RESTART);
            GL11C.glEnable(GL32C.GL_PROGRAM_POINT_SIZE);
            GL11C.glEnable(GL32C.GL_TEXTURE_CUBE_MAP_SEAMLESS);
            GL11C.glDisable(GL11C.GL_DITHER);
            GL11C.glEnable(GL30C.GL_CLIP_DISTANCE0 + 2);
            GL11C.glEnable(GL30C.GL_CLIP_DISTANCE0 + 5);
            GL11C.glClearColor(0.9f, 0.1f, 0.2f, 0.5f);
            GL11C.glDepthRange(0.0, 1.0);
            if (breakDrawing) {
                // what would spoil the plants if the renderer inherited it
                GL11C.glColorMask(false, true, false, false);
                GL11C.glEnable(GL11C.GL_STENCIL_TEST);
                GL11C.glEnable(GL11C.GL_COLOR_LOGIC_OP);
                GL11C.glEnable(GL13C.GL_SAMPLE_COVERAGE);
                GL11C.glEnable(GL32C.GL_SAMPLE_MASK);
                GL32C.glSampleMaski(0, 0x1);
                GL11C.glPolygonMode(GL11C.GL_FRONT_AND_BACK, GL11C.GL_LINE);
                GL11C.glEnable(GL32C.GL_DEPTH_CLAMP);
                GL11C.glDisable(GL13C.GL_MULTISAMPLE); // the plants' cores would lose their samples
            }
        }

        @Override
        public void close() {
            GL30C.glBindVertexArray(0);
            GL20C.glDeleteProgram(program);
            GL30C.glDeleteVertexArrays(vao);
            GL15C.glDeleteBuffers(buffers);
            GL11C.glDeleteTextures(textures);
            for (int u = 0; u < UNITS; u++) {
                GL33C.glBindSampler(u, 0);
            }
            GL33C.glDeleteSamplers(samplers);
            GL13C.glActiveTexture(GL13C.GL_TEXTURE0);
            GL11C.glEnable(GL13C.GL_MULTISAMPLE);
            GL11C.glDisable(GL11C.GL_BLEND);
            GL14C.glBlendFuncSeparate(GL11C.GL_ONE, GL11C.GL_ZERO, GL11C.GL_ONE, GL11C.GL_ZERO);
            GL20C.glBlendEquationSeparate(GL14C.GL_FUNC_ADD, GL14C.GL_FUNC_ADD);
            GL14C.glBlendColor(0, 0, 0, 0);
            GL11C.glDisable(GL11C.GL_CULL_FACE);
            GL11C.glCullFace(GL11C.GL_BACK);
            GL11C.glFrontFace(GL11C.GL_CCW);
            GL11C.glDepthFunc(GL11C.GL_LESS);
            GL11C.glDepthMask(true);
            GL11C.glDisable(GL11C.GL_POLYGON_OFFSET_FILL);
            GL11C.glDisable(GL11C.GL_POLYGON_OFFSET_LINE);
            GL11C.glPolygonOffset(0f, 0f);
            GL20C.glStencilFuncSeparate(GL11C.GL_FRONT_AND_BACK, GL11C.GL_ALWAYS, 0, 0xffffffff);
            GL20C.glStencilOpSeparate(GL11C.GL_FRONT_AND_BACK, GL11C.GL_KEEP, GL11C.GL_KEEP, GL11C.GL_KEEP);
            GL11C.glStencilMask(0xffffffff);
            GL11C.glClearStencil(0);
            GL11C.glClearDepth(1.0);
            GL11C.glLogicOp(GL11C.GL_COPY);
            GL32C.glProvokingVertex(GL32C.GL_LAST_VERTEX_CONVENTION);
            GL31C.glPrimitiveRestartIndex(0);
            GL11C.glPixelStorei(GL11C.GL_PACK_ALIGNMENT, 4);
            GL11C.glPixelStorei(GL11C.GL_PACK_ROW_LENGTH, 0);
            GL11C.glPixelStorei(GL11C.GL_UNPACK_ALIGNMENT, 4);
            GL11C.glPixelStorei(GL11C.GL_UNPACK_ROW_LENGTH, 0);
            GL11C.glPixelStorei(GL11C.GL_UNPACK_SKIP_PIXELS, 0);
            GL11C.glPixelStorei(GL11C.GL_UNPACK_SKIP_ROWS, 0);
            GL11C.glPixelStorei(GL12C.GL_UNPACK_IMAGE_HEIGHT, 0);
            GL11C.glPixelStorei(GL12C.GL_UNPACK_SKIP_IMAGES, 0);
            GL13C.glSampleCoverage(1f, false);
            GL11C.glDisable(GL30C.GL_FRAMEBUFFER_SRGB);
            GL11C.glDisable(GL31C.GL_PRIMITIVE_RESTART);
            GL11C.glDisable(GL32C.GL_PROGRAM_POINT_SIZE);
            GL11C.glDisable(GL32C.GL_TEXTURE_CUBE_MAP_SEAMLESS);
            GL11C.glEnable(GL11C.GL_DITHER);
            GL11C.glDisable(GL30C.GL_CLIP_DISTANCE0 + 2);
            GL11C.glDisable(GL30C.GL_CLIP_DISTANCE0 + 5);
            GL11C.glClearColor(0f, 0f, 0f, 0f);
            GL11C.glColorMask(true, true, true, true);
            GL11C.glDisable(GL11C.GL_STENCIL_TEST);
            GL11C.glDisable(GL11C.GL_COLOR_LOGIC_OP);
            GL11C.glDisable(GL13C.GL_SAMPLE_COVERAGE);
            GL11C.glDisable(GL32C.GL_SAMPLE_MASK);
            GL32C.glSampleMaski(0, 0xffffffff);
            GL11C.glPolygonMode(GL11C.GL_FRONT_AND_BACK, GL11C.GL_FILL);
            GL11C.glDisable(GL32C.GL_DEPTH_CLAMP);
        }
    }
}
