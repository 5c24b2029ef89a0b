// The OpenGL set-up the VTK views need. Qt creates every QOpenGLWidget's context from the default
// surface format, so it must be set before QApplication exists: the application's main() and
// every GUI test's main() call setDefaultSurfaceFormat() first.
#pragma once

#include <QSurfaceFormat>

namespace armtrack::ui {

/// OpenGL 3.2 core profile, 8-bit RGBA, a 24-bit depth buffer, no stencil, no multisampling:
/// what VTK's OpenGL2 backend renders with (Mesa's llvmpipe under Xvfb included).
QSurfaceFormat vtkSurfaceFormat();

/// Makes vtkSurfaceFormat() the default. Call before constructing QApplication (main thread).
void setDefaultSurfaceFormat();

}  // namespace armtrack::ui
