// SPDX-License-Identifier: GPL-3.0-or-later
#include "headroom/headroom_view.h"

#include <qcustomplot.h>
#include <QCheckBox>
#include <QComboBox>
#include <QFile>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QSpinBox>
#include <QSplitter>
#include <QTableWidget>
#include <QVBoxLayout>

#include "common/reading_label.h"
#include "common/record_chooser.h"
#include "common/table_shape.h"
#include "headroom/headroom_run_panel.h"
#include "headroom/headroom_table.h"
#include "headroom_figure.h"

namespace bs::ui {
namespace {

QString describe(const StoredHeadroom& s) {
  const headroom::HeadroomMeasurement& m = s.measurement;
  return QStringLiteral("%1 — %2, %3, %4 (import %5)%6")
      .arg(QString::fromStdString(m.platform), QString::fromStdString(m.tool),
           QString::fromStdString(std::string(headroom::to_string(m.kind))),
           QString::fromStdString(m.provenance.date.empty() ? "undated" : m.provenance.date))
      .arg(s.import_id)
      .arg(m.realtime() ? QString() : QObject::tr(" — non-real-time"));
}

QString source_of(const StoredHeadroom& s) {
  const headroom::HeadroomMeasurement& m = s.measurement;
  const std::string file = m.provenance.source_file.empty() ? m.command : m.provenance.source_file;
  return QStringLiteral("measurement #%1 (import %2): %3").arg(s.id).arg(s.import_id).arg(QString::fromStdString(file));
}

}  // namespace

HeadroomView::HeadroomView(QWidget* parent)
    : QWidget(parent),
      run_(new HeadroomRunPanel(this)),
      chooser_(new QComboBox(this)),
      deadline_(new QSpinBox(this)),
      show_deadline_(new QCheckBox(tr("Deadline"), this)),
      flags_(new QLabel(this)),
      source_(reading_label(this)),
      empty_(new QLabel(this)),
      plot_(new QCustomPlot(this)),
      table_(new QTableWidget(this)) {
  shape_record_chooser(chooser_, tr("The headroom measurement shown: platform, tool, what it measured, when"));
  deadline_->setRange(1, 10'000'000);
  deadline_->setSuffix(tr(" µs"));
  deadline_->setToolTip(tr("The vertical line: cycles whose wake-up latency lies beyond it are counted per curve"));
  show_deadline_->setChecked(true);
  flags_->setWordWrap(true);
  flags_->setTextFormat(Qt::RichText);
  empty_->setWordWrap(true);
  empty_->setText(
      tr("No headroom measurement yet. Run one above, on this machine or a robot (the probe idle and beside the "
         "vision pipeline), run `benchscope-cli headroom --workspace WS`, or import cyclictest, rttest or "
         "performance_test results."));
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  table_->setSelectionBehavior(QAbstractItemView::SelectRows);
  table_->verticalHeader()->hide();
  table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  plot_->setMinimumHeight(220);

  auto* export_tex = new QPushButton(tr("Export LaTeX…"), this);
  auto* export_csv = new QPushButton(tr("Export CSV…"), this);
  auto* controls = new QHBoxLayout;
  controls->addWidget(new QLabel(tr("Measurement:"), this));
  controls->addWidget(chooser_, 1);
  controls->addWidget(show_deadline_);
  controls->addWidget(deadline_);
  controls->addWidget(export_tex);
  controls->addWidget(export_csv);
  auto* split = new QSplitter(Qt::Vertical, this);
  split->addWidget(plot_);
  split->addWidget(table_);
  split->setStretchFactor(0, 3);
  split->setStretchFactor(1, 2);
  split->setChildrenCollapsible(false);
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(run_);
  layout->addLayout(controls);
  layout->addWidget(flags_);
  layout->addWidget(empty_);
  layout->addWidget(split, 1);
  layout->addWidget(source_);

  connect(chooser_, &QComboBox::currentIndexChanged, this, &HeadroomView::show_current);
  connect(deadline_, &QSpinBox::valueChanged, this, &HeadroomView::redraw_plot);
  connect(show_deadline_, &QCheckBox::toggled, this, &HeadroomView::redraw_plot);
  connect(show_deadline_, &QCheckBox::toggled, deadline_, &QSpinBox::setEnabled);
  connect(export_tex, &QPushButton::clicked, this, [this] { export_table(true); });
  connect(export_csv, &QPushButton::clicked, this, [this] { export_table(false); });
  show_current();
}

const headroom::HeadroomMeasurement* HeadroomView::current() const {
  const int i = chooser_->currentIndex();
  return i >= 0 && i < static_cast<int>(measurements_.size()) ? &measurements_[static_cast<std::size_t>(i)].measurement
                                                              : nullptr;
}

void HeadroomView::set_measurements(std::vector<StoredHeadroom> measurements) {
  measurements_ = std::move(measurements);
  refill_record_chooser(chooser_, measurements_, describe, newest_seen_);
  show_current();
}

bool HeadroomView::select(std::int64_t id) {
  const int at = chooser_->findData(QVariant::fromValue<qint64>(id));
  if (at < 0) return false;
  chooser_->setCurrentIndex(at);
  return true;
}

void HeadroomView::show_current() {
  const headroom::HeadroomMeasurement* m = current();
  empty_->setVisible(!m);
  plot_->setVisible(m != nullptr);
  table_->setVisible(m != nullptr);
  chooser_->setEnabled(!measurements_.empty());
  if (!m) {
    flags_->clear();
    source_->clear();
    table_->clear();
    return;
  }
  const StoredHeadroom& s = measurements_[static_cast<std::size_t>(chooser_->currentIndex())];
  // The deadline of the first thread (the period unless the run set one) starts the line.
  for (const headroom::Phase& p : m->phases)
    if (!p.threads.empty() && p.threads.front().deadline_ns > 0) {
      const QSignalBlocker block(deadline_);
      deadline_->setValue(static_cast<int>(p.threads.front().deadline_ns / 1000));
      break;
    }
  QStringList parts;
  for (const std::string& f : headroom::flags(*m)) {
    const QString text = QString::fromStdString(f).toHtmlEscaped();
    parts << (f.rfind("non-real-time", 0) == 0 ? QStringLiteral("<b style='color:#b00000'>%1</b>").arg(text) : text);
  }
  flags_->setText(parts.isEmpty() ? QString() : QStringLiteral("⚠ ") + parts.join(QStringLiteral(" · ")));
  flags_->setVisible(!parts.isEmpty());
  source_->setText(source_of(s));
  const ExportTable t = headroom::headroom_table(*m, source_of(s).toStdString());
  shape_table(table_, t);
  for (std::size_t r = 0; r < t.rows.size(); ++r)
    for (std::size_t c = 0; c < t.rows[r].size(); ++c) {
      auto* item = new QTableWidgetItem(QString::fromStdString(t.rows[r][c]));
      if (c >= 2 && c + 1 < t.rows[r].size()) item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
      table_->setItem(static_cast<int>(r), static_cast<int>(c), item);
    }
  QString notes;
  for (const std::string& n : t.notes) notes += QString::fromStdString(n) + "\n";
  table_->setToolTip(notes.trimmed());
  redraw_plot();
}

void HeadroomView::redraw_plot() {
  const headroom::HeadroomMeasurement* m = current();
  if (!m) return;
  const StoredHeadroom& s = measurements_[static_cast<std::size_t>(chooser_->currentIndex())];
  // The title names the measurement; its whole source (a robot's command line runs to 300 characters) is the
  // wrapped label under the plot: a plot title does not wrap, and one that long held the window 2,267 px wide.
  const QString title =
      QStringLiteral("%1: %2 (measurement #%3)")
          .arg(QString::fromStdString(m->platform), QString::fromStdString(std::string(headroom::to_string(m->kind))))
          .arg(s.id);
  headroom_histogram_figure(
      *plot_, headroom_curves(*m),
      show_deadline_->isChecked() ? std::optional<std::int64_t>(deadline_->value() * 1000LL) : std::nullopt, title);
  plot_->replot();
}

void HeadroomView::export_table(bool latex) {
  const headroom::HeadroomMeasurement* m = current();
  if (!m) return;
  const QString path =
      QFileDialog::getSaveFileName(this, latex ? tr("Export LaTeX table") : tr("Export CSV table"),
                                   latex ? QStringLiteral("headroom.tex") : QStringLiteral("headroom.csv"),
                                   latex ? tr("LaTeX (*.tex)") : tr("CSV (*.csv)"));
  if (path.isEmpty()) return;
  const ExportTable t = headroom::headroom_table(
      *m, source_of(measurements_[static_cast<std::size_t>(chooser_->currentIndex())]).toStdString());
  QFile f(path);
  if (!f.open(QIODevice::WriteOnly) || f.write(QByteArray::fromStdString(latex ? to_latex(t) : to_csv(t))) < 0)
    QMessageBox::warning(this, tr("Export failed"), tr("Cannot write %1: %2").arg(path, f.errorString()));
}

}  // namespace bs::ui
