// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/pipeline_view.h"

#include <QFile>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>
#include <cmath>
#include <limits>

#include "analysis/platform/pipeline_table.h"
#include "common/numeric_item.h"
#include "platform/inference_table.h"
#include "vision/pipeline_measure_panel.h"

namespace bs::ui {
namespace {

QTableWidgetItem* cell(const QString& text, double sort_value, const QString& tip) {
  auto* item = new NumericItem(text);
  item->setData(kSortRole, sort_value);
  item->setToolTip(tip);
  item->setFlags(Qt::ItemIsSelectable | Qt::ItemIsEnabled);
  return item;
}

QString fps_text(double fps) { return QString::number(fps, 'f', fps >= 100 ? 0 : fps >= 10 ? 1 : 2) + " fps"; }

}  // namespace

PipelineView::PipelineView(QWidget* parent)
    : QWidget(parent),
      measure_(new PipelineMeasurePanel(this)),
      summary_(new QLabel(this)),
      table_(new QTableWidget(0, ColumnCount, this)) {
  table_->setHorizontalHeaderLabels({tr("Stage"), tr("Platform"), tr("Device (backend)"), tr("Time, mean ± SD (n)"),
                                     tr("p95 (ms)"), tr("Stage rate (fps)"), tr("Pipeline (fps)"), tr("Data"),
                                     tr("Lens")});
  table_->horizontalHeaderItem(LensColumn)
      ->setToolTip(tr(
          "How the lens the run reprojected with was obtained: manual, circle fit, checkerboard (RMS, images) or line "
          "fit (residual before/after)"));
  table_->horizontalHeaderItem(Time)->setToolTip(
      tr("Per-frame time of the stage in milliseconds: mean ± sample SD "
         "over n frames"));
  table_->horizontalHeaderItem(StageRate)->setToolTip(
      tr("1 / mean time: the frame rate this stage alone keeps up with"));
  table_->horizontalHeaderItem(Throughput)
      ->setToolTip(tr("Frames through the whole concurrent pipeline per second of wall time (measured runs only)"));
  table_->horizontalHeaderItem(P95)->setToolTip(tr("95th percentile of the per-frame time (measured runs only)"));
  // No sort column until the user picks one: rows keep core's order (stage, then platform), as in the paper.
  table_->horizontalHeader()->setSortIndicator(-1, Qt::AscendingOrder);
  table_->setSortingEnabled(true);
  table_->verticalHeader()->hide();
  table_->setAlternatingRowColors(true);
  table_->setSelectionBehavior(QAbstractItemView::SelectRows);
  // Numbers and names keep their full width; the long device names get a fixed 170 px (the user can widen it),
  // wrapped onto more lines rather than cut (issue #32.7: "Jetson GPU (…ores)" named no device), so the table fits
  // a 1100 px window without scrolling.
  table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  table_->horizontalHeader()->setSectionResizeMode(Device, QHeaderView::Interactive);
  table_->setColumnWidth(Device, 170);
  table_->horizontalHeader()->setSectionResizeMode(LensColumn, QHeaderView::Interactive);
  table_->setColumnWidth(LensColumn, 190);
  table_->setWordWrap(true);
  table_->setTextElideMode(Qt::ElideNone);
  table_->verticalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  summary_->setWordWrap(true);
  summary_->setTextFormat(Qt::RichText);

  auto* latex = new QPushButton(tr("Export LaTeX…"), this);
  auto* csv = new QPushButton(tr("Export CSV…"), this);
  connect(latex, &QPushButton::clicked, this, [this] { export_table(true); });
  connect(csv, &QPushButton::clicked, this, [this] { export_table(false); });
  auto* buttons = new QHBoxLayout;
  buttons->addWidget(summary_, 1);
  buttons->addWidget(latex);
  buttons->addWidget(csv);
  connect(measure_, &PipelineMeasurePanel::run_measured, this, &PipelineView::run_measured);
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(measure_);
  layout->addLayout(buttons);
  layout->addWidget(table_, 2);
  inference_ = new InferenceTable(this);
  layout->addWidget(inference_, 1);
  fill();
}

void PipelineView::set_inference_runs(std::vector<DnnRun> runs) { inference_->set_runs(std::move(runs)); }

void PipelineView::set_data(std::vector<PipelineRun> runs) {
  runs_ = std::move(runs);
  fill();
}

void PipelineView::fill() {
  const auto rows = pipeline_table_rows(runs_);
  table_->setSortingEnabled(false);
  table_->setRowCount(static_cast<int>(rows.size()));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  int reconstructed = 0;
  for (int i = 0; i < static_cast<int>(rows.size()); ++i) {
    const PipelineTableRow& r = rows[static_cast<std::size_t>(i)];
    const QString tip = QString::fromStdString(r.provenance);
    const bool rebuilt = r.origin == DataOrigin::Reconstructed;
    reconstructed += rebuilt;
    // Stages sort in pipeline order (preprocessing, detection, end to end), not alphabetically.
    table_->setItem(i, Stage, cell(QString::fromStdString(r.stage_label), pipeline_stage_order(r.stage), tip));
    table_->setItem(i, Platform, cell(QString::fromStdString(r.platform), nan, tip));
    table_->item(i, Platform)->setData(kSortRole, QVariant());
    const QString device = QString::fromStdString(r.device + " (" + r.backend + ")");
    table_->setItem(i, Device, cell(device, nan, device + "\n\n" + tip));
    table_->item(i, Device)->setData(kSortRole, QVariant());
    table_->setItem(i, Time, cell(QString::fromStdString(r.time_text()), r.mean_ms, tip));
    table_->setItem(i, P95, cell(QString::fromStdString(r.p95_text()), r.p95_ms ? *r.p95_ms : nan, tip));
    table_->setItem(
        i, StageRate,
        cell(r.stage_fps ? fps_text(*r.stage_fps) : QStringLiteral("–"), r.stage_fps ? *r.stage_fps : nan, tip));
    table_->setItem(i, Throughput,
                    cell(r.throughput_fps ? fps_text(*r.throughput_fps) : QStringLiteral("–"),
                         r.throughput_fps ? *r.throughput_fps : nan, tip));
    auto* origin =
        cell(rebuilt ? tr("reconstructed") : QString::fromStdString(std::string(to_string(r.origin))), nan, tip);
    origin->setData(kSortRole, QVariant());
    if (rebuilt) origin->setForeground(QColor(0x9a, 0x5b, 0x00));  // never passes for a measurement
    table_->setItem(i, Data, origin);
    const QString lens = QString::fromStdString(r.lens_calibration);
    auto* lens_cell = cell(
        lens.isEmpty() ? QStringLiteral("–") : lens, nan,
        lens.isEmpty() ? tr("The run did not record its lens (imported or older runs)") : tr("Lens: %1").arg(lens));
    lens_cell->setData(kSortRole, QVariant());
    table_->setItem(i, LensColumn, lens_cell);
  }
  table_->setSortingEnabled(true);
  if (rows.empty())
    summary_->setText(
        tr("No pipeline runs yet: import pipeline JSON (sample_data/paper-2018/pipeline-*.json), "
           "measure one above, or run <code>benchscope-cli pipeline FRAME --lens LENS.json --workspace "
           "WS</code>."));
  else
    summary_->setText(
        tr("%n stage timing(s) from %1 run(s), %2 of them reconstructed from published figures (hover a row "
           "for its provenance). Times are per frame; stages run concurrently (measured runs: detection on the "
           "worker threads named under Device).",
           nullptr, static_cast<int>(rows.size()))
            .arg(runs_.size())
            .arg(reconstructed));
}

void PipelineView::export_table(bool latex) {
  const QString path = QFileDialog::getSaveFileName(this, latex ? tr("Export LaTeX table") : tr("Export CSV table"),
                                                    latex ? "pipeline.tex" : "pipeline.csv",
                                                    latex ? tr("LaTeX (*.tex)") : tr("CSV (*.csv)"));
  if (path.isEmpty()) return;
  const ExportTable t = pipeline_table(runs_);
  const std::string text = latex ? to_latex(t) : to_csv(t);
  QFile f(path);
  if (!f.open(QIODevice::WriteOnly) || f.write(text.data(), static_cast<qint64>(text.size())) < 0)
    QMessageBox::warning(this, tr("Export"), tr("Cannot write %1: %2").arg(path, f.errorString()));
}

}  // namespace bs::ui
