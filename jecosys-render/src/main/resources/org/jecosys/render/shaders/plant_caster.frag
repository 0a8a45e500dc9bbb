#version 330 core
// The plants drawn into the sun's shadow map (plant.vert compiled with SHADOW_CASTER): depth only.
// Plants in a level-of-detail band keep the same share of their fragments as on screen (the dither
// on the map's texels), so a band casts one plant's shadow, not two.
#ifdef DITHER
flat in vec2 vKeep;
#include "dither.glsl"
#endif

void main() {
#ifdef DITHER
    if (dithered(vKeep)) {
        discard;
    }
#endif
}
