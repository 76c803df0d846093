// SPDX-License-Identifier: GPL-3.0-or-later
#include "peaks/peak_table.h"

#include <QApplication>
#include <QClipboard>
#include <QColor>
#include <QHeaderView>
#include <QKeyEvent>
#include <QSortFilterProxyModel>
#include <QStyledItemDelegate>
#include <algorithm>
#include <cmath>

#include "analysis/peaks/plausibility.h"
#include "analysis/stats/units.h"
#include "device_palette.h"

namespace bs::ui {

QString peak_mean_sd_text(const PeakRow& r) {
  if (r.peak.at_peak.n <= 1) return QString::fromStdString(format_si(r.peak.flops, "FLOPS"));
  const int e = si_exponent(r.peak.flops);
  const double scale = std::pow(10.0, e);
  return QStringLiteral("%1 ± %2 %3FLOPS")
      .arg(r.peak.flops / scale, 0, 'f', 2)
      .arg(r.peak.at_peak.sd / scale, 0, 'f', 2)
      .arg(QString::fromUtf8(si_prefix(e).data(), static_cast<qsizetype>(si_prefix(e).size())));
}

void PeakTableModel::set_rows(std::vector<PeakRow> rows, std::vector<int> color_indices,
                              std::vector<std::string> run_names) {
  color_indices.resize(rows.size(), 0);
  // Rows grouped by platform, platforms in the order they first appear, each platform's rows in their given order.
  std::vector<std::string> platforms;
  for (const PeakRow& r : rows)
    if (std::find(platforms.begin(), platforms.end(), r.platform) == platforms.end()) platforms.push_back(r.platform);
  std::vector<std::size_t> order(rows.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  const auto rank = [&](std::size_t i) {
    return std::find(platforms.begin(), platforms.end(), rows[i].platform) - platforms.begin();
  };
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return rank(a) < rank(b); });
  beginResetModel();
  rows_.clear();
  colors_.clear();
  runs_.clear();
  for (std::size_t i : order) {
    const std::size_t run = rows[i].run_index;
    runs_.push_back(run < run_names.size() ? QString::fromStdString(run_names[run]) : QString());
    rows_.push_back(std::move(rows[i]));
    colors_.push_back(color_indices[i]);
  }
  endResetModel();
}

int PeakTableModel::rowCount(const QModelIndex& parent) const {
  return parent.isValid() ? 0 : static_cast<int>(rows_.size());
}

int PeakTableModel::columnCount(const QModelIndex& parent) const { return parent.isValid() ? 0 : ColumnCount; }

