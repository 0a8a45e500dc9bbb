package com.example.gdxmeadow;


import java.nio.file.Path;
import org.jecosys.render.ExampleLook;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * Issue 38: the wind's sheen in the libGDX example is the library's own. The meadow's start view at
 * 960 x 540 on the example's default back buffer (no samples) and its own ground, 150 frames at 1/30 s,
 * against the library's viewer picture at the same camera and size, stepped the same way
 * ({@link ExampleLook#viewer}): the median over the 16 x 16 blocks of the ground part (below the ground's
 * highest row in the middle column, the lower of the two pictures') of the temporal standard deviation
 * of the block's mean luminance is within 30% of the viewer's. Tagged {@code slow} (150 frames of the
 * whole meadow twice at 960 x 540 on llvmpipe: 60 to 75 s on two cores): it runs in
 * {@code mvn -B verify -Pnightly}. The example runs in a child JVM while this JVM draws the viewer's
 * picture.
 */
@Tag("slow")
class GdxMeadowSheenTest {
    private static final int FRAMES = 150;
    private static final Path OUT = Path.of("examples/gdx/target/example-test");

    @Test
    void theSheenIsTheViewersWithin30Percent() throws Exception {
        ExampleLook.assertSheenLikeTheViewer("libGDX", OUT, GdxMeadowExampleTest.MEADOW, GdxMeadowExampleTest.START_W, GdxMeadowExampleTest.START_H, FRAMES,
                GdxMeadowExampleTest::run);
    }
}
