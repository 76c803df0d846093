// SPDX-License-Identifier: GPL-3.0-or-later
#include "power/power_view.h"

#include "store/log_settings_store.h"

#include <qcustomplot.h>
#include <QCheckBox>
#include <QComboBox>
#include <QDateTime>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QMessageBox>
#include <QSplitter>
#include <QTabWidget>
#include <QTableWidget>
#include <QTimeZone>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>

#include "analysis/power/decimate.h"
#include "analysis/power/power.h"
#include "analysis/power/range_table.h"
#include "analysis/stats/measurement_text.h"
#include "device_palette.h"
#include "power/phase_markers.h"
#include "power/power_cursors.h"
#include "power/power_overlay.h"
#include "power/power_stats_panel.h"
#include "power/power_trace_drag.h"
#include "power/save_phase_dialog.h"
#include "store/battery_preset_store.h"

namespace bs::ui {
namespace {

// Ranges of up to this many samples get exact percentiles on every mouse move (a few ms); longer ones when the
// drag ends (analysis/trace_index.h: nth_element over the range).
constexpr std::size_t kLivePercentileSamples = 200'000;
constexpr const char* kBatteryTabSetupKey = "battery-tab/current";  // what the Battery tab shows (battery_view.cpp)

// Seconds since 1970 (UTC) of a log's first sample from its ISO 8601 start_time; NaN when it has none.
double start_epoch_s(const PowerTrace& t) {
  if (t.start_time.empty()) return std::nan("");
  QDateTime when = QDateTime::fromString(QString::fromStdString(t.start_time), Qt::ISODateWithMs);
  if (!when.isValid()) when = QDateTime::fromString(QString::fromStdString(t.start_time), Qt::ISODate);
  if (!when.isValid()) return std::nan("");
  if (when.timeSpec() == Qt::LocalTime)
    when.setTimeSpec(Qt::UTC);  // no zone stated: read as UTC, as the importers write it
  return static_cast<double>(when.toMSecsSinceEpoch()) / 1000.0;
}

// A log as the tables name it: its platform and its own name ("NUC — nuc-current.csv"), since a platform may have
// several logs (issue #43.4: "NUC, NUC, Jetson TX2, Jetson TX2" told nothing apart).
QString log_name(const PowerTrace& t) {
  if (t.platform.empty()) return QString::fromStdString(t.label);
  return QStringLiteral("%1 — %2").arg(QString::fromStdString(t.platform), QString::fromStdString(t.label));
}

}  // namespace

PowerView::PowerView(QWidget* parent)
    : QWidget(parent),
      quantity_box_(new QComboBox(this)),
      wall_clock_box_(new QCheckBox(tr("Wall-clock time (UTC)"), this)),
      detect_box_(new QCheckBox(tr("Detected phases"), this)),
      plot_(new QCustomPlot(this)),
      panels_(new QTabWidget(this)),
      table_(new QTableWidget(this)),
      selection_(new PowerStatsPanel(tr("No selection: Shift + drag on the plot, or press A and B with the mouse "
                                        "over it, to place the cursors"),
                                     true, this)),
      phases_(new PowerStatsPanel(tr("No phases: the logs have no marks; tick \"Detected phases\" for level "
                                     "changes, or save a selection as a phase"),
                                  false, this)),
      overlay_(new PowerOverlayPanel(this)),
      cursors_(new PowerCursors(plot_)),
      trace_drag_(new PowerTraceDrag(plot_)) {
  wall_clock_box_->setToolTip(
      tr("Plot against the time of day the logs were recorded (when every log states its "
         "absolute start) instead of seconds from each log's start"));
  connect(wall_clock_box_, &QCheckBox::toggled, this, [this](bool on) { set_wall_clock(on); });
  detect_box_->setToolTip(
      tr("Also shade and list load phases found from level changes of each trace (idle / load), "
         "as benchscope-cli power --phases does"));
  connect(detect_box_, &QCheckBox::toggled, this, [this](bool on) { set_detected_phases(on); });
  quantity_box_->addItem(tr("Current (A)"));
  quantity_box_->addItem(tr("Power (W)"));
  quantity_box_->setToolTip(
      tr("Supply current as in the paper's figure 4, or power; the tables' level columns "
         "follow it"));
  connect(quantity_box_, &QComboBox::currentIndexChanged, this,
          [this](int i) { set_quantity(i == 0 ? Quantity::Current : Quantity::Power); });
  auto* hint = new QLabel(tr("Shift + drag: select · drag A/B: move a cursor · keys A/B: cursor at the mouse · "
                             "Esc: clear · Ctrl + drag a trace: shift it · wheel/drag: zoom/pan · double-click: "
                             "whole log"),
                          this);
  hint->setWordWrap(true);
  hint->setToolTip(
      tr("The View range tab summarises the range in view; the Selection tab the range between the "
         "cursors A and B"));
  plot_->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
  plot_->setToolTip(
      tr("Shift + drag to select a range; A / B place the cursors at the mouse; Esc clears; "
         "Ctrl + drag a trace to shift it in time (Overlay tab: typed offsets, alignment)"));
  plot_->axisRect()->setRangeZoom(Qt::Horizontal);
  plot_->axisRect()->setRangeDrag(Qt::Horizontal);
  plot_->xAxis->setLabel(tr("Time (s)"));
  plot_->yAxis->setLabel(tr("Current (A)"));
  plot_->legend->setVisible(true);
  plot_->axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignTop | Qt::AlignRight);
  connect(plot_->xAxis, qOverload<const QCPRange&>(&QCPAxis::rangeChanged), this, [this] {
    redraw_visible();
    update_table();
  });
  connect(plot_, &QCustomPlot::mouseDoubleClick, this, [this] { rescale(); });
  connect(cursors_, &PowerCursors::changed, this, [this](bool final) { update_selection(final); });
  connect(selection_, &PowerStatsPanel::save_phase_requested, this, [this] { ask_save_phase(); });
  connect(overlay_, &PowerOverlayPanel::changed, this, [this] { overlay_changed(); });
  connect(trace_drag_, &PowerTraceDrag::dragged, this, [this](std::size_t trace, double by_s, bool final) {
    if (!drag_base_s_) drag_base_s_ = overlay_->offset(trace);  // the offset at the press
    overlay_->set_offset(trace, *drag_base_s_ + by_s);
    if (final) drag_base_s_.reset();
  });
  table_->setColumnCount(8);
  table_->setHorizontalHeaderLabels({tr("Platform"), tr("Samples"), tr("Current (A)"), tr("Power (W)"),
                                     tr("Max power (W)"), tr("Energy (J)"), tr("GFLOPS/W (paper)"),
                                     tr("Battery (min)")});
  table_->horizontalHeaderItem(6)->setToolTip(tr("Peak FLOPS of the platform's best run / (supply V × max current)"));
  table_->verticalHeader()->hide();
  table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  panels_->addTab(selection_, tr("Selection A–B"));
  panels_->setTabToolTip(0, tr("Statistics of the range between the cursors, per visible trace"));
  panels_->addTab(phases_, tr("Phases"));
  panels_->setTabToolTip(1, tr("Statistics per phase and trace; the same phase of different traces side by side"));
  panels_->addTab(table_, tr("View range"));
  panels_->setTabToolTip(2, tr("Statistics of the time range in view, GFLOPS/W and battery life"));
  panels_->addTab(overlay_, tr("Overlay"));
  panels_->setTabToolTip(3, tr("Show or hide traces and shift them on the shared time axis"));
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(4, 4, 4, 4);
  auto* top = new QHBoxLayout;
  top->addWidget(new QLabel(tr("Plot:"), this));
  top->addWidget(quantity_box_);
  top->addWidget(wall_clock_box_);
  top->addWidget(detect_box_);
  top->addWidget(hint, 1);
  layout->addLayout(top);
  auto* split = split_ = new QSplitter(Qt::Vertical, this);
  split->addWidget(plot_);
  split->addWidget(panels_);
  split->setStretchFactor(0, 3);
  split->setStretchFactor(1, 2);
  split->setChildrenCollapsible(false);
  layout->addWidget(split, 1);
  read_battery();
}

