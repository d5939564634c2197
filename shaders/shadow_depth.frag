#version 450 core
// Shadow pass 1: the window z of each fragment is all it writes.
void main() {}