QVariant PeakTableModel::data(const QModelIndex& index, int role) const {
  if (!index.isValid()) return {};
  const PeakRow& r = rows_[static_cast<std::size_t>(index.row())];
  const auto qs = [](const std::string& s) { return QString::fromStdString(s); };
  if (role == Qt::DisplayRole) {
    switch (index.column()) {
      case Platform:
        return qs(r.platform);
      case Device:
        return qs(r.device);
      case Backend:
        return r.variant == "paper" ? qs(r.backend) : qs(r.backend + " (" + r.variant + ")");
      case Dims:
        return r.dims > 0 ? QVariant(r.dims) : QVariant(QStringLiteral("–"));  // "–": another tool's sweep
      case Run:
        return runs_[static_cast<std::size_t>(index.row())];
      case Peak: {
        const QString s = peak_mean_sd_text(r);
        return r.flags.empty() ? s : QStringLiteral("⚠ ") + s;
      }
      case Workers:
        return QLocale().toString(static_cast<qlonglong>(r.peak.workers));
      case Reported:
        return r.reported_flops ? qs(format_si(*r.reported_flops, "FLOPS")) : QStringLiteral("–");
      case Ratio:
        return r.ratio_to_reported ? QStringLiteral("%1×").arg(*r.ratio_to_reported, 0, 'f', 2) : QStringLiteral("–");
      case OfTheoretical:
        return r.fraction_of_theoretical ? QStringLiteral("%1 %").arg(*r.fraction_of_theoretical * 100, 0, 'f', 1)
                                         : QStringLiteral("–");
      case OfCeiling:
        return r.fraction_of_ceiling ? QStringLiteral("%1 %").arg(*r.fraction_of_ceiling * 100, 0, 'f', 1)
                                     : QStringLiteral("–");
      case OfSpec:
        return r.fraction_of_spec ? QStringLiteral("%1 %").arg(*r.fraction_of_spec * 100, 0, 'f', 1)
                                  : QStringLiteral("–");
      case Origin:
        return QString::fromUtf8(to_string(r.origin).data());
    }
  }
  if (role == kFlaggedRole) return !r.flags.empty();
  if (role == Qt::BackgroundRole && !r.flags.empty()) return QColor(0xff, 0xe0, 0xb2);  // amber: see the tooltip
  if (role == Qt::ForegroundRole && !r.flags.empty() && index.column() == Peak) return QColor(0x8a, 0x4b, 0x00);
  if (role == kSortRole) {
    switch (index.column()) {
      case Platform:
        return qs(r.platform);
      case Dims:
        return r.dims;
      case Peak:
        return r.peak.flops;
      case Workers:
        return static_cast<qlonglong>(r.peak.workers);
      case Reported:
        return r.reported_flops.value_or(-1);
      case Ratio:
        return r.ratio_to_reported.value_or(-1);
      case OfTheoretical:
        return r.fraction_of_theoretical.value_or(-1);
      case OfCeiling:
        return r.fraction_of_ceiling.value_or(-1);
      case OfSpec:
        return r.fraction_of_spec.value_or(-1);
      default:
        return data(index, Qt::DisplayRole);
    }
  }
  if (role == Qt::DecorationRole && index.column() == Device)
    return device_color(colors_[static_cast<std::size_t>(index.row())]);
  if (role == Qt::TextAlignmentRole && index.column() >= Dims && index.column() <= OfSpec && index.column() != Run)
    return QVariant::fromValue(Qt::AlignRight | Qt::AlignVCenter);
  if (role == Qt::ToolTipRole) {
    QString tip = QStringLiteral("%1 on %2\nPeak %3 at %L4 workers (n = %5)\nSource: %6")
                      .arg(qs(r.device), qs(r.platform), qs(format_si(r.peak.flops, "FLOPS", 4)))
                      .arg(static_cast<qlonglong>(r.peak.workers))
                      .arg(r.peak.at_peak.n)
                      .arg(qs(r.source_file));
    if (r.spec)
      tip += tr("\nVendor FP32 peak: %1 (%2: %3; %4)")
                 .arg(qs(format_si(r.spec->fp32_peak_flops, "FLOPS")), qs(r.spec->name), qs(r.spec->derivation),
                      qs(r.spec->source_title));
    else
      tip += tr("\nNot in the device table: no vendor peak to check against");
    if (r.empirical_ceiling_flops)
      tip +=
          tr("\nEmpirical ceiling: %1 (%2)").arg(qs(format_si(*r.empirical_ceiling_flops, "FLOPS")), qs(r.ceiling_how));
    else
      tip += tr("\nNo empirical ceiling measured for this device (Kernel Runner: Measure ceilings)");
    // The ratio columns say what they divide, with both numbers, above the row's provenance.
    QString division;
    if (index.column() == Ratio && r.ratio_to_reported && r.reported_flops)
      division = tr("Measured peak %1 ÷ reported %2 = %3×")
                     .arg(qs(format_si(r.peak.flops, "FLOPS")), qs(format_si(*r.reported_flops, "FLOPS")))
                     .arg(*r.ratio_to_reported, 0, 'f', 3);
    if (index.column() == OfTheoretical && r.fraction_of_theoretical)
      division = tr("Measured peak %1 ÷ this kernel's theoretical peak on the device %2 = %3 %")
                     .arg(qs(format_si(r.peak.flops, "FLOPS")),
                          qs(format_si(r.peak.flops / *r.fraction_of_theoretical, "FLOPS")))
                     .arg(*r.fraction_of_theoretical * 100, 0, 'f', 1);
    if (index.column() == OfSpec && r.fraction_of_spec && r.spec)
      division = tr("Measured peak %1 ÷ the vendor's FP32 peak %2 (%3) = %4 %")
                     .arg(qs(format_si(r.peak.flops, "FLOPS")), qs(format_si(r.spec->fp32_peak_flops, "FLOPS")),
                          qs(r.spec->name))
                     .arg(*r.fraction_of_spec * 100, 0, 'f', 1);
    if (!division.isEmpty()) tip = division + QStringLiteral("\n\n") + tip;
    if (!r.flags.empty()) tip = qs(flags_text(r.flags)) + QStringLiteral("\n\n") + tip;
    return tip;
  }
  return {};
}