void PowerView::set_workspace(Workspace* workspace) {
  workspace_ = workspace;
  read_battery();
  update_table();
}

void PowerView::resizeEvent(QResizeEvent* event) {
  QWidget::resizeEvent(event);
  // The first real size: about 60 % plot, 40 % tables (the user's splitter position is kept afterwards).
  if (!split_placed_ && height() > 300) {
    split_->setSizes({height() * 3 / 5, height() * 2 / 5});
    split_placed_ = true;
  }
}

void PowerView::showEvent(QShowEvent* event) {
  QWidget::showEvent(event);
  read_battery();  // the Battery tab may have changed the pack meanwhile
  update_table();
}

void PowerView::read_battery() {
  // The Battery tab's current setup, as it saved it in the workspace; without one, the first built-in preset (the
  // paper's 4S LiPo): the pack is data, never a constant of this widget.
  BatterySetup setup = builtin_battery_setups().front();
  if (workspace_) {
    try {
      for (const auto& [key, json] : workspace_->settings(kBatteryTabSetupKey))
        if (key == kBatteryTabSetupKey) setup = battery_setup_from_json(json);
    } catch (const std::exception&) {
      // An unreadable saved setup: the Battery tab reports it; here the built-in pack stands.
    }
  }
  battery_volts_ = setup.pack.nominal_v();
  battery_ah_ = setup.pack.capacity_ah * setup.depth_of_discharge;
  battery_name_ = QString::fromStdString(setup.pack.name);
  table_->horizontalHeaderItem(7)->setToolTip(
      tr("%1 V × %2 Ah usable (%3, the Battery tab's pack) / mean power: the paper's constant-power model")
          .arg(battery_volts_, 0, 'f', 1)
          .arg(battery_ah_, 0, 'f', 2)
          .arg(battery_name_));
}

