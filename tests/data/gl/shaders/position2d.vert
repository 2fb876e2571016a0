#version 330 core
// Passes 2D clip-space positions through (attribute 0).
layout(location = 0) in vec2 aPosition;

void main() {
    gl_Position = vec4(aPosition, 0.0, 1.0);
}
