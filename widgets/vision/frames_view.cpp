// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/frames_view.h"

#include <QFileDialog>
#include <QHBoxLayout>
#include <QListWidget>
#include <QMessageBox>
#include <QSplitter>

#include "frames/frame_store.h"
#include "triptych_panels.h"
#include "vision/frame_triptych.h"

namespace bs::ui {

FramesView::FramesView(QWidget* parent)
    : QWidget(parent), list_(new QListWidget(this)), triptych_(new FrameTriptych(this)) {
  auto* split = new QSplitter(Qt::Horizontal, this);
  split->addWidget(list_);
  split->addWidget(triptych_);
  split->setStretchFactor(0, 0);
  split->setStretchFactor(1, 1);
  split->setSizes({220, 1200});
  list_->setMinimumWidth(160);
  list_->setWordWrap(true);
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(split);
  connect(list_, &QListWidget::currentRowChanged, this, &FramesView::show_frame);
}

void FramesView::set_workspace(const Workspace* ws) {
  const std::int64_t keep = ws == ws_ ? current_frame_id() : 0;  // a reload keeps the frame in view
  ws_ = ws;
  frames_ = ws ? ws->frames() : std::vector<StoredFrame>{};
  const QSignalBlocker block(list_);
  list_->clear();
  for (const StoredFrame& s : frames_) {
    const Frame& f = s.frame;
    const QString kind =
        f.is_mosaic() ? QString::fromStdString(f.pattern) : (f.channels == 3 ? tr("colour") : tr("grey"));
    auto* item = new QListWidgetItem(
        tr("%1\n%2×%3 px, %4, %5-bit\n%6, %7")
            .arg(QString::fromStdString(f.label))
            .arg(f.width)
            .arg(f.height)
            .arg(kind)
            .arg(f.bit_depth)
            .arg(f.synthetic ? tr("synthetic") : tr("captured"))
            .arg(f.storage == FrameStorage::Copy ? tr("copied into the workspace") : tr("by reference")),
        list_);
    item->setToolTip(QString::fromStdString(s.path));
  }
  if (frames_.empty()) {
    triptych_->clear(
        tr("This workspace has no frames. Import a capture: a .raw file with its JSON sidecar, PGM/PPM, "
           "PNG or TIFF (File > Import files, or benchscope-cli import WS FILE.raw)."));
    return;
  }
  int row = 0;
  for (std::size_t i = 0; i < frames_.size(); ++i)
    if (frames_[i].id == keep) row = static_cast<int>(i);
  list_->setCurrentRow(row);
  show_frame(row);
}

void FramesView::select(int index) { list_->setCurrentRow(index); }

const StoredFrame* FramesView::current_frame() const {
  const int row = list_->currentRow();
  if (row < 0 || row >= static_cast<int>(frames_.size())) return nullptr;
  return &frames_[static_cast<std::size_t>(row)];
}

std::int64_t FramesView::current_frame_id() const {
  const StoredFrame* f = current_frame();
  return f ? f->id : 0;
}

bool FramesView::select_frame_id(std::int64_t id) {
  for (std::size_t i = 0; i < frames_.size(); ++i)
    if (frames_[i].id == id) {
      list_->setCurrentRow(static_cast<int>(i));
      return true;
    }
  return false;
}

void FramesView::show_frame(int index) {
  if (!ws_ || index < 0 || index >= static_cast<int>(frames_.size())) return;
  const StoredFrame& s = frames_[static_cast<std::size_t>(index)];
  try {
    // A copy comes from the workspace, a reference is read again and checked against its content hash.
    // With the lens the workspace gives it (saved for the frame or its camera, recorded, or the paper's).
    triptych_->set_frame(load_frame(*ws_, s), vision::resolve_frame_lens(ws_, s));
  } catch (const std::exception& e) {
    triptych_->clear(tr("Cannot show %1:\n%2").arg(QString::fromStdString(s.frame.label), QString::fromUtf8(e.what())));
  }
  emit frame_selected(s.id);
}

bool FramesView::export_figure(const QString& path, QString* error) {
  if (!triptych_->has_frame()) {
    if (error) *error = tr("no frame is shown");
    return false;
  }
  if (!triptych_->wait_until_rendered(60000)) {
    if (error) *error = tr("the triptych is still rendering");
    return false;
  }
  return export_triptych_figure(path, triptych_->panel_images(), triptych_->captions(), error);
}

void FramesView::export_figure_dialog() {
  if (!triptych_->has_frame()) {
    QMessageBox::information(this, tr("Export Figure 3"), tr("Open the Frames tab and select a frame first."));
    return;
  }
  const QString path = QFileDialog::getSaveFileName(
      this, tr("Export Figure 3 (triptych)"), QStringLiteral("figure3.pdf"), tr("PDF (*.pdf);;PNG image (*.png)"));
  if (path.isEmpty()) return;
  QString error;
  if (!export_figure(path, &error)) QMessageBox::warning(this, tr("Export Figure 3"), error);
}

}  // namespace bs::ui
