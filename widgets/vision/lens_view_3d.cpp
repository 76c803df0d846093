// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/lens_view_3d.h"

#include <QMouseEvent>
#include <QOpenGLContext>
#include <QOpenGLExtraFunctions>
#include <QSurfaceFormat>
#include <QWheelEvent>
#include <cmath>
#include <cstdio>
#include <string>

#include <vtkActor.h>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCommand.h>
#include <vtkFloatArray.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkGenericRenderWindowInteractor.h>
#include <vtkImageData.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkNew.h>
#include <vtkOpenGLFramebufferObject.h>
#include <vtkOpenGLState.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkTexture.h>
#include <vtkUnsignedCharArray.h>

namespace bs::ui {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kRings = 72, kSectors = 144;  // sphere patch resolution: 1.4 degrees per ring at 195 degrees

// The overlays (the output camera's frustum, its image plane, the lens axis) are drawn in one flat colour, unlit, so
// that they read the same from every side; the caller then gives each its line width or opacity.
vtkProperty* show_unlit(vtkPolyData* data, vtkPolyDataMapper* mapper, vtkActor* actor, double r, double g, double b) {
  mapper->SetInputData(data);
  actor->SetMapper(mapper);
  vtkProperty* look = actor->GetProperty();
  look->SetColor(r, g, b);
  look->LightingOff();
  return look;
}

}  // namespace

void set_vtk_default_surface_format() {
  QSurfaceFormat fmt;
  fmt.setRenderableType(QSurfaceFormat::OpenGL);
  fmt.setVersion(3, 2);
  fmt.setProfile(QSurfaceFormat::CoreProfile);
  fmt.setSwapBehavior(QSurfaceFormat::DoubleBuffer);
  fmt.setRedBufferSize(8);
  fmt.setGreenBufferSize(8);
  fmt.setBlueBufferSize(8);
  fmt.setAlphaBufferSize(8);
  fmt.setDepthBufferSize(24);
  QSurfaceFormat::setDefaultFormat(fmt);
}

struct LensView3D::Impl {
  LensView3D* widget;
  vtkNew<vtkGenericOpenGLRenderWindow> window;
  vtkNew<vtkGenericRenderWindowInteractor> interactor;
  vtkNew<vtkInteractorStyleTrackballCamera> style;
  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkPolyData> patch;
  vtkNew<vtkPolyDataMapper> patch_mapper;
  vtkNew<vtkActor> patch_actor;
  vtkNew<vtkTexture> texture;
  vtkNew<vtkImageData> image;
  vtkNew<vtkPolyData> frustum;
  vtkNew<vtkPolyDataMapper> frustum_mapper;
  vtkNew<vtkActor> frustum_actor;
  vtkNew<vtkPolyData> plane;
  vtkNew<vtkPolyDataMapper> plane_mapper;
  vtkNew<vtkActor> plane_actor;
  vtkNew<vtkTextActor> caption;
  vtkNew<vtkPolyData> lens_axis;
  vtkNew<vtkPolyDataMapper> lens_axis_mapper;
  vtkNew<vtkActor> lens_axis_actor;
  vision::Lens lens = vision::Lens::paper();
  vision::View view;
  bool have_image = false;
  int triangles = 0;

  // VTK asks for its context: make the widget's context current only when it is not already. Never
  // QOpenGLWidget::makeCurrent(): that rebinds Qt's FBO behind VTK's state cache (toolchain-facts.md).
  void make_current(vtkObject*, unsigned long, void*) {
    QOpenGLContext* ctx = widget->context();
    if (ctx && QOpenGLContext::currentContext() != ctx) ctx->makeCurrent(ctx->surface());
  }
  void is_current(vtkObject*, unsigned long, void* data) {
    QOpenGLContext* ctx = widget->context();
    *static_cast<bool*>(data) = ctx && QOpenGLContext::currentContext() == ctx;
  }
  void supports_opengl(vtkObject*, unsigned long, void* data) { *static_cast<int*>(data) = 1; }
  void is_direct(vtkObject*, unsigned long, void* data) { *static_cast<int*>(data) = 1; }
  void render_requested(vtkObject*, unsigned long, void*) { widget->update(); }
};