QString PowerView::legend_name(std::size_t i) const {
  // The platform alone while it has one log here; with several, each log's own name too.
  const PowerTrace& t = trace(i);
  std::size_t same = 0;
  for (std::size_t k = 0; k < count(); ++k) same += trace(k).platform == t.platform ? 1 : 0;
  return same > 1 || t.platform.empty() ? log_name(t) : QString::fromStdString(t.platform);
}

double PowerView::offset(std::size_t trace) const {
  return (wall_clock_on_ ? start_epoch_[trace] : 0.0) + overlay_->offset(trace);
}

void PowerView::set_data(std::vector<StoredPowerTrace> traces, std::vector<PeakRow> peaks,
                         std::vector<std::pair<std::string, int>> colors) {
  set_data(share_traces(std::move(traces)), std::move(peaks), std::move(colors));
}

void PowerView::set_data(SharedTraces traces, std::vector<PeakRow> peaks,
                         std::vector<std::pair<std::string, int>> colors) {
  traces_ = traces ? std::move(traces) : share_traces(std::vector<PowerTrace>{});
  peaks_ = std::move(peaks);
  flags_.clear();
  trace_phases_.clear();
  phase_origins_.clear();
  index_.clear();
  detected_.clear();
  start_epoch_.clear();
  colors_.clear();
  plot_->clearGraphs();
  for (std::size_t i = 0; i < count(); ++i) {
    const PowerTrace& t = trace(i);
    flags_.push_back(check_power_trace_bundled(t));
    trace_phases_.push_back(t.phases);
    // Which phases the user saved ("user") and which came with the log ("log"), as the workspace records them.
    std::vector<std::string> origins;
    if (workspace_ && i < traces_->ids.size() && traces_->ids[i] > 0) {
      try {
        origins = phase_origins(*workspace_, traces_->ids[i]);
      } catch (const std::exception&) {
        origins.clear();  // a workspace without the column (cannot happen after migration): every phase the log's
      }
    }
    if (origins.size() != t.phases.size()) origins.assign(t.phases.size(), "log");
    phase_origins_.push_back(std::move(origins));
    index_.emplace_back(trace_of(traces_, i));  // once per trace, in place: every selection, phase and range asks it
    detected_.emplace_back();
    QCPGraph* g = plot_->addGraph();
    int color = static_cast<int>(plot_->graphCount()) + 7;
    for (const auto& [platform, index] : colors)
      if (platform == t.platform) color = index;
    g->setPen(QPen(device_color(color), 1));
    colors_.push_back(color);
    start_epoch_.push_back(start_epoch_s(t));
  }
  const bool all_absolute =
      count() > 0 && std::none_of(start_epoch_.begin(), start_epoch_.end(), [](double e) { return std::isnan(e); });
  wall_clock_box_->setEnabled(all_absolute);
  if (!all_absolute && wall_clock_on_) set_wall_clock(false);
  {
    const QSignalBlocker block(overlay_);
    std::vector<QString> names;
    std::vector<std::vector<TracePhase>> phases;
    for (std::size_t i = 0; i < count(); ++i) names.push_back(log_name(trace(i)));
    overlay_->set_traces(names, trace_phases_);
  }
  const bool detect = detect_box_->isChecked();
  if (detect) set_detected_phases(true);  // recomputed for the new traces
  const QSignalBlocker block(cursors_);
  cursors_->clear();
  place_phase_markers();
  // A quantity none of the logs has would open as an empty plot (tegrastats and RAPL logs give power, no current):
  // then the one they have is shown.
  const auto any_has = [this](Quantity q) {
    for (std::size_t i = 0; i < count(); ++i) {
      const TraceIndex* index = q == Quantity::Current ? index_[i].current() : index_[i].power();
      if (index && !index->empty()) return true;
    }
    return false;
  };
  const Quantity other = quantity_ == Quantity::Current ? Quantity::Power : Quantity::Current;
  if (!any_has(quantity_) && any_has(other)) quantity_ = other;
  set_quantity(quantity_);
  update_selection(true);
}

