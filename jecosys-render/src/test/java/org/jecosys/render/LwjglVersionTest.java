package org.jecosys.render;

import static org.junit.jupiter.api.Assertions.assertDoesNotThrow;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.DataInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.lang.reflect.Field;
import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Method;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Tag;

/**
 * The renderer runs on LWJGL 3.3.3 (what libGDX and jMonkeyEngine bring) and later: every LWJGL
 * method and field its classes refer to exists in the LWJGL on the class path (this class runs in
 * both of the module's test runs, on the build's LWJGL and on 3.3.3), and an older LWJGL is refused
 * with a message that names the version found and the version needed.
 */
@Tag("lwjgl-compat")
class LwjglVersionTest {
    @Test
    void theTestRunUsesTheLwjglItSaysItDoes() {
        String expected = System.getProperty("jecosys.expectedLwjgl");
        assertNotNull(expected, "the surefire execution names its LWJGL");
        assertTrue(org.lwjgl.Version.getVersion().startsWith(expected + "+")
                || org.lwjgl.Version.getVersion().startsWith(expected + " "), org.lwjgl.Version.getVersion());
    }

    @Test
    void versionsFromTheOldestSupportedOnAreAcceptedAndOlderOnesRefusedNamingBoth() {
        for (String ok : new String[] {"3.3.3+5", "3.3.3 SNAPSHOT", "3.3.4", "3.4.3+4", "3.10.0", "4.0.0 build 1"}) {
            assertDoesNotThrow(() -> LwjglVersion.require(ok), ok);
        }
        for (String old : new String[] {"3.3.2+1", "3.2.3 build 13", "3.3.1", "2.9.3", "3.3", "unknown"}) {
            IllegalStateException e = assertThrows(IllegalStateException.class, () -> LwjglVersion.require(old), old);
            assertTrue(e.getMessage().contains("found LWJGL " + old) && e.getMessage().contains("needs LWJGL 3.3.3 or newer"),
                    e.getMessage());
        }
        assertDoesNotThrow(() -> LwjglVersion.require());
    }

    @Test
    void anOlderLwjglOnTheClassPathIsRefusedWhenAContextIsWrapped() throws Exception {
        Path old = Path.of("jecosys-render/target/lwjgl-too-old/lwjgl-3.2.3.jar");
        Path render = Path.of(LwjglVersion.class.getProtectionDomain().getCodeSource().getLocation().toURI());
        Path core = Path.of(org.jecosys.math.Require.class.getProtectionDomain().getCodeSource().getLocation().toURI());
        assertTrue(Files.isRegularFile(old), "LWJGL 3.2.3 is fetched by the build (maven-dependency-plugin): " + old);
        try (URLClassLoader loader = new URLClassLoader(new URL[] {render.toUri().toURL(), core.toUri().toURL(),
            old.toUri().toURL()}, ClassLoader.getPlatformClassLoader())) {
            Class<?> v = Class.forName(LwjglVersion.class.getName(), true, loader);
            InvocationTargetException e = assertThrows(InvocationTargetException.class,
                    () -> v.getMethod("require").invoke(null));
            assertTrue(e.getCause() instanceof IllegalStateException, String.valueOf(e.getCause()));
            assertTrue(e.getCause().getMessage().startsWith("JEcoSys needs LWJGL 3.3.3 or newer, found LWJGL 3.2.3"),
                    e.getCause().getMessage());
        }
    }

    @Test
    void everyLwjglMemberTheRendererUsesExistsInTheLwjglOnTheClassPath() throws Exception {
        Path classes = Path.of(LwjglVersion.class.getProtectionDomain().getCodeSource().getLocation().toURI());
        List<String> missing = new ArrayList<>();
        int checked = 0;
        try (Stream<Path> s = Files.walk(classes)) {
            for (Path f : s.filter(p -> p.toString().endsWith(".class")).toList()) {
                for (String[] ref : lwjglRefs(f)) {
                    checked++;
                    if (!exists(ref)) {
                        missing.add(classes.relativize(f) + " -> " + ref[0] + "." + ref[1] + ref[2]);
                    }
                }
            }
        }
        assertTrue(checked > 200, "references checked: " + checked);
        // the check tells the versions apart: the overload that broke the engines exists from 3.4 only
        boolean v34 = !org.lwjgl.Version.getVersion().startsWith("3.3.");
        assertEquals(v34, exists(new String[] {"org.lwjgl.system.MemoryUtil", "memFree", "(Ljava/nio/FloatBuffer;)V", "M"}));
        assertTrue(exists(new String[] {"org.lwjgl.system.MemoryUtil", "memFree", "(Ljava/nio/Buffer;)V", "M"}));
        assertEquals(List.of(), missing, "LWJGL " + org.lwjgl.Version.getVersion() + " lacks what the renderer calls");
    }