LensView3D::LensView3D(QWidget* parent) : QOpenGLWidget(parent), d_(std::make_unique<Impl>()) {
  d_->widget = this;
  setMinimumSize(240, 200);
  setFocusPolicy(Qt::StrongFocus);
  setToolTip(
      tr("Lens in 3D: the fisheye frame on the unit sphere of rays it covers (lens axis along the grey "
         "line), the output camera's frustum (yellow) and image plane. Drag to rotate, wheel to zoom."));
  auto& w = *d_->window;
  w.SetReadyForRendering(false);
  w.SetFrameBlitModeToNoBlit();
  w.SetMultiSamples(0);
  w.AddObserver(vtkCommand::WindowMakeCurrentEvent, d_.get(), &Impl::make_current);
  w.AddObserver(vtkCommand::WindowIsCurrentEvent, d_.get(), &Impl::is_current);
  w.AddObserver(vtkCommand::WindowSupportsOpenGLEvent, d_.get(), &Impl::supports_opengl);
  w.AddObserver(vtkCommand::WindowIsDirectEvent, d_.get(), &Impl::is_direct);
  w.AddRenderer(d_->renderer);
  d_->interactor->SetRenderWindow(&w);
  d_->interactor->SetInteractorStyle(d_->style);
  d_->interactor->EnableRenderOff();  // the interactor asks for a repaint; paintGL renders
  d_->interactor->AddObserver(vtkCommand::RenderEvent, d_.get(), &Impl::render_requested);

  d_->renderer->SetBackground(0.13, 0.14, 0.17);
  d_->patch_mapper->SetInputData(d_->patch);
  d_->patch_actor->SetMapper(d_->patch_mapper);
  d_->texture->SetInputData(d_->image);
  d_->texture->InterpolateOn();
  d_->texture->EdgeClampOn();
  d_->patch_actor->SetTexture(d_->texture);
  d_->patch_actor->GetProperty()->SetAmbient(1.0);  // show the frame's own colours, unshaded
  d_->patch_actor->GetProperty()->SetDiffuse(0.0);
  d_->patch_actor->GetProperty()->BackfaceCullingOff();
  show_unlit(d_->frustum, d_->frustum_mapper, d_->frustum_actor, 1.0, 0.85, 0.1)->SetLineWidth(2.0);
  show_unlit(d_->plane, d_->plane_mapper, d_->plane_actor, 1.0, 0.85, 0.1)->SetOpacity(0.12);
  d_->renderer->AddActor(d_->patch_actor);
  d_->renderer->AddActor(d_->frustum_actor);
  d_->renderer->AddActor(d_->plane_actor);
  {
    // The lens's optical axis (+x in ray space), through the centre of the image circle.
    vtkNew<vtkPoints> ap;
    ap->InsertNextPoint(0, 0, 0);
    ap->InsertNextPoint(1.4, 0, 0);
    vtkNew<vtkCellArray> al;
    const vtkIdType seg[2] = {0, 1};
    al->InsertNextCell(2, seg);
    d_->lens_axis->SetPoints(ap);
    d_->lens_axis->SetLines(al);
    show_unlit(d_->lens_axis, d_->lens_axis_mapper, d_->lens_axis_actor, 0.75, 0.75, 0.75)->SetLineWidth(2.0);
    d_->renderer->AddActor(d_->lens_axis_actor);
  }
  d_->caption->GetTextProperty()->SetFontSize(14);
  d_->caption->GetTextProperty()->SetColor(0.9, 0.9, 0.9);
  d_->caption->SetDisplayPosition(8, 8);
  d_->renderer->AddActor2D(d_->caption);
  rebuild();
  reset_camera();
}

