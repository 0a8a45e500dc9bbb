// How a point of a plant is coloured and lit (#include; plant_common.glsl for vertices, the resolve
// pass for a whole component of a line level): the component's colour turned in hue and scaled in
// brightness by its variation, toward straw at the tips and in dry patches; sky ambient light, darker
// toward the base (the neighbours' shade), the sun on the face toward it, light through the blade when
// it is lit from behind (back-lit grass glows), a sheen toward the tip against the sun, and haze toward the
// horizon colour with distance (the terrain's formula).
uniform vec3 uEye;
uniform vec3 uLightDir;                          // unit, toward the sun
uniform vec3 uSunColour;                         // sunlight on a surface facing the sun
uniform vec3 uAmbient;                           // sky light
uniform vec3 uFogColour;
uniform float uFogStart;
uniform float uFogEnd;
uniform float uSheen;                            // strength of the wind's sheen on bent blades, 0: off
#ifdef LIST_TABLE
float uDryTips = 0.0;                            // set per list by plant_resolve.comp
#else
uniform float uDryTips;                          // this species: how far tips turn to straw, 0..1
#endif

// the share of the sun's direct light that reaches the point being lit: 1; plant.vert compiled with
// SHADOW_MAP lights each vertex a second time with 0, for the shadow map's per-fragment shading
float gSunLit = 1.0;

const vec3 STRAW = vec3(0.74, 0.66, 0.38);
const vec3 THROUGH = vec3(1.05, 1.22, 0.6);      // light through a blade: yellower than reflected light

// the colour before light: base colour, look = (cos, sin of the hue turn, brightness, patch dryness),
// kind (0 blade, 1 stem, 2 petal, 3 fan head), along = fraction along the component
vec3 albedo(vec3 base, vec4 look, int kind, float along) {
    const vec3 k = vec3(0.57735027);
    vec3 c = base * look.x + cross(k, base) * look.y + k * dot(k, base) * (1.0 - look.x);
    c = max(c, vec3(0.0)) * look.z;
    if (kind < 2) {
        float dryness = clamp(uDryTips * along * along + look.w * (0.35 + 0.65 * along), 0.0, 1.0);
        float grey = dot(c, vec3(0.3, 0.59, 0.11));
        c = mix(c, STRAW * (0.55 + 1.1 * grey), dryness);
        c = mix(c, c * vec3(1.08, 1.12, 0.85) + vec3(0.03, 0.04, 0.0), along * along); // sunlit tips
    }
    return c;
}

// the shade toward the base and low down in a tuft, where the neighbouring leaves hide the sky: 1 at
// the tip of a part standing clear; along = fraction along the part, height = metres above its base
float baseShade(int kind, float along, float height) {
    if (kind >= 2) {
        return 1.0;
    }
    return (0.5 + 0.5 * sqrt(along)) * mix(0.45, 1.0, smoothstep(0.0, 0.3, height));
}

// The wind's sheen (issue 26): a blade bent by the wind shows its paler side and catches the sky's light,
// the more the further it bends, most when it bends toward the eye or the sun; so a gust reads from
// afar as a band of light travelling over the field. bend: how far the part is bent, 0 (rest) to 1
// (its species' largest bend); dir: the horizontal direction it bends toward (unit or 0); lit: its lit
// colour before haze.
vec3 windSheen(vec3 lit, float bend, vec2 dir, vec3 toEye) {
    if (uSheen <= 0.0 || bend <= 0.0) {
        return lit;
    }
    float el = length(toEye.xz);
    vec2 e = el > 1e-6 ? toEye.xz / el : vec2(0.0);
    float sl = length(uLightDir.xz);
    vec2 s = sl > 1e-6 ? uLightDir.xz / sl : vec2(0.0);
    float toward = 0.6 + 0.25 * dot(dir, e) + 0.15 * dot(dir, s);
    // seen at a grazing angle (from afar) a blade's surface reflects more of the sky (Fresnel), so the
    // same bend shows more
    float g = 1.0 - abs(toEye.y) / max(length(toEye), 1e-6);
    toward *= 0.8 + 0.8 * g * g * g;
    float b = clamp(6.0 * bend, 0.0, 1.0);
    vec3 pale = lit * 1.25 + 0.35 * uFogColour * (uAmbient + 0.5 * uSunColour);
    // 1.3: at sheen 1 a gust shows in the middle and far field (block luma s.d. >= 4/255, WindSheenTest)
    // now that the thin parts blend by their true coverage
    return mix(lit, pale, clamp(1.3 * uSheen * b * toward, 0.0, 1.0));
}

// c lit at a point with surface normal (not normalised; 0: none), height metres above its part's
// base, seen from toEye at distance, bent by bend (0 to 1) toward dir (the wind's sheen); far drops
// the specular glint
vec3 lit(vec3 c, int kind, float along, float height, vec3 normal, vec3 toEye, float distance, bool far,
         float bend, vec2 dir) {
    // the shade low in a tuft fades out from 6 m to 15 m: from afar the tops of the tufts show, and the
    // few far plants a thinned frame keeps are drawn wider to stand for the others
    float ao = baseShade(kind, along, mix(height, 1.0, smoothstep(6.0, 15.0, distance)));
    vec3 e = toEye / max(distance, 1e-6);
    vec3 light;
    vec3 gloss = vec3(0.0);
    float len = length(normal);
    if (len > 1e-9) {
        vec3 n = normal / len;
        n = dot(n, e) < 0.0 ? -n : n;
        float nl = dot(n, uLightDir);
        float front = max(nl, 0.0);
        float back = max(-nl, 0.0);
        float toward = 0.5 + 0.5 * dot(-e, uLightDir);    // 1 looking straight into the sun
        // a blade lit from behind glows: thin leaves pass on much of the light, more toward the tip
        // thin tips pass on the most
        float through = kind == 3 ? 0.0 : back * (1.6 + 1.6 * toward * toward) * (0.35 + 0.9 * along * along);
        vec3 sun = gSunLit * uSunColour;
        light = uAmbient * ao * (0.8 + 0.2 * abs(n.y)) + sun * (front * (0.2 + 0.8 * ao)) + sun * THROUGH * through;
        if (!far) {
            // sheen: a blade's waxy surface glints toward the tip when seen against the sun, at grazing
            // angles (forward scattering), not when the sun is behind the viewer
            float t2 = toward * toward;
            float grazing = 1.0 - abs(dot(n, e));
            gloss = gSunLit * uSunColour * (0.35 * along * t2 * t2 * t2 * (0.4 + 0.6 * grazing));
        }
    } else {
        light = uAmbient * ao + gSunLit * uSunColour * 0.45;
    }
    vec3 colour = c * light + gloss;
    // brighter than white: scale down instead of clipping each channel, which would turn a sunlit
    // yellow petal greenish (red and green both clipped to 1)
    if (kind < 2) {
        colour = windSheen(colour, bend * (0.3 + 0.7 * along), dir, toEye);
    }
    colour /= max(1.0, max(colour.r, max(colour.g, colour.b)));
    float fog = clamp((distance - uFogStart) / max(uFogEnd - uFogStart, 1e-3), 0.0, 1.0);
    return mix(colour, uFogColour, fog * fog);
}
