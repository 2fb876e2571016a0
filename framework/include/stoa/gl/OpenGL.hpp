#pragma once
// The one way to reach OpenGL in Stoa: GLEW's declarations for OpenGL 3.3 core.
// Include this instead of <GL/gl.h> or <GL/glew.h>.

#include <GL/glew.h>