void PowerView::set_detected_phases(bool on) {
  {
    const QSignalBlocker block(detect_box_);
    detect_box_->setChecked(on);
  }
  for (std::size_t i = 0; i < count(); ++i)
    detected_[i] = on ? detect_level_phases(index_[i], PhaseOptions{}) : std::vector<TracePhase>{};
  // Alignment can use detected phases too ("load": the first load step of each trace).
  std::vector<std::vector<TracePhase>> phases;
  for (std::size_t i = 0; i < count(); ++i) {
    phases.push_back(trace_phases_[i]);
    phases.back().insert(phases.back().end(), detected_[i].begin(), detected_[i].end());
  }
  overlay_->set_phases(std::move(phases));
  place_phase_markers();
  update_phase_table();
}

void PowerView::overlay_changed() {
  for (std::size_t i = 0; i < count() && i < static_cast<std::size_t>(plot_->graphCount()); ++i) {
    plot_->graph(static_cast<int>(i))->setVisible(overlay_->visible(i));
    plot_->graph(static_cast<int>(i))->removeFromLegend();
    if (overlay_->visible(i)) plot_->graph(static_cast<int>(i))->addToLegend();
  }
  place_phase_markers();
  redraw_visible();
  update_table();
  update_selection(true);
  update_phase_table();
}

void PowerView::place_phase_markers() {
  plot_->clearItems();  // the previous traces' phase markers (and the cursors' items, brought back below)
  for (std::size_t i = 0; i < count(); ++i) {
    if (!overlay_->visible(i)) continue;
    std::vector<TracePhase> phases = trace_phases_[i];
    if (i < detected_.size()) phases.insert(phases.end(), detected_[i].begin(), detected_[i].end());
    for (TracePhase& p : phases) p.start_s += offset(i), p.end_s += offset(i);
    // Marks, runs, saved selections, level changes; up to 60 named (idle and load alternate: naming every second
    // one would name only one kind).
    add_phase_markers(plot_, phases, device_color(colors_[i]), 60);
  }
  cursors_->rebuild_items();
}

