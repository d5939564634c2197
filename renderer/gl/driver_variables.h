#pragma once
// Mesa reads its driver choice from the environment when the first context
// is made, and a bad choice can crash inside the library (GALLIUM_DRIVER=bogus
// segfaults in libOSMesa) where no error can be reported. The variables are
// checked before any OpenGL library is loaded instead.
namespace facet::gl {

// Throws facet::Error naming the variable when GALLIUM_DRIVER asks for a
// driver other than llvmpipe, the one driver that gives OpenGL 4.5 core on
// a machine with no GPU.
void checkDriverVariables();

}  // namespace facet::gl