LensView3D::~LensView3D() {
  // Release VTK's GL resources with our context current, then let VTK forget it.
  if (context()) {
    makeCurrent();
    d_->window->Finalize();
    doneCurrent();
  }
}

void LensView3D::reset_camera() {
  vtkCamera* cam = d_->renderer->GetActiveCamera();
  // From behind and above the lens, looking into the bowl of rays: the frame appears as the lens saw it.
  cam->SetFocalPoint(0.2, 0, 0);
  cam->SetPosition(-3.4, 2.3, 2.2);
  cam->SetViewUp(0, 0, 1);
  cam->SetViewAngle(32);
  d_->renderer->ResetCameraClippingRange();
  update();
}

int LensView3D::textured_triangles() const { return d_->triangles; }

void LensView3D::set_fisheye(const cv::Mat& bgr) {
  if (bgr.empty() || bgr.depth() != CV_8U || (bgr.channels() != 3 && bgr.channels() != 1)) return;
  vtkImageData* img = d_->image;
  img->SetDimensions(bgr.cols, bgr.rows, 1);
  img->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* out = static_cast<unsigned char*>(img->GetScalarPointer());
  // Row 0 of the frame becomes texture row t = 0; the texture coordinates below use the same convention.
  for (int y = 0; y < bgr.rows; ++y) {
    const auto* row = bgr.ptr<std::uint8_t>(y);
    for (int x = 0; x < bgr.cols; ++x, out += 3) {
      if (bgr.channels() == 3) {
        out[0] = row[3 * x + 2];
        out[1] = row[3 * x + 1];
        out[2] = row[3 * x];
      } else {
        out[0] = out[1] = out[2] = row[x];
      }
    }
  }
  img->Modified();
  d_->have_image = true;
  update();
}

void LensView3D::set_lens(const vision::Lens& lens, const vision::View& view) {
  d_->lens = lens;
  d_->view = view;
  rebuild();
  update();
}

