package org.jecosys.jme;

import java.io.IOException;

/** Image paths of a scene, made plain and kept inside the scene's folder. */
final class JmePaths {
    private JmePaths() {
    }

    /**
     * A relative path that stays in its folder, with '/' separators and without '.' or '..' segments.
     *
     * @param path as the scene writes it
     * @return the path made plain
     * @throws IOException when it is absolute, empty, or leads out of the folder
     */
    static String inFolder(String path) throws IOException {
        String p = path.replace('\\', '/');
        if (p.isEmpty() || p.startsWith("/") || (p.length() > 1 && p.charAt(1) == ':')) {
            throw new IOException("image '" + path + "': not a path relative to the scene's folder");
        }
        StringBuilder out = new StringBuilder(p.length());
        int depth = 0;
        for (String part : p.split("/")) {
            if (part.isEmpty() || part.equals(".")) {
                continue;
            }
            if (part.equals("..")) {
                if (depth == 0) {
                    throw new IOException("image '" + path + "': leads out of the scene's folder");
                }
                int cut = out.lastIndexOf("/");
                out.setLength(Math.max(cut, 0));
                depth--;
                continue;
            }
            if (out.length() > 0) {
                out.append('/');
            }
            out.append(part);
            depth++;
        }
        if (depth == 0) {
            throw new IOException("image '" + path + "': names the scene's folder, not a file");
        }
        return out.toString();
    }
}
