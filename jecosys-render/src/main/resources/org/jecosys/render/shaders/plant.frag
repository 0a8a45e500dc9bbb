#version 330 core
// Screen-door dither across a level-of-detail band: level L keeps pixels with lo <= bayer < hi, level
// L + 1 the complementary ones, so the switch is gradual. Only plants in a band are drawn with the
// test (compiled with DITHER); the others are drawn by the variant without it, which never
// discards, so the rasteriser can test depth before shading. Colour arrives lit and fogged from
// the vertex shader; alpha is the share of the drawn width the real part covers: the thin parts blend by
// it (SPLIT), with or without samples, or, where the renderer is told to, alpha-to-coverage turns it
// into samples (and stores alpha 1: alpha-to-one).
// Compiled with SHADOW_MAP (the sun's shadow map is drawn) it takes the sun's share away where the map
// says the fragment is in shadow.
in vec4 vShade;
noperspective in vec2 vEdge;                     // side (-1 to 1), drawn half width in pixels (negative:
                                                 // not a blade)
const float MIDRIB = 0.3;                       // a blade's middle this much lighter, its edges darker
uniform float uAlphaFloor;
// > 0: the opaque core's pass on a multisampled target: alpha becomes 1 at or above it and 0 below, so
// that alpha-to-coverage writes the core only (no discard: the depth test can run before shading)
uniform float uCoreCut;
uniform float uFeather;
#ifdef SPLIT
// targets without samples draw the near plants twice: their opaque core writing depth (uSplit 1), then
// the fringe the soft edge and thin parts blend (uSplit 2), depth-tested but not written, so a faint
// edge never hides a blade behind it; uSplit 3: the fringe on pixel centres over a core drawn on a
// multisampled target's samples without the soft edge, so the fringe keeps what that core left out
uniform float uSplit;
#endif
#ifdef DITHER
flat in vec2 vKeep;
#endif
layout(location = 0) out vec4 fragColour;
// the resolve's detail mask (GlFramebuffer): 1 where thin geometry wants the wide filter, 0 elsewhere;
// written only into the library's own framebuffer (a host's other draw buffers are masked off)
layout(location = 1) out vec4 fragDetail;

#ifdef DITHER
#include "dither.glsl"
#endif
#ifdef SHADOW_MAP
in vec3 vSun;
in vec3 vWorld;
#include "sun_shadow.glsl"
#endif
#ifdef TEXTURED
// the components' images (PlantTextures: a layer each, mipmapped with their coverage kept, the colour
// bled under transparent texels so that no dark fringe is filtered in); the lit colour is multiplied by
// the texel, the haze kept as it is; alpha cuts the outline (coverage under multisampling, blended at the
// fringe without samples)
in vec4 vTex;
uniform sampler2DArray uPlantTextures;
uniform vec3 uFogColour;
#endif

void main() {
    // the share of the drawn width the part covers, times its image's coverage
    float cover = vShade.a;
#ifdef TEXTURED
    vec4 texel = vec4(1.0);
    if (vTex.z > -0.5) {
        // no discard here: a shader that may discard loses the early depth test on llvmpipe, and the
        // outline is coverage (multisampled) or blended (the fringe of a target without samples)
        texel = texture(uPlantTextures, vec3(vTex.xy, floor(vTex.z + 0.5)));
        cover *= texel.a;
    }
#endif
    // the soft edge (a pass on pixel centres, which blends by alpha): the outer uFeather pixels fade
    float alpha = uFeather > 0.0 ? cover * clamp((1.0 - abs(vEdge.x)) * abs(vEdge.y) / uFeather, 0.0, 1.0) : cover;
#ifndef SPLIT
    if (uCoreCut > 0.0) {
        alpha = alpha >= uCoreCut ? 1.0 : 0.0;
    } else if (uCoreCut < 0.0 && cover >= 0.996) {
        // the fringe over the core's pass: what the core drew on the samples (edges included) is left
        // to it; alpha 0 adds nothing, and unlike a discard keeps the early depth test
        alpha = 0.0;
    }
#endif
#ifdef SPLIT
    if (((uSplit > 2.5 ? cover : alpha) >= 0.996) != (uSplit < 1.5)) {
        discard;
    }
#endif
#ifdef DITHER
    if (dithered(vKeep)) {
        discard;
    }
#endif
    vec3 colour = vShade.rgb;
    // a blade's midrib: lighter along its middle, darker toward its edges (the mean across it kept), where
    // the blade is drawn wide enough to show it (fading in between 3 and 8 pixels across, so thin far
    // blades do not flicker)
    colour *= 1.0 + MIDRIB * clamp((vEdge.y - 1.5) / 2.5, 0.0, 1.0) * (1.0 - 2.0 * abs(vEdge.x));
#ifdef SHADOW_MAP
    // the other plants' shadows (and its own), per fragment: the sun's share taken away
    vec2 shadow = sunShadowMap(vWorld);
    colour -= (uSunShadow.w * shadow.x * shadow.y) * vSun;
#endif
#ifdef TEXTURED
    // vShade = lit (1 - h) + haze h: the image tints the lit part only
    colour = colour * texel.rgb + (vTex.w * uFogColour) * (1.0 - texel.rgb);
#endif
    fragColour = vec4(colour, max(alpha, uAlphaFloor));
    fragDetail = vec4(1.0);
}
