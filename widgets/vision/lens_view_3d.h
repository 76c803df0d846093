// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// 3D view of a lens setup (VTK inside a QOpenGLWidget): the fisheye frame textured onto the patch of the unit
// sphere of rays the lens covers (texture coordinates from the lens model), the output camera's frustum and its
// image plane. Drag to rotate, wheel to zoom. Needs an X display (VTK here is GLX only): never used in the CLI.
//
// The render window is driven the way VTK 9.1's own Qt 5 adapter (QVTKOpenGLNativeWidget) does it; see
// /work/shared/notes/toolchain-facts.md for what mattered (context handling in WindowMakeCurrentEvent).
#include <QOpenGLWidget>
#include <memory>

#include <opencv2/core.hpp>

#include "vision/lens/lens.h"

namespace bs::ui {

// The default QSurfaceFormat VTK needs (OpenGL 3.2 core, double buffer, RGBA8, 24-bit depth). Must be called
// before QApplication is constructed (app/gui/main.cpp, the display tests).
void set_vtk_default_surface_format();

class LensView3D : public QOpenGLWidget {
  Q_OBJECT
 public:
  explicit LensView3D(QWidget* parent = nullptr);
  ~LensView3D() override;

  void set_fisheye(const cv::Mat& bgr);  // 8-bit BGR or gray
  void set_lens(const vision::Lens& lens, const vision::View& view);
  // Ray space -> scene: +x forward (lens axis), +y right, +z up becomes X forward, Y left, Z up (right-handed).
  static cv::Vec3d to_scene(const cv::Vec3d& ray) { return {ray[0], -ray[1], ray[2]}; }
  int textured_triangles() const;  // triangles of the sphere patch that lie inside the frame (for tests)
  void reset_camera();

 protected:
  void initializeGL() override;
  void resizeGL(int w, int h) override;
  void paintGL() override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;
  QSize sizeHint() const override { return {480, 420}; }

 private:
  struct Impl;
  void rebuild();
  std::unique_ptr<Impl> d_;
};

}  // namespace bs::ui
