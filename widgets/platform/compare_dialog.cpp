// SPDX-License-Identifier: GPL-3.0-or-later
#include "platform/compare_dialog.h"

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QTableWidget>
#include <QVBoxLayout>
#include <cmath>

#include "analysis/stats/units.h"

namespace bs::ui {
namespace {

QString summary_text(const Summary& s, const std::string& unit) {
  if (s.n == 0) return QStringLiteral("–");
  if (unit.empty()) return QString::fromStdString(format_mean_sd(s.mean, s.sd, s.n, "", 3));
  const int e = si_exponent(s.mean);
  const double scale = std::pow(10.0, e);
  return QString::fromStdString(format_mean_sd(s.mean / scale, s.sd / scale, s.n, std::string(si_prefix(e)) + unit, 3));
}

QColor verdict_color(CompareVerdict v) {
  switch (v) {
    case CompareVerdict::Regression:
      return QColor(0xf8, 0xd0, 0xd0);
    case CompareVerdict::Improvement:
      return QColor(0xd9, 0xf2, 0xd9);
    case CompareVerdict::NotSignificant:
      return QColor(0xfb, 0xef, 0xc8);
    default:
      return {};
  }
}

}  // namespace

CompareDialog::CompareDialog(std::vector<FlopsRun> runs_a, std::vector<ResultSet> sets_a, std::vector<FlopsRun> runs_b,
                             std::vector<ResultSet> sets_b, const QString& name_a, const QString& name_b,
                             QWidget* parent)
    : QDialog(parent),
      runs_a_(std::move(runs_a)),
      runs_b_(std::move(runs_b)),
      sets_a_(std::move(sets_a)),
      sets_b_(std::move(sets_b)) {
  setWindowTitle(tr("Compare: %1 (A) → %2 (B)").arg(name_a, name_b));
  threshold_ = new QDoubleSpinBox(this);
  threshold_->setRange(0, 1000);
  threshold_->setValue(5);
  threshold_->setSuffix(tr(" %"));
  threshold_->setToolTip(tr("A change smaller than this is reported as unchanged"));
  alpha_ = new QDoubleSpinBox(this);
  alpha_->setRange(0.0001, 0.5);
  alpha_->setDecimals(4);
  alpha_->setSingleStep(0.01);
  alpha_->setValue(0.05);
  alpha_->setToolTip(tr("Significance level of the Mann-Whitney U test over the repetitions"));
  every_point_ = new QCheckBox(tr("Every worker count"), this);
  every_point_->setToolTip(tr("Compare FLOPS runs at every common worker count, not only at A's peak"));
  show_unchanged_ = new QCheckBox(tr("Show unchanged"), this);
  auto* controls = new QHBoxLayout;
  controls->addWidget(new QLabel(tr("Threshold:"), this));
  controls->addWidget(threshold_);
  controls->addWidget(new QLabel(tr("Alpha:"), this));
  controls->addWidget(alpha_);
  controls->addWidget(every_point_);
  controls->addWidget(show_unchanged_);
  controls->addStretch(1);
  summary_ = new QLabel(this);
  summary_->setWordWrap(true);
  table_ = new QTableWidget(this);
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  table_->verticalHeader()->setVisible(false);
  table_->horizontalHeader()->setStretchLastSection(true);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(controls);
  layout->addWidget(summary_);
  layout->addWidget(table_, 1);
  layout->addWidget(buttons);
  connect(threshold_, &QDoubleSpinBox::valueChanged, this, &CompareDialog::recompute);
  connect(alpha_, &QDoubleSpinBox::valueChanged, this, &CompareDialog::recompute);
  connect(every_point_, &QCheckBox::toggled, this, &CompareDialog::recompute);
  connect(show_unchanged_, &QCheckBox::toggled, this, &CompareDialog::recompute);
  resize(1200, 600);
  recompute();
}

void CompareDialog::set_threshold_percent(double percent) { threshold_->setValue(percent); }

void CompareDialog::recompute() {
  CompareOptions o;
  o.threshold = threshold_->value() / 100.0;
  o.alpha = alpha_->value();
  o.every_point = every_point_->isChecked();
  const auto rows = compare_results({runs_a_, sets_a_}, {runs_b_, sets_b_}, o);
  regressions_ = 0;
  int improvements = 0, weak = 0, shown = 0;
  table_->clear();
  table_->setColumnCount(7);
  table_->setHorizontalHeaderLabels({tr("Measure"), tr("What"), tr("A: mean ± SD (n)"), tr("B: mean ± SD (n)"),
                                     tr("Change"), tr("p (Mann-Whitney U)"), tr("Verdict")});
  table_->setRowCount(0);
  for (const MeasureComparison& r : rows) {
    regressions_ += r.verdict == CompareVerdict::Regression;
    improvements += r.verdict == CompareVerdict::Improvement;
    weak += r.verdict == CompareVerdict::NotSignificant;
    if (r.verdict == CompareVerdict::Unchanged && !show_unchanged_->isChecked()) continue;
    const int row = shown++;
    table_->insertRow(row);
    const bool both = r.a.n > 0 && r.b.n > 0;
    const QStringList cells{QString::fromStdString(r.measure),
                            QString::fromStdString(r.key),
                            summary_text(r.a, r.unit),
                            summary_text(r.b, r.unit),
                            both ? QString::asprintf("%+.1f %%", 100 * r.change) : QStringLiteral("–"),
                            both ? QString::number(r.test.p_value, 'g', 3) + (r.test.exact ? tr(" (exact)") : QString())
                                 : QStringLiteral("–"),
                            QString::fromUtf8(to_string(r.verdict).data())};
    for (int c = 0; c < cells.size(); ++c) {
      auto* item = new QTableWidgetItem(cells[c]);
      if (const QColor bg = verdict_color(r.verdict); bg.isValid()) item->setBackground(bg);
      if (c >= 2 && c <= 5) item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
      table_->setItem(row, c, item);
    }
  }
  table_->resizeColumnsToContents();
  summary_->setText(tr("%1 measures compared: <b>%2 regressions</b>, %3 improvements, %4 changes beyond the threshold "
                       "without enough evidence (more repetitions needed: with 3 per side p cannot go below 0.1).")
                        .arg(rows.size())
                        .arg(regressions_)
                        .arg(improvements)
                        .arg(weak));
}

}  // namespace bs::ui
