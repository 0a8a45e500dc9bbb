package org.jecosys.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.lang.reflect.Constructor;
import java.lang.reflect.Executable;
import java.lang.reflect.Field;
import java.lang.reflect.GenericArrayType;
import java.lang.reflect.Member;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.lang.reflect.ParameterizedType;
import java.lang.reflect.Type;
import java.lang.reflect.TypeVariable;
import java.lang.reflect.WildcardType;
import java.net.URISyntaxException;
import java.nio.file.FileSystem;
import java.nio.file.FileSystems;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import java.util.stream.Stream;
import org.jecosys.sim.Frame;
import org.junit.jupiter.api.Test;

/**
 * The public API names only public things: every public or protected method, constructor and field
 * of every public type in an API package of jecosys-core and jecosys-render (everything but the
 * internal packages: {@code render.gl}, {@code render.plant}, {@code render.ground},
 * {@code render.overlay} and any package with an {@code internal} segment), its supertypes, return,
 * parameter, field and exception types with their type arguments, names no type of an internal
 * package. And {@link Frame} is read-only to users: no public mutator.
 */
class ApiSurfaceTest {
    /** The renderer's internal packages, and any {@code .internal} package of either module. */
    static boolean internal(String pkg) {
        return pkg.equals("org.jecosys.render.gl") || pkg.equals("org.jecosys.render.plant")
                || pkg.equals("org.jecosys.render.ground") || pkg.equals("org.jecosys.render.overlay")
                || pkg.startsWith("org.jecosys.render.gl.") || pkg.startsWith("org.jecosys.render.plant.")
                || pkg.startsWith("org.jecosys.render.ground.") || pkg.startsWith("org.jecosys.render.overlay.")
                || pkg.endsWith(".internal") || pkg.contains(".internal.");
    }

    @Test
    void noApiSignatureNamesAnInternalType() throws Exception {
        List<Class<?>> api = new ArrayList<>();
        api.addAll(apiTypes(SceneRenderer.class));
        api.addAll(apiTypes(Frame.class));
        assertTrue(api.size() > 50, "the API types are found: " + api.size());
        assertTrue(api.contains(SceneRenderer.class) && api.contains(Frame.class), "both modules scanned");
        Set<String> offences = new TreeSet<>();
        for (Class<?> c : api) {
            offences.addAll(offences(c));
        }
        assertEquals("", String.join("\n", offences), offences.size() + " API signatures name internal types");
    }

    @Test
    void theScanSeesAnInternalTypeWhereOneIsNamed() {
        // the check itself: a signature naming GlTracker, also inside a type argument or an array, is caught
        assertTrue(names(Probe.class.getDeclaredFields()[0].getGenericType()).stream().anyMatch(ApiSurfaceTest::isInternal));
    }

    @SuppressWarnings("unused")
    private static final class Probe {
        java.util.List<java.util.Map<String, org.jecosys.render.gl.GlTracker[]>> probe;
    }

    @Test
    void frameAndTheDrawDecisionAreReadOnlyToUsers() {
        List<String> mutators = new ArrayList<>();
        for (Class<?> c : List.of(Frame.class, org.jecosys.sim.DrawDecision.class, org.jecosys.sim.ViewDecision.class)) {
            for (Method m : c.getMethods()) {
                if (m.getDeclaringClass() == c && (m.getName().startsWith("set") || m.getName().equals("decideAll"))) {
                    mutators.add(c.getSimpleName() + "." + m.getName());
                }
            }
        }
        assertEquals(List.of(), mutators, "public mutators of the frame and the draw decision");
        for (Field f : Frame.class.getFields()) {
            assertTrue(Modifier.isFinal(f.getModifiers()), "Frame." + f.getName() + " is final");
        }
    }

    private static boolean isInternal(Class<?> c) {
        while (c.isArray()) {
            c = c.getComponentType();
        }
        return !c.isPrimitive() && internal(c.getPackageName());
    }

