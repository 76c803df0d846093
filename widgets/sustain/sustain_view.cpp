// SPDX-License-Identifier: GPL-3.0-or-later
#include "sustain/sustain_view.h"

#include <qcustomplot.h>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QSettings>
#include <QVBoxLayout>
#include <algorithm>

#include "common/reading_label.h"
#include "common/record_chooser.h"
#include "sustain/sustain_run_panel.h"
#include "sustain/sustain_text.h"
#include "sustain_figure.h"

namespace bs::ui {
namespace {

QString describe(const StoredSustainRun& s) {
  const SustainRun& r = s.run;
  const QString what = r.load.empty()
                           ? QObject::tr("clocks and temperatures of %1").arg(QString::fromStdString(r.label))
                           : QString::fromStdString(r.load);
  return QStringLiteral("%1 — %2, %3 (%4 intervals, import %5)")
      .arg(QString::fromStdString(r.platform), what,
           QString::fromStdString(r.provenance.date.empty() ? "undated" : r.provenance.date))
      .arg(r.t_s.size())
      .arg(s.import_id);
}

// Where the numbers come from, as every view says it: the record, its import, the file or command.
QString origin_of(const StoredSustainRun& s) {
  const SustainRun& r = s.run;
  const std::string from = !r.provenance.source_file.empty() ? r.provenance.source_file : r.provenance.tool;
  return QObject::tr("sustained record #%1 (import %2): %3%4")
      .arg(s.id)
      .arg(s.import_id)
      .arg(QString::fromStdString(from))
      .arg(r.provenance.host.empty() ? QString()
                                     : QObject::tr(", measured on %1").arg(QString::fromStdString(r.provenance.host)));
}

}  // namespace

SustainView::SustainView(QWidget* parent)
    : QWidget(parent),
      run_(new SustainRunPanel(this)),
      chooser_(new QComboBox(this)),
      stable_(new QDoubleSpinBox(this)),
      threshold_(new QDoubleSpinBox(this)),
      summary_(reading_label(this)),
      source_(reading_label(this)),
      empty_(new QLabel(this)),
      plot_(new QCustomPlot(this)) {
  const QSettings s;
  const sustain::AnalysisOptions defaults;
  shape_record_chooser(chooser_, tr("The sustained record shown: platform, load (or the log it came from), when"));
  stable_->setRange(50, 100);
  stable_->setDecimals(1);
  stable_->setPrefix(tr("stable ≥ "));
  stable_->setSuffix(tr(" %"));
  stable_->setValue(s.value("sustain/stable-percent", defaults.stable_percent).toDouble());
  stable_->setToolTip(
      tr("Stability = worst interval's rate / best interval's rate. 3DMark's stress tests call a run stable at "
         "97 % or more"));
  threshold_->setRange(10, 100);
  threshold_->setDecimals(0);
  threshold_->setPrefix(tr("throttled below "));
  threshold_->setSuffix(tr(" % of max clock"));
  threshold_->setValue(100 * s.value("sustain/throttle-threshold", defaults.throttle_threshold).toDouble());
  threshold_->setToolTip(
      tr("A clock below this share of its maximum counts as throttled (NVIDIA nvbench's --throttle-threshold, 80 % "
         "by default); a thermal zone at or above its trip point does too"));
  summary_->setTextFormat(Qt::RichText);
  empty_->setWordWrap(true);
  empty_->setText(
      tr("No sustained record yet. Run one above, on this computer or a robot (a load for minutes, with every clock "
         "and temperature), run `benchscope-cli sustain --workspace WS`, or import a tegrastats, jtop or nvidia-smi "
         "log: their clocks and temperatures show here."));
  plot_->setMinimumHeight(300);

  auto* controls = new QHBoxLayout;
  controls->addWidget(new QLabel(tr("Record:"), this));
  controls->addWidget(chooser_, 1);
  controls->addWidget(stable_);
  controls->addWidget(threshold_);
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(run_);
  layout->addLayout(controls);
  layout->addWidget(summary_);
  layout->addWidget(empty_);
  layout->addWidget(plot_, 1);
  layout->addWidget(source_);

  connect(chooser_, &QComboBox::currentIndexChanged, this, &SustainView::show_current);
  for (QDoubleSpinBox* b : {stable_, threshold_})
    connect(b, &QDoubleSpinBox::valueChanged, this, [this] {
      QSettings settings;
      settings.setValue("sustain/stable-percent", stable_->value());
      settings.setValue("sustain/throttle-threshold", threshold_->value() / 100);
      live_ ? draw(*live_, tr("the run going on")) : show_current();
    });
  connect(run_, &SustainRunPanel::live_interval, this, &SustainView::show_live);
  // When a run here ends (stored, failed or cancelled) the stored records show again, a new one in front.
  connect(run_, &SustainRunPanel::stopped, this, [this] {
    live_.reset();
    show_current();
  });
  show_current();
}

sustain::AnalysisOptions SustainView::options() const {
  sustain::AnalysisOptions o;
  o.stable_percent = stable_->value();
  o.throttle_threshold = threshold_->value() / 100;
  return o;
}

const SustainRun* SustainView::current() const {
  if (live_) return &*live_;
  const int i = chooser_->currentIndex();
  return i >= 0 && i < static_cast<int>(records_.size()) ? &records_[static_cast<std::size_t>(i)].run : nullptr;
}

sustain::SustainAnalysis SustainView::current_analysis() const {
  const SustainRun* r = current();
  return r ? sustain::analyse(*r, options()) : sustain::SustainAnalysis{};
}

void SustainView::set_records(std::vector<StoredSustainRun> records) {
  records_ = std::move(records);
  refill_record_chooser(chooser_, records_, describe, newest_seen_);
  if (!live_) show_current();
}

bool SustainView::select(std::int64_t id) {
  const int at = chooser_->findData(QVariant::fromValue<qint64>(id));
  if (at < 0) return false;
  live_.reset();
  chooser_->setCurrentIndex(at);
  show_current();
  return true;
}

void SustainView::show_live(const SustainRun& so_far) {
  live_ = so_far;
  draw(*live_, tr("the run going on (%1 intervals so far)").arg(so_far.t_s.size()));
  // The time axis spans the whole run asked for: the curves grow across it as the intervals come.
  if (!so_far.t_s.empty() && plot_->axisRectCount() > 0) {
    plot_->axisRect(0)->axis(QCPAxis::atBottom)->setRange(0, std::max(so_far.t_s.back(), run_->seconds()->value()));
    plot_->replot();
  }
}

void SustainView::show_current() {
  const int i = chooser_->currentIndex();
  if (i < 0 || i >= static_cast<int>(records_.size())) {
    empty_->show();
    summary_->clear();
    source_->clear();
    plot_->hide();
    return;
  }
  const StoredSustainRun& s = records_[static_cast<std::size_t>(i)];
  draw(s.run, origin_of(s));
}

void SustainView::draw(const SustainRun& run, const QString& origin) {
  empty_->hide();
  plot_->show();
  const sustain::SustainAnalysis a = sustain::analyse(run, options());
  QString html = QStringLiteral("<table cellspacing=0 cellpadding=1>");
  for (const sustain::SummaryRow& row : sustain::summary_rows(run, a)) {
    const QString value = QString::fromStdString(row.value).toHtmlEscaped();
    html += QStringLiteral("<tr><td><b>%1</b>&nbsp;&nbsp;</td><td>%2</td></tr>")
                .arg(QString::fromStdString(row.label).toHtmlEscaped(),
                     row.alarm ? QStringLiteral("<span style='color:#c81e1e'>%1</span>").arg(value) : value);
  }
  summary_->setText(html + QStringLiteral("</table>"));
  source_->setText(tr("From %1").arg(origin));
  const QString title =
      QStringLiteral("%1 — %2").arg(QString::fromStdString(run.platform),
                                    QString::fromStdString(run.load.empty() ? run.label : run.load + ", " + run.label));
  sustain_figure(*plot_, run, a, title);
}

}  // namespace bs::ui
