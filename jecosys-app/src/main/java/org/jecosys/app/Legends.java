package org.jecosys.app;

import imgui.ImDrawList;
import imgui.ImGui;
import imgui.flag.ImGuiCond;
import imgui.flag.ImGuiWindowFlags;
import org.jecosys.render.OverlaySettings;
import org.jecosys.render.overlay.FieldOverlay;
import org.jecosys.render.overlay.GizmoRenderer;
import org.jecosys.render.overlay.Gizmos;
import org.jecosys.terrain.Heightfield;

/**
 * The legends (ImGui): the colour scale of the wind arrows on the terrain, and what the minimap's
 * grey levels, arrows and markers mean, with a dot per flow and agent drawn on the minimap in its
 * gizmo colour. Positions are ImGui's (window coordinates), converted from framebuffer pixels by
 * the display's framebuffer scale. Render thread; allocates labels.
 */
final class Legends {
    private static final int STEPS = 24;
    private static final float BAR_W = 220;
    private static final float BAR_H = 12;

    private final Heightfield ground;
    private final float[] rgb = new float[4];

    Legends(Heightfield ground) {
        this.ground = ground;
    }

    private static float scale() {
        float s = ImGui.getIO().getDisplayFramebufferScaleX();
        return s > 0 ? s : 1;
    }

    /**
     * The wind arrows' legend, bottom right.
     *
     * @param top     wind speed at the top of the scale (red), m/s
     * @param typical the speed 90% of the wind in view stays under, m/s
     */
    void wind(double top, double typical) {
        float w = ImGui.getIO().getDisplaySizeX();
        float h = ImGui.getIO().getDisplaySizeY();
        ImGui.setNextWindowPos(w - 8, h - 8, ImGuiCond.Always, 1, 1);
        ImGui.setNextWindowBgAlpha(0.55f);
        ImGui.begin("wind legend", ImGuiWindowFlags.NoDecoration | ImGuiWindowFlags.AlwaysAutoResize
                | ImGuiWindowFlags.NoInputs | ImGuiWindowFlags.NoSavedSettings);
        ImGui.text("Wind the plants feel (arrows on the terrain, V hides)");
        float x = ImGui.getCursorScreenPosX();
        float y = ImGui.getCursorScreenPosY();
        ImDrawList dl = ImGui.getWindowDrawList();
        for (int i = 0; i < STEPS; i++) {
            GizmoRenderer.windColour(top * (i + 0.5) / STEPS, top, rgb);
            dl.addRectFilled(x + BAR_W * i / STEPS, y, x + BAR_W * (i + 1) / STEPS + 0.5f, y + BAR_H,
                    imgui.ImColor.rgba(rgb[0], rgb[1], rgb[2], 1f));
        }
        ImGui.dummy(BAR_W, BAR_H);
        ImGui.text("0");
        ImGui.sameLine(BAR_W / 2 - 8);
        ImGui.text(ViewerPanel.number(top / 2));
        ImGui.sameLine(BAR_W - 30);
        ImGui.text(ViewerPanel.number(top) + " m/s");
        // (no percent sign: ImGui.text reads its string as a format)
        ImGui.text(String.format(java.util.Locale.ROOT, "9 nodes in 10 under %.1f m/s; an arrow per force-field node",
                typical));
        ImGui.end();
    }

    /**
     * The minimap's legend, under the map, and a dot per gizmo on the map.
     *
     * @param width     framebuffer width, pixels
     * @param height    framebuffer height, pixels
     * @param shown     what the map shows: the quadtree, the wind
     * @param gizmos    the flows' and agents' gizmos, or null
     */
    void map(int width, int height, OverlaySettings shown, Gizmos gizmos) {
        boolean showField = shown.showField();
        boolean showWind = shown.showWind();
        float s = scale();
        float side = FieldOverlay.mapSide(width, height) / s;
        float left = (width - FieldOverlay.MAP_MARGIN) / s - side;
        float top = FieldOverlay.MAP_MARGIN / s;
        if (gizmos != null) {
            ImDrawList dl = ImGui.getBackgroundDrawList();
            for (int i = 0; i < gizmos.size(); i++) {
                float u = (float) ((gizmos.x(i) - ground.minX()) / ground.sizeX());
                float v = (float) ((gizmos.z(i) - ground.minZ()) / ground.sizeZ());
                if (u < 0 || u > 1 || v < 0 || v > 1) {
                    continue;
                }
                GizmoRenderer.shade(gizmos.kind(i), gizmos.enabled(i), gizmos.weight(i), rgb);
                float cx = left + u * side;
                float cy = top + v * side;
                dl.addCircleFilled(cx, cy, 5.5f, imgui.ImColor.rgba(0.05f, 0.05f, 0.05f, 1f));
                dl.addCircleFilled(cx, cy, 4f, imgui.ImColor.rgba(rgb[0], rgb[1], rgb[2], 1f));
            }
        }
        ImGui.setNextWindowPos(left + side, top + side + 4, ImGuiCond.Always, 1, 0);
        ImGui.setNextWindowBgAlpha(0.55f);
        ImGui.begin("map legend", ImGuiWindowFlags.NoDecoration | ImGuiWindowFlags.AlwaysAutoResize
                | ImGuiWindowFlags.NoInputs | ImGuiWindowFlags.NoSavedSettings);
        ImGui.text("Map, north (-Z) up");
        if (showField) {
            grey(FieldOverlay.grey(true, 0), "node with its own force");
            grey(FieldOverlay.grey(true, 1), "one level up (LOD, Fig. 2)");
            grey(FieldOverlay.grey(true, 3), "three or more levels up");
            grey(FieldOverlay.grey(false, -1), "not in view");
        }
        if (showWind) {
            ImGui.colorButton("##wind", 0.85f, 0.1f, 0.1f, 1f);
            ImGui.sameLine();
            ImGui.text("wind per node (Fig. 3), full length at 8 m/s");
        }
        ImGui.colorButton("##you", 1f, 0.85f, 0.1f, 1f);
        ImGui.sameLine();
        ImGui.text("you, pointing where you look");
        if (gizmos != null && gizmos.size() > 0) {
            ImGui.text("dots: flows and agents (gizmo colours)");
        }
        ImGui.end();
    }

    private static void grey(float g, String what) {
        ImGui.colorButton("##" + what, g, g, g, 1f);
        ImGui.sameLine();
        ImGui.text(what);
    }
}
