// The ground cover's look on the ground (#include; terrain.frag under the library's terrain,
// cover_skin.frag over a host's own ground): the cover's colour (RenderDef.GroundCover) with a grain
// of blade tips at two scales (a mipmapped tile, so it fades to its mean with distance instead of
// shimmering), drier in the dry patches, and the wind's sheen rolling over it from the plants' bends.
uniform sampler2D uGrain;                        // the cover's grain tile, repeating
uniform vec4 uCover;                             // amount (0: none), 1 / grain tile (1/m), height (m), the level
                                                 // beyond the terrain (the cover map's mean; terrain only)
uniform vec3 uCoverColour;
uniform vec3 uCoverDry;
uniform sampler2D uBend;                         // the plants' mean bend per tile (CoverBlades), signed bytes
uniform vec4 uBendMap;                           // bend map minX, minZ, 1 / (tile width), 1 / (tile height)
uniform float uSheen;                            // the wind's sheen on the cover (plant_light.glsl), 0: off
uniform vec3 uSheenLight;                        // the sky's light a bent blade's pale side catches
uniform vec2 uSunXZ;                             // horizontal direction toward the sun, unit

// The cover at ground point xz (world, metres) whose dry-patch level is dryPatch and cover level
// (amount times the cover map) is level: rgb its unlit colour, a how much of the ground it hides
// (thin cover lets the ground show through its gaps)
vec4 groundCover(vec2 xz, float dryPatch, float level) {
    vec2 p = xz * uCover.y;
    float fine = texture(uGrain, p).r;
    float coarse = texture(uGrain, mat2(0.8, -0.6, 0.6, 0.8) * p * 0.29 + vec2(0.37, 0.71)).r;
    float grain = 0.6 * fine + 0.4 * coarse;
    // dry patches and a few dry flecks turn the cover toward straw
    float dry = clamp(dryPatch * 1.3 + (coarse - 0.5) * 0.35, 0.0, 1.0);
    // blade tips bright, the gaps between them dark (the canopy's own shade)
    vec3 cover = mix(uCoverColour, uCoverDry, dry) * (0.72 + 0.55 * grain);
    float hides = smoothstep(0.1, 0.75, level + 0.45 * (grain - 0.5));
    return vec4(cover, hides);
}

// The lit colour with the wind's sheen on the cover at world point p seen from eye, as on the plants'
// blades (plant_light.glsl windSheen), from the plants' bend where p is: gusts roll over the sward as
// bands of light. Call only while uSheen > 0.
vec3 coverSheen(vec3 lit, vec3 p, vec3 eye, float level) {
    vec2 bend = (texture(uBend, (p.xz - uBendMap.xy) * uBendMap.zw).rg * 255.0 - 128.0) * (1.6 / 127.0);
    float bent = length(bend);
    vec2 dir = bent > 1e-4 ? bend / bent : vec2(0.0);
    vec2 e = normalize(eye.xz - p.xz + vec2(1e-6));
    float toward = 0.6 + 0.25 * dot(dir, e) + 0.15 * dot(dir, uSunXZ);
    vec3 view = eye - p;
    float g = 1.0 - abs(view.y) / max(length(view), 1e-6);
    toward *= 0.8 + 0.8 * g * g * g;
    float k = uSheen * clamp(6.0 * bent * (1.0 / 1.2), 0.0, 1.0) * toward * clamp(level * 1.5, 0.0, 1.0);
    return mix(lit, lit * 1.25 + uSheenLight, clamp(1.4 * k, 0.0, 1.0)); // 1.4: as the plants' 1.3
}
