// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/frame_triptych.h"

#include <QTextDocument>

#include <QCheckBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QElapsedTimer>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>
#include <cmath>

#include "common/reading_label.h"
#include "vision/frames/frame_image.h"
#include "vision/image_pane.h"
#include "vision/lens/view_geometry.h"

namespace bs::ui {

struct FrameTriptych::Job {
  std::uint64_t generation = 0;
  Frame meta;
  cv::Mat raw;
  cv::Mat demosaiced;  // reused when only the lens changed
  vision::DemosaicMethod method{};
  vision::Lens lens;
  vision::View view;
  CancelToken cancel;
  vision::TriptychImages out;
  QString error;
};

namespace {

QImage to_qimage(const cv::Mat& m8) {
  if (m8.empty()) return {};
  if (m8.channels() == 1)
    return QImage(m8.data, m8.cols, m8.rows, static_cast<qsizetype>(m8.step), QImage::Format_Grayscale8).copy();
  return QImage(m8.data, m8.cols, m8.rows, static_cast<qsizetype>(m8.step), QImage::Format_BGR888).copy();
}

cv::Vec3i rgb_at(const cv::Mat& bgr, int x, int y) {
  if (bgr.depth() == CV_16U) {
    const auto v = bgr.at<cv::Vec3w>(y, x);
    return {v[2], v[1], v[0]};
  }
  const auto v = bgr.at<cv::Vec3b>(y, x);
  return {v[2], v[1], v[0]};
}

QString method_name(vision::DemosaicMethod m) {
  switch (m) {
    case vision::DemosaicMethod::Bilinear:
      return QObject::tr("bilinear");
    case vision::DemosaicMethod::MalvarHeCutler:
      return QObject::tr("Malvar-He-Cutler");
    case vision::DemosaicMethod::OpenCvBilinear:
      return QObject::tr("OpenCV bilinear");
    case vision::DemosaicMethod::OpenCvEdgeAware:
      return QObject::tr("OpenCV edge-aware");
    case vision::DemosaicMethod::OpenCvVng:
      return QObject::tr("OpenCV VNG");
  }
  return {};
}

}  // namespace

FrameTriptych::FrameTriptych(QWidget* parent)
    : QWidget(parent),
      method_box_(new QComboBox(this)),
      low_box_(new QSpinBox(this)),
      high_box_(new QSpinBox(this)),
      full_range_(new QPushButton(tr("Full range"), this)),
      overlay_box_(new QCheckBox(tr("Outlines"), this)),
      banner_(new QLabel(this)),
      inspector_(reading_label(this)),
      watcher_(new QFutureWatcher<std::shared_ptr<Job>>(this)) {
  auto* controls = new QHBoxLayout;
  controls->addWidget(new QLabel(tr("Demosaic:"), this));
  method_box_->addItem(tr("Bilinear (ours)"), static_cast<int>(vision::DemosaicMethod::Bilinear));
  method_box_->addItem(tr("Malvar-He-Cutler (ours)"), static_cast<int>(vision::DemosaicMethod::MalvarHeCutler));
  method_box_->addItem(tr("OpenCV bilinear"), static_cast<int>(vision::DemosaicMethod::OpenCvBilinear));
  method_box_->setToolTip(tr("Demosaicing method for panel (b); panel (c) reprojects its result"));
  controls->addWidget(method_box_);
  controls->addSpacing(16);
  auto* window_label = new QLabel(tr("Window (counts):"), this);
  window_label->setToolTip(tr("Display window: sample values from low to high are shown from black to white"));
  controls->addWidget(window_label);
  for (QSpinBox* b : {low_box_, high_box_}) {
    b->setRange(0, 65535);
    b->setToolTip(tr("Display window: sample values from low to high are shown from black to white"));
  }
  controls->addWidget(low_box_);
  controls->addWidget(new QLabel(QStringLiteral("–"), this));
  controls->addWidget(high_box_);
  full_range_->setToolTip(tr("Window = 0 to the largest value of the frame's bit depth"));
  controls->addWidget(full_range_);
  controls->addSpacing(16);
  overlay_box_->setChecked(true);
  overlay_box_->setToolTip(
      tr("On the fisheye panels: the image circle of the lens's field of view (yellow) and "
         "the border of the reprojected view (cyan)"));
  controls->addWidget(overlay_box_);
  controls->addStretch(1);

  auto* row = new QHBoxLayout;
  row->setSpacing(4);
  const char* titles[] = {"(a) Raw Bayer mosaic", "(b) Demosaiced", "(c) Reprojected"};
  for (int i = 0; i < 3; ++i) {
    panes_[static_cast<std::size_t>(i)] = new ImagePane(tr(titles[i]), this);
    ImagePane* p = panes_[static_cast<std::size_t>(i)];
    row->addWidget(p, 1);
    connect(p, &ImagePane::view_changed, this, [this, i](double z, QPointF c) { sync_from(i, z, c); });
    connect(p, &ImagePane::cursor_moved, this, [this, i](QPointF q) { show_inspection(i, q); });
    connect(p, &ImagePane::cursor_left, this, [this] {
      for (ImagePane* q : panes_) q->set_marker(std::nullopt);
    });
  }
  banner_->setWordWrap(true);
  inspector_->setText(tr("Move the cursor over an image to inspect its pixels."));
  QFont mono = inspector_->font();
  mono.setStyleHint(QFont::Monospace);
  mono.setFamily(QStringLiteral("monospace"));
  inspector_->setFont(mono);

  auto* layout = new QVBoxLayout(this);
  layout->addLayout(controls);
  layout->addWidget(banner_);
  layout->addLayout(row, 1);
  layout->addWidget(inspector_);

  connect(method_box_, &QComboBox::currentIndexChanged, this,
          [this] { set_demosaic_method(static_cast<vision::DemosaicMethod>(method_box_->currentData().toInt())); });
  connect(low_box_, &QSpinBox::valueChanged, this, [this](int v) { set_window(v, std::max(v + 1, window_high_)); });
  connect(high_box_, &QSpinBox::valueChanged, this, [this](int v) { set_window(std::min(window_low_, v - 1), v); });
  connect(full_range_, &QPushButton::clicked, this,
          [this] { set_window(0, static_cast<int>(vision::full_scale(frame_))); });
  connect(overlay_box_, &QCheckBox::toggled, this, &FrameTriptych::set_overlays_visible);
  connect(watcher_, &QFutureWatcher<std::shared_ptr<Job>>::finished, this, &FrameTriptych::job_finished);
  clear(tr("No frame: import a capture (.raw + sidecar, PGM, PNG, TIFF) into the workspace."));
}

FrameTriptych::~FrameTriptych() {
  if (running_) running_->cancel.cancel();
  watcher_->waitForFinished();
}

void FrameTriptych::clear(const QString& message) {
  ++generation_;
  if (running_) running_->cancel.cancel();
  pending_ = false;
  raw_ = cv::Mat();
  frame_ = Frame();
  images_ = {};
  for (ImagePane* p : panes_) {
    p->set_message(message);
    p->set_overlays({});
    p->set_marker(std::nullopt);
  }
  banner_->clear();
  banner_->hide();
  for (QWidget* w : std::initializer_list<QWidget*>{method_box_, low_box_, high_box_, full_range_, overlay_box_})
    w->setEnabled(false);
}

void FrameTriptych::set_frame(const Frame& frame) { set_frame(frame, vision::resolve_frame_lens(frame)); }

void FrameTriptych::set_frame(const Frame& frame, const vision::ResolvedLens& resolved) {
  try {
    raw_ = vision::frame_to_mat(frame);
  } catch (const std::exception& e) {
    clear(tr("Cannot show %1: %2").arg(QString::fromStdString(frame.label), QString::fromUtf8(e.what())));
    return;
  }
  frame_ = frame;
  frame_.pixels.clear();  // kept once, in raw_
  lens_ = resolved.lens;
  view_ = resolved.view;
  lens_source_ = QString::fromStdString(vision::describe_lens_source(resolved));
  images_ = {};
  const int top = static_cast<int>(vision::full_scale(frame_));
  for (QSpinBox* b : {low_box_, high_box_}) {
    const QSignalBlocker block(b);
    b->setRange(0, top);
  }
  window_low_ = 0;
  window_high_ = top;
  {
    const QSignalBlocker a(low_box_), b(high_box_);
    low_box_->setValue(0);
    high_box_->setValue(top);
  }
  for (QWidget* w : std::initializer_list<QWidget*>{low_box_, high_box_, full_range_, overlay_box_})
    w->setEnabled(true);
  method_box_->setEnabled(frame_.is_mosaic());
  update_banner();
  banner_->show();
  for (ImagePane* p : panes_) {
    p->set_message(tr("Rendering…"));
    p->set_view(1, QPointF(0.5, 0.5));
  }
  update_titles();
  request_render(true);
}

void FrameTriptych::update_banner() {
  QString banner;
  if (frame_.synthetic)
    banner = tr("<b>Synthetic capture</b>: a test chart rendered through a lens model, not a camera image. ");
  // Which lens reprojects panel (c), always: saved, recorded, tuned or the paper's default.
  banner +=
      tr("Lens: <b>%1</b> (%2).")
          .arg(lens_source_.toHtmlEscaped(), QString::fromStdString(vision::describe_lens(lens_)).toHtmlEscaped());
  banner_->setText(banner);
}

QString FrameTriptych::banner_text() const {
  QTextDocument doc;
  doc.setHtml(banner_->text());
  return doc.toPlainText();
}

void FrameTriptych::set_lens(const vision::Lens& lens, const vision::View& view) {
  set_lens(lens, view, tr("tuned in the Lens tab"));
}

void FrameTriptych::set_lens(const vision::Lens& lens, const vision::View& view, const QString& source) {
  lens_ = lens;
  view_ = view;
  lens_source_ = source;
  if (has_frame()) update_banner();
  update_titles();
  if (has_frame()) request_render(false);
}

void FrameTriptych::set_demosaic_method(vision::DemosaicMethod method) {
  if (method == method_) return;
  method_ = method;
  const int index = method_box_->findData(static_cast<int>(method));
  if (index >= 0 && method_box_->currentIndex() != index) {
    const QSignalBlocker block(method_box_);
    method_box_->setCurrentIndex(index);
  }
  update_titles();
  if (has_frame()) request_render(true);
}

void FrameTriptych::set_window(int low, int high) {
  const int top = has_frame() ? static_cast<int>(vision::full_scale(frame_)) : 65535;
  window_low_ = std::clamp(low, 0, top - 1);
  window_high_ = std::clamp(high, window_low_ + 1, top);
  const QSignalBlocker a(low_box_), b(high_box_);
  low_box_->setValue(window_low_);
  high_box_->setValue(window_high_);
  update_display();
}

void FrameTriptych::set_overlays_visible(bool on) {
  overlays_ = on;
  if (overlay_box_->isChecked() != on) {
    const QSignalBlocker block(overlay_box_);
    overlay_box_->setChecked(on);
  }
  update_overlays();
}

void FrameTriptych::set_view(double zoom, QPointF centre) {
  for (ImagePane* p : panes_) p->set_view(zoom, centre);
}

void FrameTriptych::sync_from(int pane, double zoom, QPointF centre) {
  for (int i = 0; i < 3; ++i)
    if (i != pane) panes_[static_cast<std::size_t>(i)]->set_view(zoom, centre);
}

// ---- rendering off the GUI thread -----------------------------------------------------------------------------

void FrameTriptych::request_render(bool demosaic_again) {
  pending_demosaic_ = pending_demosaic_ || demosaic_again;
  ++generation_;
  if (running_) {
    // The running job is stale now: stop it at its next stage boundary and start the newest request after it.
    running_->cancel.cancel();
    pending_ = true;
    return;
  }
  start_job();
}

void FrameTriptych::start_job() {
  auto job = std::make_shared<Job>();
  job->generation = generation_;
  job->meta = frame_;
  job->raw = raw_;
  if (!pending_demosaic_ && !images_.demosaiced.empty()) job->demosaiced = images_.demosaiced;
  pending_demosaic_ = false;
  pending_ = false;
  job->method = method_;
  job->lens = lens_;
  job->view = view_;
  running_ = job;
  watcher_->setFuture(QtConcurrent::run([job] {
    try {
      if (job->demosaiced.empty()) {
        job->out = vision::render_triptych(job->raw, job->meta, job->method, job->lens, job->view, &job->cancel);
      } else {
        // Only the lens or view changed: the demosaiced image stands, reproject it again.
        job->out.demosaiced = job->demosaiced;
        job->out.reprojected = vision::ReprojectionLut(job->lens, job->view).apply(job->demosaiced);
      }
    } catch (const Cancelled&) {
      job->error = QStringLiteral("cancelled");
    } catch (const std::exception& e) {
      job->error = QString::fromUtf8(e.what());
    }
    return job;
  }));
}

void FrameTriptych::job_finished() {
  const std::shared_ptr<Job> job = watcher_->result();
  running_.reset();
  const bool current = job->generation == generation_;
  if (current && job->error.isEmpty()) {
    if (job->out.mosaic.empty()) job->out.mosaic = images_.mosaic;  // a reprojection-only job
    images_ = std::move(job->out);
    update_display();
    update_overlays();
    emit rendered();
  } else if (current && job->error != QLatin1String("cancelled")) {
    panes_[2]->set_message(tr("Cannot reproject: %1").arg(job->error));
    emit render_failed(job->error);
  }
  if (pending_ || (!current && has_frame())) {
    if (!current) pending_demosaic_ = pending_demosaic_ || job->demosaiced.empty();
    start_job();
  }
}

bool FrameTriptych::wait_until_rendered(int timeout_ms) {
  QElapsedTimer t;
  t.start();
  while (running_ || pending_) {
    if (t.elapsed() > timeout_ms) return false;
    QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
  }
  return true;
}

// ---- display --------------------------------------------------------------------------------------------------

void FrameTriptych::update_display() {
  if (images_.demosaiced.empty()) return;
  const auto panels = panel_images();
  for (std::size_t i = 0; i < 3; ++i) panes_[i]->set_image(panels[i]);
}

std::array<QImage, 3> FrameTriptych::panel_images() const {
  std::array<QImage, 3> out;
  if (images_.demosaiced.empty()) return out;
  const cv::Mat* mats[] = {&images_.mosaic, &images_.demosaiced, &images_.reprojected};
  for (std::size_t i = 0; i < 3; ++i) out[i] = to_qimage(vision::window_to_8bit(*mats[i], window_low_, window_high_));
  return out;
}

void FrameTriptych::update_overlays() {
  std::vector<ImagePane::Overlay> overlays;
  if (overlays_ && has_frame()) {
    // Image coordinates of the panes put pixel centres at +0.5; core's coordinates put them at integers.
    if (const auto circle = vision::image_circle(lens_)) {
      QPolygonF poly;
      for (int i = 0; i < 180; ++i) {
        const double a = 2 * M_PI * i / 180;
        poly << QPointF(circle->centre.x + 0.5 + circle->radius * std::cos(a),
                        circle->centre.y + 0.5 + circle->radius * std::sin(a));
      }
      overlays.push_back({poly, true, QColor(255, 210, 0)});
    }
    QPolygonF outline;
    for (const cv::Point2d& p : vision::view_outline(lens_, view_)) outline << QPointF(p.x + 0.5, p.y + 0.5);
    if (!outline.isEmpty()) overlays.push_back({outline, true, QColor(0, 220, 255)});
  }
  panes_[0]->set_overlays(overlays);
  panes_[1]->set_overlays(overlays);
}

void FrameTriptych::update_titles() {
  const auto c = captions();
  panes_[0]->set_title(c[0] + tr(", shown as grey"));
  panes_[1]->set_title(c[1]);
  panes_[2]->set_title(c[2] + tr(", %1×%2 px").arg(view_.width).arg(view_.height));
}

std::array<QString, 3> FrameTriptych::captions() const {
  // Short enough to fit on one line under a panel one third of a 7.16 in column wide, at 8 pt.
  const QString bits = tr("%1-bit").arg(frame_.bit_depth);
  const QString a = frame_.is_mosaic()
                        ? tr("(a) Raw Bayer mosaic (%1, %2)").arg(QString::fromStdString(frame_.pattern), bits)
                        : tr("(a) Raw image as grey (%1)").arg(bits);
  const QString b =
      frame_.is_mosaic() ? tr("(b) Demosaiced (%1)").arg(method_name(method_)) : tr("(b) Colour (no mosaic)");
  const QString c = tr("(c) Reprojected (%1° rectilinear)").arg(view_.fov_deg, 0, 'g', 4);
  return {a, b, c};
}

// ---- pixel inspector ------------------------------------------------------------------------------------------

PixelInspection FrameTriptych::inspect(int pane, QPointF q) const {
  PixelInspection r;
  if (!has_frame()) return r;
  if (pane == 2) {
    const cv::Point o(static_cast<int>(std::floor(q.x())), static_cast<int>(std::floor(q.y())));
    if (o.x < 0 || o.y < 0 || o.x >= view_.width || o.y >= view_.height) return r;
    r.output = o;
    r.output_exact = cv::Point2d(o.x, o.y);
    r.fisheye_exact = vision::source_of(lens_, view_, o.x, o.y);
    if (r.fisheye_exact)
      r.fisheye = cv::Point(static_cast<int>(std::lround(r.fisheye_exact->x)),
                            static_cast<int>(std::lround(r.fisheye_exact->y)));
  } else {
    const cv::Point f(static_cast<int>(std::floor(q.x())), static_cast<int>(std::floor(q.y())));
    if (f.x < 0 || f.y < 0 || f.x >= raw_.cols || f.y >= raw_.rows) return r;
    r.fisheye = f;
    r.fisheye_exact = cv::Point2d(f.x, f.y);
    r.output_exact = vision::output_of(lens_, view_, f.x, f.y);
    if (r.output_exact)
      r.output =
          cv::Point(static_cast<int>(std::lround(r.output_exact->x)), static_cast<int>(std::lround(r.output_exact->y)));
  }
  if (r.fisheye) {
    const int x = r.fisheye->x, y = r.fisheye->y;
    if (raw_.channels() == 1) {
      r.raw = raw_.depth() == CV_16U ? raw_.at<std::uint16_t>(y, x) : raw_.at<std::uint8_t>(y, x);
      if (const auto pattern = vision::frame_pattern(frame_))
        r.channel = "BGR"[vision::bayer_channel(*pattern, y, x)];
      else
        r.channel = 'Y';
    } else {
      r.raw = images_.mosaic.empty()             ? -1
              : images_.mosaic.depth() == CV_16U ? images_.mosaic.at<std::uint16_t>(y, x)
                                                 : images_.mosaic.at<std::uint8_t>(y, x);
      r.channel = 'Y';
    }
    if (!images_.demosaiced.empty()) r.fisheye_rgb = rgb_at(images_.demosaiced, x, y);
  }
  if (r.output && !images_.reprojected.empty() && r.output->x < images_.reprojected.cols &&
      r.output->y < images_.reprojected.rows)
    r.output_rgb = rgb_at(images_.reprojected, r.output->x, r.output->y);
  return r;
}

void FrameTriptych::show_inspection(int pane, QPointF image_point) {
  const PixelInspection r = inspect(pane, image_point);
  const auto rgb = [](const std::optional<cv::Vec3i>& v) {
    return v ? QStringLiteral("(%1, %2, %3)").arg((*v)[0]).arg((*v)[1]).arg((*v)[2]) : QStringLiteral("–");
  };
  QString text;
  if (r.fisheye)
    text = tr("fisheye (x, y) = (%1, %2) px   raw = %3 counts (%4)   RGB = %5 counts")
               .arg(r.fisheye->x)
               .arg(r.fisheye->y)
               .arg(r.raw)
               .arg(QChar(r.channel))
               .arg(rgb(r.fisheye_rgb));
  else
    text = tr("fisheye: outside the lens's field of view");
  text += QStringLiteral("\n");
  if (r.output_exact)
    text += tr("output  (x, y) = (%1, %2) px   RGB = %3 counts")
                .arg(r.output_exact->x, 0, 'f', 1)
                .arg(r.output_exact->y, 0, 'f', 1)
                .arg(rgb(r.output_rgb));
  else
    text += tr("output: this point is not in the reprojected view");
  inspector_->setText(text);
  const std::optional<QPointF> fish =
      r.fisheye_exact ? std::optional<QPointF>(QPointF(r.fisheye_exact->x + 0.5, r.fisheye_exact->y + 0.5))
                      : std::nullopt;
  const std::optional<QPointF> out =
      r.output_exact ? std::optional<QPointF>(QPointF(r.output_exact->x + 0.5, r.output_exact->y + 0.5)) : std::nullopt;
  for (int i = 0; i < 3; ++i)
    panes_[static_cast<std::size_t>(i)]->set_marker(i == pane ? std::nullopt : (i == 2 ? out : fish));
  emit cursor_moved(r.fisheye_exact ? QPointF(r.fisheye_exact->x, r.fisheye_exact->y) : QPointF(-1, -1),
                    r.output_exact ? QPointF(r.output_exact->x, r.output_exact->y) : QPointF(-1, -1));
}

QString FrameTriptych::inspector_text() const { return inspector_->text(); }

}  // namespace bs::ui