void LensView3D::rebuild() {
  const vision::Lens& lens = d_->lens;
  const vision::View& view = d_->view;
  // Sphere patch: rings of constant angle theta off the lens axis, sectors of azimuth phi. A vertex's texture
  // coordinate is where the lens images that ray: (cx + r(theta) cos phi, cy - r(theta) sin phi).
  double theta_max = lens.fov_deg * kPi / 360;
  if (lens.type == vision::LensType::Orthographic) theta_max = std::min(theta_max, kPi / 2);
  if (lens.type == vision::LensType::Rectilinear) theta_max = std::min(theta_max, kPi / 2 - 0.02);
  vtkNew<vtkPoints> pts;
  vtkNew<vtkFloatArray> tc;
  tc->SetNumberOfComponents(2);
  tc->SetName("tcoords");
  std::vector<char> inside;
  const cv::Point2d c = lens.centre();
  for (int i = 0; i <= kRings; ++i) {
    const double theta = theta_max * i / kRings;
    const auto r = lens.radius(std::min(theta, theta_max));
    for (int j = 0; j <= kSectors; ++j) {
      const double phi = 2 * kPi * j / kSectors;
      const cv::Vec3d ray(std::cos(theta), std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi));
      const cv::Vec3d p = to_scene(ray);
      pts->InsertNextPoint(p[0], p[1], p[2]);
      const double sx = r ? c.x + *r * std::cos(phi) : -1, sy = r ? c.y - *r * std::sin(phi) : -1;
      inside.push_back(r && sx >= 0 && sy >= 0 && sx <= lens.width - 1 && sy <= lens.height - 1);
      tc->InsertNextTuple2((sx + 0.5) / lens.width, (sy + 0.5) / lens.height);
    }
  }
  vtkNew<vtkCellArray> tris;
  const auto id = [](int i, int j) { return static_cast<vtkIdType>(i * (kSectors + 1) + j); };
  d_->triangles = 0;
  for (int i = 0; i < kRings; ++i)
    for (int j = 0; j < kSectors; ++j) {
      const vtkIdType a = id(i, j), b = id(i + 1, j), cc = id(i + 1, j + 1), dd = id(i, j + 1);
      // Only triangles whose corners the sensor recorded (the sensor cuts the paper's circle at top and bottom).
      if (inside[a] && inside[b] && inside[cc]) {
        const vtkIdType t[3] = {a, b, cc};
        tris->InsertNextCell(3, t);
        ++d_->triangles;
      }
      if (inside[a] && inside[cc] && inside[dd]) {
        const vtkIdType t[3] = {a, cc, dd};
        tris->InsertNextCell(3, t);
        ++d_->triangles;
      }
    }
  d_->patch->Initialize();
  d_->patch->SetPoints(pts);
  d_->patch->SetPolys(tris);
  d_->patch->GetPointData()->SetTCoords(tc);
  d_->patch->Modified();

  // Output camera: its four corner rays out to the unit sphere, the lines joining them (the image plane, a
  // rectangle because every corner ray has the same length), and its optical axis; the lens axis in grey.
  const cv::Matx33d R = vision::view_rotation(view);
  const double f = view.focal_px(), hx = (view.width - 1) / 2.0, hy = (view.height - 1) / 2.0;
  vtkNew<vtkPoints> fp;
  fp->InsertNextPoint(0, 0, 0);
  const double corners[4][2] = {{-hx, hy}, {hx, hy}, {hx, -hy}, {-hx, -hy}};
  for (const auto& k : corners) {
    cv::Vec3d v(f, k[0], k[1]);
    const cv::Vec3d p = to_scene(R * (v / cv::norm(v)));
    fp->InsertNextPoint(p[0], p[1], p[2]);
  }
  const cv::Vec3d axis = to_scene(R * cv::Vec3d(1.25, 0, 0));
  fp->InsertNextPoint(axis[0], axis[1], axis[2]);
  vtkNew<vtkCellArray> lines;
  for (vtkIdType k = 1; k <= 4; ++k) {
    const vtkIdType ray[2] = {0, k}, edge[2] = {k, k % 4 + 1};
    lines->InsertNextCell(2, ray);
    lines->InsertNextCell(2, edge);
  }
  const vtkIdType optical[2] = {0, 5};
  lines->InsertNextCell(2, optical);
  d_->frustum->Initialize();
  d_->frustum->SetPoints(fp);
  d_->frustum->SetLines(lines);
  d_->frustum->Modified();
  vtkNew<vtkCellArray> quad;
  const vtkIdType q[4] = {1, 2, 3, 4};
  quad->InsertNextCell(4, q);
  d_->plane->Initialize();
  d_->plane->SetPoints(fp);
  d_->plane->SetPolys(quad);
  d_->plane->Modified();
  char text[200];
  std::snprintf(
      text, sizeof text,
      "lens: %s, %.1f deg FOV (grey: lens axis)\nview (yellow): %.1f deg FOV, yaw %.1f, pitch %.1f, roll %.1f deg",
      std::string(vision::to_string(lens.type)).c_str(), lens.fov_deg, view.fov_deg, view.yaw_deg, view.pitch_deg,
      view.roll_deg);
  d_->caption->SetInput(text);
  d_->renderer->ResetCameraClippingRange();
}

void LensView3D::initializeGL() {
  auto& w = *d_->window;
  w.SetOwnContext(false);
  w.OpenGLInitContext();
  w.GetState()->Reset();  // VTK's GL state cache must match what Qt left bound
  w.SetReadyForRendering(true);
  d_->interactor->Initialize();
  const qreal dpr = devicePixelRatioF();
  d_->interactor->UpdateSize(static_cast<int>(width() * dpr), static_cast<int>(height() * dpr));
}

void LensView3D::resizeGL(int w, int h) {
  const qreal dpr = devicePixelRatioF();
  d_->interactor->UpdateSize(static_cast<int>(w * dpr), static_cast<int>(h * dpr));
}

