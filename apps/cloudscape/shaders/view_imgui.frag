#version 450
// ImGui's colour times the font atlas's coverage.
layout(binding = 0) uniform sampler2D atlas;

layout(location = 0) in vec2 uv;
layout(location = 1) in vec4 colour;

layout(location = 0) out vec4 outColour;

void main() {
    outColour = colour * texture(atlas, uv);
}
