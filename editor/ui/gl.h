#pragma once
// OpenGL 3.3 core declarations. Mesa's and NVIDIA's libGL export every core entry point, so
// the prototypes are used directly (no loader); GLFW must not include its own GL header.
#define GL_GLEXT_PROTOTYPES 1
#include <GL/glcorearb.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
