#pragma once
// Loads OpenGL entry points from whichever context is current: a GLX window
// (freeglut), an OSMesa context or an EGL surfaceless context.
//
// Why this exists: GLEW loads functions through glXGetProcAddressARB, and calls
// the OpenGL 1.0/1.1 functions (glClear, glReadPixels, glGetString, ...) directly
// from libGL. That is right for a window, but with OSMesa libGL knows no context
// and with EGL it cannot answer GLX queries. So Stoa defines glXGetProcAddressARB
// and the OpenGL 1.0/1.1 core functions in every program (FunctionLoader.cpp);
// they forward to the loader of the current backend. One binary then renders in
// a window, through OSMesa and through EGL, on Mesa and on vendor drivers.

namespace stoa::gl {

using ProcAddress = void (*)();
using ProcLoader = ProcAddress (*)(const char* name);

/// The real glXGetProcAddressARB of libGL, for windows.
ProcLoader glxLoader();

/// Makes `loader` answer every GL lookup from now on, loads the OpenGL 1.0/1.1
/// entry points and runs glewInit(). Call it once a context is current.
/// `backendName` is used in error messages. Throws std::runtime_error when the
/// context lacks OpenGL 3.3 or an entry point is missing.
void loadFunctions(ProcLoader loader, const char* backendName);

} // namespace stoa::gl
