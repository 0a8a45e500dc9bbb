package org.jecosys.render.ground;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.jecosys.math.Rgb;
import org.jecosys.scene.RenderDef;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * The near cover's ceiling (issue 36): a cover set at run time, which no scene check saw, is thinned so
 * that a frame submits at most {@link RenderDef.GroundCover#MAX_BLADES_PER_VIEW} blades, while the
 * shipped meadow's cover is drawn exactly as before. Pure decisions; no GL context.
 */
@Tag("reliability")
class CoverCeilingTest {
    @Test
    void theMeadowsCoverIsNotThinned() {
        // density 2500, reach 8: at most 17 x 17 tiles in the box around the eye
        assertEquals(2500, CoverBlades.bladesPerTile(2500, 17 * 17));
        assertEquals(2500, CoverBlades.bladesPerTile(2500, 0), "no tiles: nothing to thin");
    }

    @Test
    void aCoverPastTheCeilingIsThinnedEvenlyToIt() {
        RenderDef.GroundCover gc = new RenderDef.GroundCover(1, 0.06, 20_000, 50, 1.5, new Rgb(0.3f, 0.5f, 0.16f),
                new Rgb(0.6f, 0.5f, 0.3f));
        int tiles = CoverBlades.MAX_TILES;
        int perTile = CoverBlades.bladesPerTile(gc.bladesPerTile(), tiles);
        assertTrue((long) perTile * tiles <= RenderDef.GroundCover.MAX_BLADES_PER_VIEW,
                perTile + " blades on each of " + tiles + " tiles");
        assertTrue(perTile >= RenderDef.GroundCover.MAX_BLADES_PER_VIEW / tiles, "thinned no more than needed: " + perTile);
        assertEquals(RenderDef.GroundCover.MAX_BLADE_TILES, CoverBlades.MAX_TILES, "the check's bound uses the same tiles");
        assertEquals(RenderDef.GroundCover.BLADE_TILE, CoverBlades.TILE, 0.0);
    }
}