bool PowerView::set_wall_clock(bool on) {
  if (on && !wall_clock_box_->isEnabled()) on = false;
  const bool was = wall_clock_on_;
  wall_clock_on_ = on;
  if (was != on && count() > 0) {  // the cursors keep the same samples: move them with the axis
    const QSignalBlocker block(cursors_);
    cursors_->shift(on ? start_epoch_[0] : -start_epoch_[0]);
  }
  {
    const QSignalBlocker block(wall_clock_box_);
    wall_clock_box_->setChecked(on);
  }
  if (on) {
    auto ticker = QSharedPointer<QCPAxisTickerDateTime>(new QCPAxisTickerDateTime);
    ticker->setDateTimeFormat(QStringLiteral("HH:mm:ss\nyyyy-MM-dd"));
    ticker->setTimeZone(QTimeZone::utc());
    plot_->xAxis->setTicker(ticker);
    plot_->xAxis->setLabel(tr("Time of day (UTC)"));
  } else {
    plot_->xAxis->setTicker(QSharedPointer<QCPAxisTicker>(new QCPAxisTicker));
    plot_->xAxis->setLabel(tr("Time (s)"));
  }
  place_phase_markers();
  rescale();
  return on;
}

const TraceIndex* PowerView::shown(std::size_t trace) const {
  const TraceIndex* index = quantity_ == Quantity::Current ? index_[trace].current() : index_[trace].power();
  return index && !index->empty() ? index : nullptr;
}

void PowerView::set_quantity(Quantity q) {
  quantity_ = q;
  const bool current = q == Quantity::Current;
  const QSignalBlocker block(quantity_box_);
  quantity_box_->setCurrentIndex(current ? 0 : 1);
  plot_->yAxis->setLabel(current ? tr("Current (A)") : tr("Power (W)"));
  for (std::size_t i = 0; i < count() && i < static_cast<std::size_t>(plot_->graphCount()); ++i) {
    const QString missing = current ? tr(" (no current channel)") : tr(" (power unknown: no supply voltage)");
    plot_->graph(static_cast<int>(i))->setName(legend_name(i) + (shown(i) ? QString() : missing));
  }
  rescale();
  update_selection(true);
  update_phase_table();
}

void PowerView::rescale() {
  // Every log on one time axis from its own start (t = 0 s), so the platforms line up as in the paper's figure 4.
  double min_t = wall_clock_on_ ? std::numeric_limits<double>::infinity() : 0, max_t = 0, max_v = 0;
  // Only the logs that draw something: a power-only log (tegrastats) in the current plot draws nothing, and its
  // fifty minutes left the 120 s logs beside it a sliver of the axis.
  for (std::size_t i = 0; i < count(); ++i) {
    const TraceIndex* v = shown(i);
    if (!overlay_->visible(i) || !v) continue;
    min_t = std::min(min_t, offset(i) + v->first_s());
    max_t = std::max(max_t, offset(i) + v->last_s());
    max_v = std::max(max_v, v->summary(v->first_s(), v->last_s()).samples.max);  // O(log n) from the index
  }
  if (!std::isfinite(min_t)) min_t = 0;
  if (!wall_clock_on_) min_t = std::min(min_t, 0.0);        // offsets may move a trace before 0 s
  plot_->yAxis->setRange(0, max_v > 0 ? max_v * 1.25 : 1);  // headroom: the legend sits above the traces
  const QCPRange before = plot_->xAxis->range();
  plot_->xAxis->setRange(min_t, max_t > min_t ? max_t : min_t + 1);
  if (before == plot_->xAxis->range()) {  // no rangeChanged signal: redraw here
    redraw_visible();
    update_table();
  }
}

