#version 330 core
// The second half of a multisampled framebuffer's resolve: the samples of each pixel have been
// averaged (a box filter one pixel wide); this widens the filter toward a tent of one pixel's radius,
// blended by uTent (0: box, 1: tent), so that thin geometry moving by a fraction of a pixel changes
// the image smoothly. Four bilinear taps at the pixel's corners make the 3x3 tent
// (1 2 1; 2 4 2; 1 2 1) / 16.
uniform sampler2D uImage;
uniform vec2 uTexel;                             // 1 / size
uniform float uTent;
out vec4 fragColour;

void main() {
    vec2 uv = gl_FragCoord.xy * uTexel;
    vec4 box = texture(uImage, uv);
    vec4 tent = 0.25 * (texture(uImage, uv + uTexel * vec2(-0.5, -0.5)) + texture(uImage, uv + uTexel * vec2(0.5, -0.5))
            + texture(uImage, uv + uTexel * vec2(-0.5, 0.5)) + texture(uImage, uv + uTexel * vec2(0.5, 0.5)));
    fragColour = mix(box, tent, uTent);
}