    /** The class file's references into org.lwjgl: {owner, name, descriptor, kind ('M' or 'F')}. */
    private static List<String[]> lwjglRefs(Path classFile) throws IOException {
        List<String[]> out = new ArrayList<>();
        try (InputStream in = Files.newInputStream(classFile); DataInputStream d = new DataInputStream(in)) {
            d.readInt();
            d.readUnsignedShort();
            d.readUnsignedShort();
            int n = d.readUnsignedShort();
            Object[] pool = new Object[n];
            int[][] refs = new int[n][];
            char[] kinds = new char[n];
            for (int i = 1; i < n; i++) {
                int tag = d.readUnsignedByte();
                switch (tag) {
                    case 1 -> pool[i] = d.readUTF();
                    case 3, 4 -> d.readInt();
                    case 5, 6 -> {
                        d.readLong();
                        i++;
                    }
                    case 7, 8, 16, 19, 20 -> pool[i] = new int[] {d.readUnsignedShort()};
                    case 9, 10, 11 -> {
                        refs[i] = new int[] {d.readUnsignedShort(), d.readUnsignedShort()};
                        kinds[i] = tag == 9 ? 'F' : 'M';
                    }
                    case 12 -> pool[i] = new int[] {d.readUnsignedShort(), d.readUnsignedShort()};
                    case 15 -> {
                        d.readUnsignedByte();
                        d.readUnsignedShort();
                    }
                    case 17, 18 -> {
                        d.readUnsignedShort();
                        d.readUnsignedShort();
                    }
                    default -> throw new IOException(classFile + ": constant tag " + tag);
                }
            }
            for (int i = 1; i < n; i++) {
                if (refs[i] == null) {
                    continue;
                }
                String owner = (String) pool[((int[]) pool[refs[i][0]])[0]];
                int[] nt = (int[]) pool[refs[i][1]];
                if (owner.startsWith("org/lwjgl/")) {
                    out.add(new String[] {owner.replace('/', '.'), (String) pool[nt[0]], (String) pool[nt[1]],
                        String.valueOf(kinds[i])});
                }
            }
        }
        return out;
    }

    private static boolean exists(String[] ref) {
        Class<?> c;
        try {
            c = Class.forName(ref[0], false, LwjglVersionTest.class.getClassLoader());
        } catch (ClassNotFoundException e) {
            return false;
        }
        for (Class<?> k = c; k != null; k = k.getSuperclass()) {
            if (ref[3].equals("F")) {
                for (Field f : k.getDeclaredFields()) {
                    if (f.getName().equals(ref[1]) && descriptor(f.getType()).equals(ref[2])) {
                        return true;
                    }
                }
            } else {
                for (Method m : k.getDeclaredMethods()) {
                    if (m.getName().equals(ref[1]) && descriptor(m).equals(ref[2])) {
                        return true;
                    }
                }
                if (ref[1].equals("<init>")) {
                    return true; // constructors of LWJGL classes the renderer makes: checked by the tests that run them
                }
            }
            for (Class<?> i : k.getInterfaces()) {
                if (exists(new String[] {i.getName(), ref[1], ref[2], ref[3]})) {
                    return true;
                }
            }
        }
        return false;
    }

    private static String descriptor(Method m) {
        StringBuilder sb = new StringBuilder("(");
        for (Class<?> p : m.getParameterTypes()) {
            sb.append(descriptor(p));
        }
        return sb.append(')').append(descriptor(m.getReturnType())).toString();
    }

    private static String descriptor(Class<?> t) {
        if (t.isArray()) {
            return t.getName().replace('.', '/');
        }
        if (t.isPrimitive()) {
            return switch (t.getName()) {
                case "int" -> "I";
                case "long" -> "J";
                case "float" -> "F";
                case "double" -> "D";
                case "boolean" -> "Z";
                case "byte" -> "B";
                case "char" -> "C";
                case "short" -> "S";
                default -> "V";
            };
        }
        return "L" + t.getName().replace('.', '/') + ";";
    }
}