    private static List<String> offences(Class<?> c) {
        List<String> out = new ArrayList<>();
        List<Type> supers = new ArrayList<>();
        if (c.getGenericSuperclass() != null) {
            supers.add(c.getGenericSuperclass());
        }
        supers.addAll(List.of(c.getGenericInterfaces()));
        for (Type t : supers) {
            report(out, c.getName() + " extends/implements", t);
        }
        for (Field f : c.getDeclaredFields()) {
            if (visible(f)) {
                report(out, c.getName() + "." + f.getName() + " (field)", f.getGenericType());
            }
        }
        List<Executable> code = new ArrayList<>();
        code.addAll(List.of(c.getDeclaredConstructors()));
        code.addAll(List.of(c.getDeclaredMethods()));
        for (Executable e : code) {
            if (!visible(e) || e.isSynthetic() || (e instanceof Method m && m.isBridge())) {
                continue;
            }
            String name = c.getName() + "." + (e instanceof Constructor<?> ? "<init>" : e.getName()) + signature(e);
            if (e instanceof Method m) {
                report(out, name + " returns", m.getGenericReturnType());
            }
            for (Type t : e.getGenericParameterTypes()) {
                report(out, name + " takes", t);
            }
            for (Type t : e.getGenericExceptionTypes()) {
                report(out, name + " throws", t);
            }
        }
        return out;
    }

    private static String signature(Executable e) {
        StringBuilder s = new StringBuilder("(");
        for (Class<?> p : e.getParameterTypes()) {
            s.append(s.length() > 1 ? ", " : "").append(p.getSimpleName());
        }
        return s.append(')').toString();
    }

    private static void report(List<String> out, String where, Type t) {
        for (Class<?> n : names(t)) {
            if (isInternal(n)) {
                out.add(where + " " + n.getName());
            }
        }
    }

    /** The classes a type names, with its type arguments, bounds and array components. */
    private static Set<Class<?>> names(Type t) {
        Set<Class<?>> out = new java.util.LinkedHashSet<>();
        collect(t, out, new java.util.HashSet<>());
        return out;
    }

    private static void collect(Type t, Set<Class<?>> out, Set<Type> seen) {
        if (t == null || !seen.add(t)) {
            return;
        }
        if (t instanceof Class<?> c) {
            out.add(c.isArray() ? c.componentType() : c);
            if (c.isArray()) {
                collect(c.componentType(), out, seen);
            }
        } else if (t instanceof ParameterizedType p) {
            collect(p.getRawType(), out, seen);
            collect(p.getOwnerType(), out, seen);
            for (Type a : p.getActualTypeArguments()) {
                collect(a, out, seen);
            }
        } else if (t instanceof GenericArrayType g) {
            collect(g.getGenericComponentType(), out, seen);
        } else if (t instanceof WildcardType w) {
            for (Type b : w.getUpperBounds()) {
                collect(b, out, seen);
            }
            for (Type b : w.getLowerBounds()) {
                collect(b, out, seen);
            }
        } else if (t instanceof TypeVariable<?> v) {
            for (Type b : v.getBounds()) {
                collect(b, out, seen);
            }
        }
    }

    private static boolean visible(Member m) {
        return Modifier.isPublic(m.getModifiers()) || Modifier.isProtected(m.getModifiers());
    }

    /** The public types (nested ones whose enclosing types are public too) of the API packages of the module holding {@code anchor}. */
    private static List<Class<?>> apiTypes(Class<?> anchor) throws IOException, URISyntaxException, ClassNotFoundException {
        Path root = Path.of(anchor.getProtectionDomain().getCodeSource().getLocation().toURI());
        List<String> names = new ArrayList<>();
        if (Files.isDirectory(root)) {
            names.addAll(classNames(root));
        } else {
            try (FileSystem jar = FileSystems.newFileSystem(root)) {
                names.addAll(classNames(jar.getPath("/")));
            }
        }
        List<Class<?>> out = new ArrayList<>();
        for (String n : names) {
            Class<?> c = Class.forName(n, false, anchor.getClassLoader());
            if (!internal(c.getPackageName()) && exported(c)) {
                out.add(c);
            }
        }
        return out;
    }

    private static boolean exported(Class<?> c) {
        for (Class<?> k = c; k != null; k = k.getDeclaringClass()) {
            if (!Modifier.isPublic(k.getModifiers()) || k.isAnonymousClass() || k.isLocalClass() || k.isSynthetic()) {
                return false;
            }
        }
        return true;
    }

    private static List<String> classNames(Path root) throws IOException {
        try (Stream<Path> files = Files.walk(root)) {
            return files.filter(p -> p.toString().endsWith(".class"))
                    .map(p -> root.relativize(p).toString().replace('\\', '/'))
                    .filter(p -> p.startsWith("org/jecosys/") && !p.endsWith("module-info.class") && !p.endsWith("package-info.class"))
                    .map(p -> p.substring(0, p.length() - ".class".length()).replace('/', '.'))
                    .sorted().toList();
        }
    }
}
