#version 330 core
// Void cells: flat colour.
flat in vec4 fill;
out vec4 colour;
void main() {
    colour = fill;
}