void PowerView::redraw_visible() {
  // Min/max per pixel column of the visible range: a 10-million-sample trace stays a few thousand points.
  const QCPRange range = plot_->xAxis->range();
  const auto columns = static_cast<std::size_t>(std::max(200, plot_->axisRect()->width()));
  for (std::size_t i = 0; i < count() && i < static_cast<std::size_t>(plot_->graphCount()); ++i) {
    QVector<double> keys, vals;
    if (const TraceIndex* shown_index = shown(i)) {  // its present samples, read in place; power may be scaled current
      const double off = offset(i);
      const DecimatedSeries d = decimate_min_max(shown_index->time(), shown_index->unscaled_values(), range.lower - off,
                                                 range.upper - off, columns);
      keys = QVector<double>(d.t.begin(), d.t.end());
      for (double& k : keys) k += off;
      vals = QVector<double>(d.v.begin(), d.v.end());
      for (double& v : vals) v *= shown_index->scale();
    }
    plot_->graph(static_cast<int>(i))->setData(keys, vals, true);
  }
  plot_->replot();
}

void PowerView::update_table() {
  const QCPRange range = plot_->xAxis->range();
  table_->setRowCount(static_cast<int>(count()));
  for (std::size_t i = 0; i < count(); ++i) {
    const PowerTrace& t = trace(i);
    const PowerStats ps = index_[i].stats(range.lower - offset(i), range.upper - offset(i), false);
    std::optional<Summary> current_a, power_w;
    if (ps.current_a) current_a = ps.current_a->summary;
    if (ps.power_w) power_w = ps.power_w->summary;
    // Every cell says how the log was measured; a flagged log's row is tinted and its tooltips start with why.
    const QString measured = tr("Power measured by: %1").arg(QString::fromStdString(measurement_text(t.provenance)));
    const std::vector<PlausibilityFlag>& flags = flags_[i];
    const QString tip = flags.empty() ? measured : QString::fromStdString(flags_text(flags)) + "\n\n" + measured;
    auto cell = [&](int col, const QString& text) {
      auto* item = new QTableWidgetItem(col == 0 && !flags.empty() ? QStringLiteral("⚠ ") + text : text);
      if (col > 0) item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
      item->setToolTip(tip);
      if (!flags.empty()) item->setBackground(QColor(0xff, 0xe0, 0xb2));
      table_->setItem(static_cast<int>(i), col, item);
    };
    const auto mean_sd = [](const std::optional<Summary>& v) {
      return v ? QStringLiteral("%1 ± %2").arg(v->mean, 0, 'f', 2).arg(v->sd, 0, 'f', 2) : QStringLiteral("–");
    };
    cell(0, log_name(t) + QStringLiteral(" (%1)").arg(QString::fromUtf8(to_string(t.provenance.origin).data())));
    cell(1, QLocale().toString(static_cast<qulonglong>(ps.n)));
    cell(2, mean_sd(current_a));
    cell(3, mean_sd(power_w));
    cell(4, power_w ? QString::number(power_w->max, 'f', 2) : QStringLiteral("–"));
    cell(5, ps.energy_j ? QString::number(*ps.energy_j, 'f', 1) : QStringLiteral("–"));
    QString gflops_w = QStringLiteral("–");
    const PeakRow* best = nullptr;
    for (const PeakRow& r : peaks_)
      if (r.platform == t.platform && (!best || r.peak.flops > best->peak.flops)) best = &r;
    if (best && current_a && t.supply_voltage_v)
      gflops_w =
          QString::number(paper_flops_per_watt(best->peak.flops, *t.supply_voltage_v, current_a->max) / 1e9, 'f', 2);
    cell(6, gflops_w);
    if (best && !best->flags.empty() && table_->item(static_cast<int>(i), 6)) {  // the peak behind GFLOPS/W is flagged
      QTableWidgetItem* item = table_->item(static_cast<int>(i), 6);
      item->setText(QStringLiteral("⚠ ") + item->text());
      item->setBackground(QColor(0xff, 0xe0, 0xb2));
      item->setToolTip(QString::fromStdString(flags_text(best->flags)) + "\n\n" + item->toolTip());
    }
    cell(7, power_w && power_w->mean > 0 && battery_volts_ > 0 && battery_ah_ > 0
                ? QString::number(constant_power_runtime_h(battery_volts_, battery_ah_, power_w->mean) * 60, 'f', 2)
                : QStringLiteral("–"));
  }
}

