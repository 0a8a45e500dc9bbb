package org.jecosys.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import javax.tools.JavaCompiler;
import javax.tools.ToolProvider;
import org.jecosys.sim.Frame;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The module descriptors work: a small named module that {@code requires org.jecosys.render}
 * compiles and runs on the module path with jecosys-core, jecosys-render and their dependencies
 * (JOML, Jackson, LWJGL) as named or automatic modules. It steps a simulation of
 * {@code scenes/c1.xml} (no GL), sees the API packages exported, the internal ones not, and is
 * refused an internal package at compile time. (The rest of the tests run on the class path.)
 */
class ModulePathConsumerTest {
    private static final String DESCRIPTOR = "module consumer {\n    requires org.jecosys.render;\n}\n";

    private static final String MAIN = """
            package consumer;

            import java.nio.file.Path;
            import org.jecosys.math.MatrixCamera;
            import org.jecosys.math.Progress;
            import org.jecosys.render.SceneRenderer;
            import org.jecosys.scene.Scene;
            import org.jecosys.scene.SceneFiles;
            import org.jecosys.scene.Scenes;
            import org.jecosys.sim.Frame;
            import org.jecosys.sim.Simulation;

            public final class Main {
                public static void main(String[] args) throws Exception {
                    Scene scene = SceneFiles.read(Path.of(args[0]));
                    try (Simulation sim = Scenes.simulation(scene, 0, Progress.NONE)) {
                        MatrixCamera camera = new MatrixCamera();
                        for (int i = 0; i < 10; i++) {
                            sim.step(1 / 30.0, camera);
                        }
                        Frame f = sim.latestFrame();
                        Module render = SceneRenderer.class.getModule();
                        Module core = Frame.class.getModule();
                        System.out.println("named " + render.getName() + " " + core.getName()
                                + " " + Main.class.getModule().getName());
                        System.out.println("exported render " + render.isExported("org.jecosys.render")
                                + " gl " + render.isExported("org.jecosys.render.gl")
                                + " plant " + render.isExported("org.jecosys.render.plant")
                                + " internal " + render.isExported("org.jecosys.render.internal")
                                + " sim " + core.isExported("org.jecosys.sim")
                                + " sim.internal " + core.isExported("org.jecosys.sim.internal"));
                        System.out.println("frame " + f.number() + " components " + f.componentCount());
                    }
                }
            }
            """;

    @Test
    void aNamedModuleRequiringTheRendererStepsASimulation(@TempDir Path dir) throws Exception {
        List<String> modulePath = modulePath(dir);
        String mp = String.join(File.pathSeparator, modulePath);
        Path src = dir.resolve("src");
        Files.createDirectories(src.resolve("consumer"));
        Files.writeString(src.resolve("module-info.java"), DESCRIPTOR, StandardCharsets.UTF_8);
        Files.writeString(src.resolve("consumer/Main.java"), MAIN, StandardCharsets.UTF_8);
        Path out = dir.resolve("out");
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        java.io.ByteArrayOutputStream err = new java.io.ByteArrayOutputStream();
        int rc = javac.run(null, err, err, "--release", "17", "--module-path", mp, "-d", out.toString(),
                src.resolve("module-info.java").toString(), src.resolve("consumer/Main.java").toString());
        assertEquals(0, rc, "the consumer compiles on the module path:\n" + err);

        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        Path log = dir.resolve("run.log");
        Process p = new ProcessBuilder(java, "--module-path", out + File.pathSeparator + mp,
                "-m", "consumer/consumer.Main", Path.of("scenes/c1.xml").toAbsolutePath().toString())
                .redirectErrorStream(true).redirectOutput(log.toFile()).start();
        boolean ended = p.waitFor(60, TimeUnit.SECONDS);
        if (!ended) {
            p.destroyForcibly();
        }
        String output = Files.readString(log, StandardCharsets.UTF_8);
        assertTrue(ended, "the consumer ends within a minute:\n" + output);
        assertEquals(0, p.exitValue(), "the consumer runs:\n" + output);
        assertTrue(output.contains("named org.jecosys.render org.jecosys.core consumer"), output);
        assertTrue(output.contains("exported render true gl false plant false internal false sim true sim.internal false"),
                output);
        assertTrue(output.matches("(?s).*frame [1-9]\\d* components [1-9]\\d*.*"), "the simulation stepped:\n" + output);
    }

