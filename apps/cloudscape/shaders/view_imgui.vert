#version 450
// Dear ImGui's vertices (position in window pixels, uv into the font atlas, colour as sRGB
// bytes) to clip space.
layout(location = 0) in vec2 position;
layout(location = 1) in vec2 uv;
layout(location = 2) in vec4 colour;

layout(push_constant) uniform Window { vec2 scale; vec2 translate; } window;

layout(location = 0) out vec2 outUv;
layout(location = 1) out vec4 outColour;

void main() {
    outUv = uv;
    outColour = colour;
    gl_Position = vec4(position * window.scale + window.translate, 0.0, 1.0);
}