void PowerView::update_selection(bool final) {
  selection_stats_.clear();
  if (!cursors_->has_selection()) {
    selection_->clear_table();
    return;
  }
  const RangeSignal signal = quantity_ == Quantity::Current ? RangeSignal::Current : RangeSignal::Power;
  std::vector<std::string> headers = {"trace"};
  for (std::string& h : range_headers(signal)) headers.push_back(std::move(h));
  std::vector<std::vector<std::string>> rows;
  std::vector<QString> tips;
  for (std::size_t i = 0; i < count(); ++i) {
    if (!overlay_->visible(i)) continue;
    const double from = cursors_->from() - offset(i), to = cursors_->to() - offset(i);
    // Percentiles are exact: live for short ranges, at the end of a drag for long ones (they cost O(samples)).
    const TraceIndex* main = index_[i].main();
    const auto [first, last] = main ? main->sample_range(from, to) : std::pair<std::size_t, std::size_t>{0, 0};
    const bool with_pct = final || last - first <= kLivePercentileSamples;
    const PowerStats s = index_[i].stats(from, to, with_pct);
    selection_stats_.emplace_back(i, s);
    std::vector<std::string> row = {log_name(trace(i)).toStdString()};
    for (std::string& c : range_cells(s, signal)) row.push_back(std::move(c));
    rows.push_back(std::move(row));
    tips.push_back(tr("%1: %2 .. %3 s of its own time; %4")
                       .arg(log_name(trace(i)))
                       .arg(s.from_s, 0, 'f', 3)
                       .arg(s.to_s, 0, 'f', 3)
                       .arg(QString::fromUtf8(to_string(s.power_source).data())));
  }
  const QString unit = wall_clock_on_ ? tr(" (s since 1970, UTC)") : tr(" s");
  selection_->set_table(tr("Selection A–B: %1 .. %2%3, %4 s; charge and energy integrate over exactly this range "
                           "(interpolated at its ends)")
                            .arg(cursors_->from(), 0, 'f', 3)
                            .arg(cursors_->to(), 0, 'f', 3)
                            .arg(unit)
                            .arg(cursors_->to() - cursors_->from(), 0, 'f', 3),
                        headers, rows, tips);
}

void PowerView::update_phase_table() {
  const RangeSignal signal = quantity_ == Quantity::Current ? RangeSignal::Current : RangeSignal::Power;
  std::vector<std::string> headers = {"phase", "trace", "origin", "from (s)", "to (s)"};
  for (std::string& h : range_headers(signal)) headers.push_back(std::move(h));
  // Rows are grouped by (name, k-th occurrence in its trace), groups in first-seen order: one trace's phases stay in
  // time order (as `power --phases` prints them), and with several traces the k-th "load" of each stands together.
  struct Row {
    std::size_t order;
    std::vector<std::string> cells;
  };
  std::vector<Row> rows;
  std::vector<std::pair<std::string, int>> groups;
  for (std::size_t i = 0; i < count(); ++i) {
    if (!overlay_->visible(i)) continue;
    std::map<std::string, int> seen;
    for (const PhaseStatsRow& p : phase_stats_rows(index_[i], trace_phases_[i], detected_[i], phase_origins_[i])) {
      const std::pair<std::string, int> key{p.name, seen[p.name]++};
      auto it = std::find(groups.begin(), groups.end(), key);
      if (it == groups.end()) it = groups.insert(groups.end(), key);
      char from[32], to[32];
      std::snprintf(from, sizeof from, "%.3f", p.start_s);
      std::snprintf(to, sizeof to, "%.3f", p.end_s);
      std::vector<std::string> cells = {p.name, log_name(trace(i)).toStdString(), p.origin, from, to};
      // A phase the sensor sampled fewer than 10 times is marked (issue #32.4), as in the Kernel Runner and the CLI.
      for (std::string& c : range_cells(p.stats, signal, true)) cells.push_back(std::move(c));
      rows.push_back({static_cast<std::size_t>(it - groups.begin()), std::move(cells)});
    }
  }
  std::stable_sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) { return a.order < b.order; });
  if (rows.empty()) {
    phases_->clear_table();
    return;
  }
  std::vector<std::vector<std::string>> cells;
  for (Row& r : rows) cells.push_back(std::move(r.cells));
  phases_->set_table(tr("%n phase row(s); times in each trace's own seconds; the table benchscope-cli power "
                        "--phases prints",
                        nullptr, static_cast<int>(cells.size())),
                     headers, cells);
}

