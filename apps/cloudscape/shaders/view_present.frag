#version 450
// The viewer's picture: the renderer's composite (linear radiance, one vec4 a pixel, row-major,
// read where the renderer left it on the device) filtered bilinearly onto the window's pixels,
// letterboxed to keep its aspect, through the model's one tone curve (output.glsl.h).
#include "output.glsl.h"

layout(std430, binding = 0) readonly buffer Composite { vec4 pixels[]; };

layout(push_constant) uniform Placement {
    ivec2 imageSize;  // the composite's pixels
    vec2 origin;      // window pixel of the image's top-left corner
    float pixelScale; // image pixels per window pixel
    float exposure;
    int decodeSrgb;   // 1 when the swapchain encodes sRGB itself
    int displayValues; // 1: the buffer holds a debug view's display values (no tone curve)
} place;

layout(location = 0) out vec4 colour;

vec3 radianceAt(ivec2 p) {
    p = clamp(p, ivec2(0), place.imageSize - 1);
    return pixels[p.y * place.imageSize.x + p.x].rgb;
}

vec3 srgbToLinear(vec3 c) {
    return mix(c / 12.92, pow((c + 0.055) / 1.055, vec3(2.4)), greaterThan(c, vec3(0.04045)));
}

void main() {
    const vec2 p = (gl_FragCoord.xy - place.origin) * place.pixelScale;
    if (any(lessThan(p, vec2(0.0))) || any(greaterThanEqual(p, vec2(place.imageSize)))) {
        colour = vec4(0.03, 0.03, 0.035, 1.0);
        return;
    }
    const vec2 q = p - 0.5;
    const ivec2 i = ivec2(floor(q));
    const vec2 f = q - vec2(i);
    const vec3 radiance =
        mix(mix(radianceAt(i), radianceAt(i + ivec2(1, 0)), f.x),
            mix(radianceAt(i + ivec2(0, 1)), radianceAt(i + ivec2(1, 1)), f.x), f.y);
    vec3 display = place.displayValues == 1 ? clamp(radiance, 0.0, 1.0)
                                            : toneMap(radiance, place.exposure);
    if (place.decodeSrgb == 1)
        display = srgbToLinear(display);
    colour = vec4(display, 1.0);
}
