// The sun's shadow map (#include; plant.vert, cover.vert, terrain.frag): the plants' depth seen from
// the sun over a square around the near part of the view (SunShadowMap), read with a 4-tap
// percentage-closer filter (each tap itself a 2x2 filtered compare where the GL filters depth
// compares), fading out toward the square's edges, where the ground falls back to the splatted shadows.
uniform sampler2DShadow uShadowMap;
uniform mat4 uShadowMatrix;                      // world -> map: texel coordinates and depth in [0, 1]
uniform vec4 uSunShadow;                         // x: 1 when the map is drawn this frame, else 0; y: a texel
                                                 // (map units); z: depth bias (map units); w: strength
uniform vec4 uShadowEye;                         // the eye (xyz) and the map's reach (w), metres: plants
                                                 // farther than the reach may be lines, which do not cast

// x: the share of the sun's light the map says is blocked at world point p (0 lit .. 1 in full
// shadow), y: how far the map covers p (1 inside, falling to 0 over the outer fifth of the reach and
// of the square)
vec2 sunShadowMap(vec3 p) {
    if (uSunShadow.x <= 0.0) {
        return vec2(0.0);
    }
    vec3 s = (uShadowMatrix * vec4(p, 1.0)).xyz;
    vec2 d = abs(s.xy - 0.5) * 2.0;
    float edge = max(d.x, d.y);
    if (edge >= 1.0 || s.z >= 1.0) {
        return vec2(0.0);
    }
    float o = 0.75 * uSunShadow.y;
    float z = s.z - uSunShadow.z;
    float lit = texture(uShadowMap, vec3(s.xy + vec2(-o, -o), z)) + texture(uShadowMap, vec3(s.xy + vec2(o, -o), z))
            + texture(uShadowMap, vec3(s.xy + vec2(-o, o), z)) + texture(uShadowMap, vec3(s.xy + vec2(o, o), z));
    float reach = 1.0 - smoothstep(0.8 * uShadowEye.w, uShadowEye.w, distance(p, uShadowEye.xyz));
    return vec2(1.0 - 0.25 * lit, min(reach, 1.0 - smoothstep(0.8, 1.0, edge)));
}