std::vector<std::size_t> PowerView::selection_logs() const {
  std::vector<std::size_t> out;
  if (!cursors_->has_selection()) return out;
  for (std::size_t i = 0; i < count(); ++i) {
    if (!overlay_->visible(i) || !index_[i].main()) continue;
    const TraceIndex& main = *index_[i].main();
    if (std::min(cursors_->to() - offset(i), main.last_s()) > std::max(cursors_->from() - offset(i), main.first_s()))
      out.push_back(i);
  }
  return out;
}

std::size_t PowerView::drawn_on(const std::vector<std::size_t>& logs) const {
  // The log whose plotted value where the selection began lies nearest to where the mouse pressed: the one the user
  // drew on. Without a press (keys, set()), the first.
  const std::optional<double> y = cursors_->drawn_at();
  const std::optional<double> x = cursors_->a();
  std::size_t best = 0;
  double best_gap = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; y && x && k < logs.size(); ++k) {
    const TraceIndex* v = shown(logs[k]);
    if (!v || v->empty()) continue;
    const double gap = std::abs(v->value_at(*x - offset(logs[k])) - *y);
    if (gap < best_gap) {
      best_gap = gap;
      best = k;
    }
  }
  return best;
}

void PowerView::ask_save_phase() {
  const std::vector<std::size_t> logs = selection_logs();
  if (logs.empty()) {
    QMessageBox::information(this, tr("Save as phase"), tr("The selection does not overlap any visible log."));
    return;
  }
  std::vector<QString> names;
  for (std::size_t i : logs) names.push_back(log_name(trace(i)));
  SavePhaseDialog dialog(names, drawn_on(logs), this);
  if (dialog.exec() != QDialog::Accepted || dialog.name().isEmpty()) return;
  std::vector<std::size_t> chosen;
  for (std::size_t k : dialog.chosen()) chosen.push_back(logs[k]);
  save_selection_as_phase(dialog.name(), chosen);
}

int PowerView::save_selection_as_phase(const QString& name) {
  const std::vector<std::size_t> logs = selection_logs();
  if (logs.empty()) return 0;
  return save_selection_as_phase(name, {logs[drawn_on(logs)]});
}

int PowerView::save_selection_as_phase(const QString& name, const std::vector<std::size_t>& logs) {
  if (!cursors_->has_selection() || name.trimmed().isEmpty()) return 0;
  int saved = 0;
  for (std::size_t i : logs) {
    if (i >= count() || !index_[i].main()) continue;
    const TraceIndex& main = *index_[i].main();
    const double from = std::max(cursors_->from() - offset(i), main.first_s());
    const double to = std::min(cursors_->to() - offset(i), main.last_s());
    if (!(to > from)) continue;
    const TracePhase phase{name.trimmed().toStdString(), from, to};
    const std::int64_t id = traces_->ids[i];
    if (workspace_ && id > 0) {
      try {
        add_user_phase(*workspace_, id, phase);  // origin "user": a range the user saved
      } catch (const std::exception& e) {
        QMessageBox::warning(this, tr("Save as phase"),
                             tr("The phase could not be saved in the workspace: %1").arg(QString::fromUtf8(e.what())));
        return saved;
      }
    }
    auto& phases = trace_phases_[i];
    const auto at = std::upper_bound(phases.begin(), phases.end(), phase,
                                     [](const TracePhase& a, const TracePhase& b) { return a.start_s < b.start_s; });
    phase_origins_[i].insert(phase_origins_[i].begin() + (at - phases.begin()), "user");
    phases.insert(at, phase);
    ++saved;
  }
  if (saved > 0) set_detected_phases(detect_box_->isChecked());  // re-shades, refills the overlay and the table
  return saved;
}

}  // namespace bs::ui