    @Test
    void anInternalPackageIsRefusedAtCompileTime(@TempDir Path dir) throws Exception {
        Path src = dir.resolve("src");
        Files.createDirectories(src.resolve("consumer"));
        Files.writeString(src.resolve("module-info.java"), DESCRIPTOR, StandardCharsets.UTF_8);
        Files.writeString(src.resolve("consumer/Peek.java"),
                "package consumer;\npublic final class Peek {\n    Object o = org.jecosys.sim.internal.FrameWriter.class;\n}\n",
                StandardCharsets.UTF_8);
        java.io.ByteArrayOutputStream err = new java.io.ByteArrayOutputStream();
        int rc = ToolProvider.getSystemJavaCompiler().run(null, err, err, "--release", "17", "--module-path",
                String.join(File.pathSeparator, modulePath(dir)), "-d", dir.resolve("out").toString(),
                src.resolve("module-info.java").toString(), src.resolve("consumer/Peek.java").toString());
        assertTrue(rc != 0 && err.toString().contains("org.jecosys.sim.internal"),
                "an unexported package does not compile: " + err);
    }

    /**
     * jecosys-core and jecosys-render (their jars, or their classes as built, put in a multi-release
     * jar as the build does: the descriptor is in META-INF/versions/17) and, from the test's class
     * path, the jars they need: JOML, Jackson with its XML parser, LWJGL's Java jars.
     */
    private static List<String> modulePath(Path dir) throws Exception {
        List<String> out = new ArrayList<>();
        out.add(jar(Path.of(SceneRenderer.class.getProtectionDomain().getCodeSource().getLocation().toURI()), dir));
        out.add(jar(Path.of(Frame.class.getProtectionDomain().getCodeSource().getLocation().toURI()), dir));
        for (String e : System.getProperty("java.class.path").split(File.pathSeparator)) {
            String name = Path.of(e).getFileName().toString();
            boolean lwjgl = name.startsWith("lwjgl") && !name.contains("natives");
            if (name.endsWith(".jar") && (lwjgl || name.startsWith("joml") || name.startsWith("jackson-")
                    || name.startsWith("woodstox") || name.startsWith("stax2"))) {
                out.add(e);
            }
        }
        assertTrue(out.stream().anyMatch(s -> s.contains("joml")) && out.stream().anyMatch(s -> s.contains("lwjgl-opengl")),
                "the dependencies are found on the class path: " + out);
        return out;
    }

    /** {@code classes} itself when a jar, else a multi-release jar of the directory in {@code dir}. */
    private static String jar(Path classes, Path dir) throws Exception {
        if (!Files.isDirectory(classes)) {
            return classes.toString();
        }
        assertTrue(Files.isRegularFile(classes.resolve("META-INF/versions/17/module-info.class")),
                "the module descriptor is built: " + classes);
        Path jar = Files.createTempFile(dir, "module", ".jar");
        java.util.jar.Manifest manifest = new java.util.jar.Manifest();
        manifest.getMainAttributes().put(java.util.jar.Attributes.Name.MANIFEST_VERSION, "1.0");
        manifest.getMainAttributes().put(java.util.jar.Attributes.Name.MULTI_RELEASE, "true");
        try (java.util.jar.JarOutputStream out = new java.util.jar.JarOutputStream(Files.newOutputStream(jar), manifest);
                java.util.stream.Stream<Path> files = Files.walk(classes)) {
            for (Path f : files.filter(Files::isRegularFile).toList()) {
                String name = classes.relativize(f).toString().replace('\\', '/');
                if (name.equals("META-INF/MANIFEST.MF")) {
                    continue;
                }
                out.putNextEntry(new java.util.jar.JarEntry(name));
                Files.copy(f, out);
                out.closeEntry();
            }
        }
        return jar.toString();
    }
}