void LensView3D::paintGL() {
  auto& w = *d_->window;
  d_->patch_actor->SetVisibility(d_->have_image);
  vtkOpenGLState* state = w.GetState();
  state->Reset();
  state->Push();
  state->vtkglDepthFunc(0x0203);  // GL_LEQUAL: Qt leaves GL_LESS, VTK expects LEQUAL
  d_->renderer->ResetCameraClippingRange();
  w.Render();
  state->Pop();

  // Copy VTK's frame into the widget's framebuffer, then force alpha to 1 (the widget is composited).
  QOpenGLExtraFunctions* f = context()->extraFunctions();
  const int* size = w.GetSize();
  state->PushFramebufferBindings();
  w.GetDisplayFramebuffer()->Bind(GL_READ_FRAMEBUFFER);
  w.GetDisplayFramebuffer()->ActivateReadBuffer(0);
  f->glBindFramebuffer(GL_DRAW_FRAMEBUFFER, defaultFramebufferObject());
  const GLenum attachment = GL_COLOR_ATTACHMENT0;
  f->glDrawBuffers(1, &attachment);
  const GLboolean scissor = f->glIsEnabled(GL_SCISSOR_TEST);
  if (scissor) f->glDisable(GL_SCISSOR_TEST);
  f->glBlitFramebuffer(0, 0, size[0], size[1], 0, 0, size[0], size[1], GL_COLOR_BUFFER_BIT, GL_NEAREST);
  f->glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_TRUE);
  f->glClearColor(0, 0, 0, 1);
  f->glClear(GL_COLOR_BUFFER_BIT);
  f->glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  if (scissor) f->glEnable(GL_SCISSOR_TEST);
  state->PopFramebufferBindings();
}

namespace {

void forward_mouse(vtkGenericRenderWindowInteractor* it, QWidget* w, QMouseEvent* e, unsigned long event) {
  const qreal dpr = w->devicePixelRatioF();
  it->SetEventInformationFlipY(static_cast<int>(e->position().x() * dpr), static_cast<int>(e->position().y() * dpr),
                               (e->modifiers() & Qt::ControlModifier) ? 1 : 0,
                               (e->modifiers() & Qt::ShiftModifier) ? 1 : 0);
  it->InvokeEvent(event, e);
}

unsigned long press_event(Qt::MouseButton b) {
  return b == Qt::LeftButton    ? vtkCommand::LeftButtonPressEvent
         : b == Qt::RightButton ? vtkCommand::RightButtonPressEvent
                                : vtkCommand::MiddleButtonPressEvent;
}
unsigned long release_event(Qt::MouseButton b) {
  return b == Qt::LeftButton    ? vtkCommand::LeftButtonReleaseEvent
         : b == Qt::RightButton ? vtkCommand::RightButtonReleaseEvent
                                : vtkCommand::MiddleButtonReleaseEvent;
}

}  // namespace

void LensView3D::mousePressEvent(QMouseEvent* e) { forward_mouse(d_->interactor, this, e, press_event(e->button())); }
void LensView3D::mouseReleaseEvent(QMouseEvent* e) {
  forward_mouse(d_->interactor, this, e, release_event(e->button()));
}
void LensView3D::mouseMoveEvent(QMouseEvent* e) { forward_mouse(d_->interactor, this, e, vtkCommand::MouseMoveEvent); }
void LensView3D::wheelEvent(QWheelEvent* e) {
  const qreal dpr = devicePixelRatioF();
  d_->interactor->SetEventInformationFlipY(static_cast<int>(e->position().x() * dpr),
                                           static_cast<int>(e->position().y() * dpr));
  d_->interactor->InvokeEvent(
      e->angleDelta().y() > 0 ? vtkCommand::MouseWheelForwardEvent : vtkCommand::MouseWheelBackwardEvent, e);
}

}  // namespace bs::ui