QVariant PeakTableModel::headerData(int section, Qt::Orientation orientation, int role) const {
  if (orientation != Qt::Horizontal) return {};
  static const char* names[] = {"Platform",         "Device",          "Backend",  "D",     "Run",
                                "Peak (mean ± SD)", "Workers at peak", "Reported", "Ratio", "% of theoretical",
                                "% of ceiling",     "% of spec",       "Origin"};
  static const char* tips[] = {
      "The computer; its rows are grouped under it",
      "Compute device (colour as in every plot)",
      "API the kernel ran through",
      "2D points rotated per worker",
      "What tells this run from others of the same device, backend and D: its name (F2 in the workspace tree), "
      "else its date or host",
      "Highest mean FLOPS = 6·D·N·W / t, ± the SD of the repeats at that worker count (n in the tooltip)",
      "Worker count where the peak occurred",
      "Vendor or literature peak figure",
      "Measured peak ÷ the vendor or literature figure in Reported (hover a cell for both numbers)",
      "Measured peak ÷ this kernel's theoretical peak on the device (its instruction mix at "
      "the device's clock and SIMD width; hover a cell for both numbers); above 100 % is flagged ⚠",
      "Measured peak ÷ the device's empirical ceiling: the rotation kernel's instruction mix "
      "measured by BenchScope's micro-kernel (docs/ceilings.md)",
      "Measured peak ÷ the vendor's FP32 peak (device table); above 130 % is flagged ⚠",
      "measured on a machine, or reconstructed from published figures"};
  if (role == Qt::DisplayRole) return tr(names[section]);
  if (role == Qt::ToolTipRole) return tr(tips[section]);
  return {};
}

namespace {
// Elides at the end, whatever the view's mode: the peak's mean and its "±" stay in view.
class RightElidingDelegate : public QStyledItemDelegate {
 public:
  using QStyledItemDelegate::QStyledItemDelegate;

 protected:
  void initStyleOption(QStyleOptionViewItem* option, const QModelIndex& index) const override {
    QStyledItemDelegate::initStyleOption(option, index);
    option->textElideMode = Qt::ElideRight;
  }
};
}  // namespace

PeakTableView::PeakTableView(QWidget* parent) : QTableView(parent), model_(new PeakTableModel(this)) {
  auto* proxy = new QSortFilterProxyModel(this);
  proxy->setSourceModel(model_);
  proxy->setSortRole(PeakTableModel::kSortRole);
  setModel(proxy);
  setSortingEnabled(true);
  sortByColumn(-1, Qt::AscendingOrder);
  setSelectionBehavior(QAbstractItemView::SelectRows);
  setAlternatingRowColors(true);
  verticalHeader()->hide();
  // Compact rows: the paper's 13 runs fit the dock without scrolling.
  verticalHeader()->setSectionResizeMode(QHeaderView::Fixed);
  verticalHeader()->setDefaultSectionSize(fontMetrics().height() + 6);
  horizontalHeader()->setStretchLastSection(true);
  horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  // Long platform and device names ("Jetson CPU (ARM A57 + Denver2)") may not push the numbers ("% of spec") off
  // a 1600 px window (issue #32.7): a column is at most 190 px, its text elided in the middle, whole in the tooltip.
  horizontalHeader()->setMaximumSectionSize(190);
  setTextElideMode(Qt::ElideMiddle);
  // Numbers are never elided in the middle: "43.16 ± 13.81 GFLOPS" cut to "43.16…GFLOPS" would hide the SD's sign.
  setItemDelegateForColumn(PeakTableModel::Peak, new RightElidingDelegate(this));
  setWordWrap(false);
}

bool PeakTableView::show_row(const std::string& platform, const std::string& device, const std::string& backend,
                             int dims) {
  const auto& rows = model_->rows();
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const PeakRow& r = rows[i];
    if (r.platform != platform || r.device != device || r.backend != backend || r.dims != dims) continue;
    const auto* proxy = static_cast<QSortFilterProxyModel*>(model());
    const QModelIndex at = proxy->mapFromSource(model_->index(static_cast<int>(i), PeakTableModel::Peak));
    selectRow(at.row());
    scrollTo(at, QAbstractItemView::PositionAtCenter);
    return true;
  }
  return false;
}

QString PeakTableView::selection_as_tsv() const {
  QStringList lines;
  QStringList header;
  for (int c = 0; c < model()->columnCount(); ++c) header << model()->headerData(c, Qt::Horizontal).toString();
  lines << header.join('\t');
  const auto rows = selectionModel()->selectedRows();
  for (const QModelIndex& idx : rows) {
    QStringList cells;
    for (int c = 0; c < model()->columnCount(); ++c) cells << model()->index(idx.row(), c).data().toString();
    lines << cells.join('\t');
  }
  return lines.join('\n');
}

void PeakTableView::keyPressEvent(QKeyEvent* event) {
  if (event->matches(QKeySequence::Copy)) {
    QApplication::clipboard()->setText(selection_as_tsv());
    return;
  }
  QTableView::keyPressEvent(event);
}

}  // namespace bs::ui
