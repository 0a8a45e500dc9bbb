#version 330 core
// A multisampled framebuffer's resolve with temporal accumulation: each frame is drawn with the
// projection moved by a sub-pixel jitter; this pass blends the frame, filtered narrowly, into a running
// mean of the frames before it (the history, reprojected for the camera's motion through this frame's
// depth), so that a view held still gathers samples from the whole pixel over frames and keeps fine
// detail that a one-frame filter wide enough against aliasing would blur.
//   history: rgb the running mean, which the framebuffer shows; a how many frames it holds (1 to uFrames)
// Where the whole history is new (the first frame, a reset) the framebuffer shows its one-frame resolve
// instead (GlFramebuffer).
// The history is clamped to the range of this frame's 3x3 neighbourhood, so that what comes out from
// behind something leaves no lasting ghost; while the scene animates by itself (uStill 0) the mean holds
// only uLiveFrames frames, a short trail, since the wind's motion has no motion vectors here.
uniform sampler2D uImage;
uniform sampler2D uDepth;
uniform sampler2D uHistory;
uniform vec2 uTexel;                             // 1 / size
uniform float uTent;                             // the accumulated frame's filter: the box mixed this far to the tent
uniform mat4 uReproject;                         // this frame's clip space to the history's
uniform float uKeep;                             // 0: the history is forgotten (first frame, reset)
uniform float uFrames;                           // most frames in the running mean
uniform float uMovingFrames;                     // most frames where the camera moved the history
uniform float uLiveFrames;                       // most frames while the scene animates
uniform float uStill;                            // 1: nothing drawn moved by itself since the last frame
uniform float uClip;                             // the neighbourhood's range: standard deviations about its mean
layout(location = 0) out vec4 history;

void main() {
    vec2 uv = gl_FragCoord.xy * uTexel;
    ivec2 texel = ivec2(gl_FragCoord.xy);
    ivec2 last = textureSize(uImage, 0) - 1;
    // the frame's 3x3 neighbourhood (the box-averaged samples of this pixel and the eight around it): the
    // accumulated frame's narrow filter (the box mixed toward the 1 2 1 tent by uTent, everywhere) and
    // the colour range the history is clamped to (its mean within uClip standard deviations, inside its
    // extremes)
    vec3 box = vec3(0.0);
    vec3 tent = vec3(0.0);
    vec3 lo = vec3(1.0);
    vec3 hi = vec3(0.0);
    vec3 sum = vec3(0.0);
    vec3 sum2 = vec3(0.0);
    for (int j = -1; j <= 1; j++) {
        for (int i = -1; i <= 1; i++) {
            vec3 c = texelFetch(uImage, clamp(texel + ivec2(i, j), ivec2(0), last), 0).rgb;
            float k = (i == 0 ? 2.0 : 1.0) * (j == 0 ? 2.0 : 1.0) / 16.0;
            tent += k * c;
            box += (i == 0 && j == 0) ? c : vec3(0.0);
            lo = min(lo, c);
            hi = max(hi, c);
            sum += c;
            sum2 += c * c;
        }
    }
    vec3 current = mix(box, tent, uTent);
    vec3 mean9 = sum / 9.0;
    vec3 sd = sqrt(max(sum2 / 9.0 - mean9 * mean9, vec3(0.0)));
    lo = min(max(lo, mean9 - uClip * sd), current);
    hi = max(min(hi, mean9 + uClip * sd), current);
    float frames = 0.0;
    vec3 past = vec3(0.0);
    if (uKeep > 0.5) {
        float depth = texelFetch(uDepth, texel, 0).r;
        vec4 p = uReproject * vec4(2.0 * uv - 1.0, 2.0 * depth - 1.0, 1.0);
        vec2 puv = p.w > 0.0 ? 0.5 * p.xy / p.w + 0.5 : vec2(-1.0);
        if (all(greaterThanEqual(puv, vec2(0.0))) && all(lessThanEqual(puv, vec2(1.0)))) {
            vec4 h = texture(uHistory, puv);
            past = clamp(h.rgb, lo, hi);
            frames = h.a;
            vec2 moved = abs(puv - uv) / uTexel;
            if (max(moved.x, moved.y) > 1.0 / 64.0) {
                frames = min(frames, uMovingFrames - 1.0);
            }
        }
    }
    // the wind moves plants, cover sheen and clouds without motion vectors: while the scene animates the
    // mean is kept short, a trail of a few frames; held still it gathers the whole jitter pattern
    float most = uStill > 0.5 ? uFrames : min(uFrames, uLiveFrames);
    frames = min(frames + 1.0, most);
    history = vec4(mix(past, current, 1.0 / frames), frames);
}
