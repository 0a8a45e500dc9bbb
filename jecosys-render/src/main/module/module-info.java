/**
 * JEcoSys render: draws a JEcoSys simulation with OpenGL 3.3 (LWJGL) into a game's context or its
 * own. Exports {@code org.jecosys.render} only; {@code render.gl}, {@code render.plant},
 * {@code render.ground}, {@code render.overlay} and {@code render.internal} are internal. LWJGL's
 * EGL (headless contexts) and STB (PNG files) bindings are optional: a program that uses them
 * requires them itself. The jar works on the class path as well.
 */
module org.jecosys.render {
    requires transitive org.jecosys.core;
    requires transitive org.lwjgl;
    requires transitive org.lwjgl.opengl;
    requires org.lwjgl.glfw;
    requires java.logging;
    requires static org.lwjgl.egl;
    requires static org.lwjgl.stb;

    exports org.jecosys.render;
}
