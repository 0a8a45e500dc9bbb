#version 330 core
out vec4 fragColour;
void main() {
    fragColour = vec4(0.3, 0.55, 0.2, 1.0);
}
