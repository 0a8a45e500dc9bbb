#version 330 core
// The plants drawn into the sun's shadow map (plant.vert compiled with SHADOW_CASTER): depth only.
// Plants in a level-of-detail band keep the same share of their fragments as on screen (the dither
// on the map's texels), so a band casts one plant's shadow, not two.
#ifdef DITHER
flat in vec2 vKeep;
#include "dither.glsl"
#endif

#ifdef TEXTURED
in vec4 vTex;
uniform sampler2DArray uPlantTextures;
#endif

void main() {
#ifdef TEXTURED
    // a textured part casts the shadow of its image's outline
    if (vTex.z > -0.5 && texture(uPlantTextures, vec3(vTex.xy, floor(vTex.z + 0.5))).a < 0.5) {
        discard;
    }
#endif
#ifdef DITHER
    if (dithered(vKeep)) {
        discard;
    }
#endif
}
