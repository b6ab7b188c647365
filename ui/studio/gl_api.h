// OpenGL 3.3 core entry points for the app's own drawing (the 3D views). Mesa's libGL (libglvnd)
// exports every core function, so the prototypes of <GL/glcorearb.h> link directly; Dear ImGui's
// backend keeps its own loader for itself.
#pragma once

#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1
#endif
#include <GL/glcorearb.h>
