// SPDX-License-Identifier: GPL-3.0-or-later
#include "platform/platform_view.h"

#include "power/left_out_logs.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QRegularExpression>
#include <QScrollArea>
#include <QSignalBlocker>
#include <QSplitter>
#include <QTableWidget>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "analysis/peaks/plausibility.h"
#include "analysis/platform/platform_table.h"
#include "analysis/power/battery.h"
#include "common/frozen_column.h"
#include "common/numeric_item.h"
#include "platform/candidates_panel.h"
#include "platform/inference_table.h"

namespace bs::ui {
namespace {

constexpr int kColumnRole = Qt::UserRole + 2;

double value_or_nan(std::optional<double> v) { return v ? *v : std::numeric_limits<double>::quiet_NaN(); }

// The number behind each numeric column (NaN = unknown) and which way is better: +1 higher, -1 lower, 0 neither.
struct ColumnValue {
  double value;
  int better;
};
std::vector<ColumnValue> column_values(const PlatformRow& r) {
  const auto frac = [&]() -> std::optional<double> {
    for (const auto* p : {&r.gpu, &r.cpu})
      if (*p && (*p)->fraction_of_theoretical) return *(*p)->fraction_of_theoretical;
    return std::nullopt;
  };
  return {{std::numeric_limits<double>::quiet_NaN(), 0},
          {value_or_nan(r.gpu ? std::optional<double>(r.gpu->peak.flops) : std::nullopt), +1},
          {value_or_nan(r.cpu ? std::optional<double>(r.cpu->peak.flops) : std::nullopt), +1},
          {value_or_nan(frac()), +1},
          {value_or_nan(r.preprocess_ms ? std::optional<double>(r.preprocess_ms->mean) : std::nullopt), -1},
          {value_or_nan(r.detect_ms ? std::optional<double>(r.detect_ms->mean) : std::nullopt), -1},
          {value_or_nan(r.mean_power_w), -1},
          {value_or_nan(r.max_power_w), -1},
          {value_or_nan(r.gflops_per_watt_paper), +1},
          {value_or_nan(r.gflops_per_watt_mean), +1},
          {value_or_nan(r.energy_per_frame_j), -1},
          {value_or_nan(r.energy_per_preprocess_j), -1},
          {value_or_nan(r.energy_per_inference_j), -1},
          {value_or_nan(r.battery_runtime_h), +1},
          {value_or_nan(r.frames_per_wh), +1}};
}

QString tooltip_for(const PlatformRow& r, const std::string& column) {
  const auto it = r.sources.find(column);
  if (it == r.sources.end()) return {};
  const CellSource& s = it->second;
  QString tip =
      QObject::tr("%1\nfrom %2 (%3)\nDouble-click to show it in the workspace")
          .arg(QString::fromStdString(s.how), QString::fromStdString(s.source_file.empty() ? "?" : s.source_file),
               QString::fromUtf8(to_string(s.origin).data()));
  if (column == column::kPower && !r.power_measurement.empty())
    tip += QObject::tr("\nMeasured by: %1").arg(QString::fromStdString(r.power_measurement));
  return tip;
}

// A flagged cell's tooltip starts with why its number is implausible (analysis/plausibility.h).
QString flagged_tooltip(const PlatformRow& r, const std::string& column, const QString& tip) {
  const auto f = r.flags.find(column);
  if (f == r.flags.end()) return tip;
  const QString why = QString::fromStdString(flags_text(f->second));
  return tip.isEmpty() ? why : why + "\n\n" + tip;
}

QDoubleSpinBox* spin(QWidget* parent, double lo, double hi, double value, const QString& suffix, int decimals) {
  auto* s = new QDoubleSpinBox(parent);
  s->setRange(lo, hi);
  s->setValue(value);
  s->setSuffix(suffix);
  s->setDecimals(decimals);
  return s;
}

// The control loop's and the sustained requirement's texts are judged alike: `judge` parses the field's text,
// judges the platforms and returns the summary's line; a text that does not parse turns the field red, and the line
// (`ignored`, its %1 the reason) says the requirement is left out.
template <class Judge>
QString judge_requirement(QLineEdit* field, const QString& ignored, Judge judge) {
  try {
    QString line = judge(field->text().toStdString());
    field->setStyleSheet(QString());
    return line;
  } catch (const std::invalid_argument& e) {
    field->setStyleSheet(QStringLiteral("color:#b00020"));
    return ignored.arg(QString::fromUtf8(e.what()).toHtmlEscaped());
  }
}

// A requirement's text as it is in force: parsed when its box is ticked, nullopt when the box is not or the text
// does not parse (the summary says why). The control loop's and the sustained requirement's alike.
template <class Parse>
auto requirement_in_force(const QCheckBox* use, const QLineEdit* field, Parse parse)
    -> std::optional<decltype(parse(std::string()))> {
  if (!use->isChecked()) return std::nullopt;
  try {
    return parse(field->text().toStdString());
  } catch (const std::invalid_argument&) {
    return std::nullopt;
  }
}

// A requirement's text set from outside (a decision read back), its box ticked when there is one, without the
// signals of a user's edit.
void show_requirement(QCheckBox* use, QLineEdit* field, const QString& text) {
  const QSignalBlocker b1(field), b2(use);
  field->setText(text);
  use->setChecked(!text.isEmpty());
}

// One platform's verdict in the summary's requirement line: its name, the status in bold, and why when there is a
// reason.
QString verdict_text(const std::string& platform, std::string_view status, const std::string& why) {
  QString part =
      QStringLiteral("%1 <b>%2</b>")
          .arg(QString::fromStdString(platform).toHtmlEscaped(), QString::fromStdString(std::string(status)));
  if (!why.empty()) part += QStringLiteral(" (%1)").arg(QString::fromStdString(why).toHtmlEscaped());
  return part;
}

}  // namespace

PlatformView::PlatformView(QWidget* parent) : QWidget(parent) {
  use_budget_ = new QCheckBox(tr("Power budget ≤"), this);
  budget_ = spin(this, 0.1, 10000, 10, tr(" W"), 1);
  use_fps_ = new QCheckBox(tr("Frame rate ≥"), this);
  fps_ = spin(this, 0.1, 10000, 30, tr(" fps"), 1);
  use_runtime_ = new QCheckBox(tr("Battery runtime ≥"), this);
  runtime_ = spin(this, 1, 100000, 60, tr(" min"), 0);
  battery_ = new QComboBox(this);
  battery_->setObjectName(QStringLiteral("battery"));
  // Preset names can be long ("Paper LiPo 4S 16 V 5.2 Ah + servos"): the list shows them whole, the closed box
  // does not widen the window for them.
  battery_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  battery_->setMinimumContentsLength(14);
  mission_ = new QComboBox(this);
  mission_->setEditable(true);
  mission_->setInsertPolicy(QComboBox::NoInsert);
  mission_->setMinimumContentsLength(18);  // fits a 1280 px window; the field scrolls for longer missions
  mission_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  mission_->lineEdit()->setPlaceholderText(tr("name:s:W, … (none: constant load)"));
  mission_->setToolTip(
      tr("Mission profile: phases name:seconds:watts, comma separated (e.g. the servos per phase), "
         "repeated until the pack is empty, in parallel with each computer's mean power and the "
         "parallel load; the battery runtime then follows the mission. Missions saved with the "
         "Battery tab's presets are listed; empty: a constant load."));
  setups_ = builtin_battery_setups();
  fill_battery_choices();
  extra_load_ = spin(this, 0, 10000, 0, tr(" W"), 1);
  use_budget_->setToolTip(tr("Mean power during the platform's power log must stay within this budget"));
  use_fps_->setToolTip(tr("Preprocessing + detection in sequence, from the platform's pipeline run"));
  use_runtime_->setToolTip(tr("Constant-power battery runtime at the mean power plus the parallel load"));
  extra_load_->setToolTip(
      tr("Load in parallel with the computer, e.g. the robot's servos (the paper's robot: up to 225 W)"));
  use_loop_ = new QCheckBox(tr("Control loop:"), this);
  loop_ = new QLineEdit(QStringLiteral("1kHz,p99.9<=200us,max-consecutive-misses<=1,load=pipeline@30fps"), this);
  use_loop_->setToolTip(
      tr("A control-loop requirement checked against each platform's headroom measurement (the Headroom tab, "
         "benchscope-cli headroom): a platform without one is unknown and never passes"));
  loop_->setToolTip(
      tr("RATE (1kHz, 500Hz), limits p50|p99|p99.9|p99.99|max<=TIME (ns, us, ms), misses<=PERCENT%, "
         "max-consecutive-misses<=N, and load=PHASE (pipeline@30fps, dnn:mobilenet-ssd, flops, idle); "
         "without load= every phase must pass"));
  use_sustained_ = new QCheckBox(tr("Sustained:"), this);
  sustained_ = new QLineEdit(QStringLiteral("stability>=97%,minutes>=20"), this);
  use_sustained_->setToolTip(
      tr("A sustained-performance requirement checked against each platform's sustained records (the Sustained tab, "
         "benchscope-cli sustain, imported tegrastats/jtop/nvidia-smi logs): a platform without one is unknown and "
         "never passes"));
  sustained_->setToolTip(
      tr("Terms separated by commas: stability>=PERCENT% (worst / best interval; 3DMark: 97 % is stable), "
         "minutes>=N (the run lasted at least this long), throttle=none (no clock below 80 % of its maximum, no zone "
         "at its trip point), sustained>=RATE (mean of the last third, in the record's unit)"));
  auto* export_tex = new QPushButton(tr("Export LaTeX…"), this);
  auto* export_csv = new QPushButton(tr("Export CSV…"), this);

  // Two rows: the constraints (and exports), then what the battery column assumes (pack, parallel load, mission).
  auto* controls = new QHBoxLayout;
  for (QWidget* w :
       {static_cast<QWidget*>(use_budget_), static_cast<QWidget*>(budget_), static_cast<QWidget*>(use_fps_),
        static_cast<QWidget*>(fps_), static_cast<QWidget*>(use_runtime_), static_cast<QWidget*>(runtime_)})
    controls->addWidget(w);
  controls->addStretch(1);
  controls->addWidget(export_tex);
  controls->addWidget(export_csv);
  auto* battery_row = new QHBoxLayout;
  battery_row->addWidget(new QLabel(tr("Battery:"), this));
  battery_row->addWidget(battery_);
  battery_row->addWidget(new QLabel(tr("Parallel load:"), this));
  battery_row->addWidget(extra_load_);
  auto* mission_label = new QLabel(tr("Mission:"), this);
  mission_label->setToolTip(mission_->toolTip());
  battery_row->addWidget(mission_label);
  battery_row->addWidget(mission_, 1);
  // A row of its own: the battery row already fills a 1280 px window beside the workspace dock.
  auto* loop_row = new QHBoxLayout;
  loop_row->addWidget(use_loop_);
  loop_row->addWidget(loop_, 2);
  loop_row->addWidget(use_sustained_);
  loop_row->addWidget(sustained_, 1);

  summary_ = new QLabel(this);
  summary_->setWordWrap(true);
  table_ = new QTableWidget(this);
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  table_->setSelectionBehavior(QAbstractItemView::SelectItems);
  table_->verticalHeader()->setVisible(false);
  table_->horizontalHeader()->setDefaultAlignment(Qt::Alignment(Qt::AlignCenter) | Qt::Alignment(Qt::TextWordWrap));
  table_->setWordWrap(true);
  table_->horizontalHeader()->setStretchLastSection(true);
  frozen_ = new FrozenFirstColumn(table_);

  auto* layout = new QVBoxLayout(this);
  layout->addLayout(controls);
  layout->addLayout(battery_row);
  layout->addLayout(loop_row);
  // Under the controls, the summary (scrolling where it is long), the comparison, the inference table and the
  // candidates share the height in a splitter the person moves and the window keeps: in one layout at 1280x800 the
  // candidates' figure and note left the comparison its header and one row (issue #50.5).
  summary_box_ = new QScrollArea(this);
  summary_box_->setWidget(summary_);
  summary_box_->setWidgetResizable(true);
  summary_box_->setFrameShape(QFrame::NoFrame);
  summary_box_->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  summary_box_->setMinimumHeight(2 * fontMetrics().lineSpacing() + 4);  // two lines, then it scrolls
  inference_ = new InferenceTable(this);
  candidates_ = new CandidatesPanel(this);
  split_ = new QSplitter(Qt::Vertical, this);
  split_->setObjectName(QStringLiteral("platformsSplit"));
  for (QWidget* pane : {static_cast<QWidget*>(summary_box_), static_cast<QWidget*>(table_),
                        static_cast<QWidget*>(inference_), static_cast<QWidget*>(candidates_)})
    split_->addWidget(pane);
  split_->setChildrenCollapsible(false);
  // A larger window gives its height to the comparison and the candidates; the summary and the inference rows keep
  // theirs.
  for (int pane : {0, 2}) split_->setStretchFactor(pane, 0);
  for (int pane : {1, 3}) split_->setStretchFactor(pane, 1);
  layout->addWidget(split_, 1);
  split_->installEventFilter(this);
  connect(split_, &QSplitter::splitterMoved, this, [this] { auto_split_ = false; });

  // A value counts when it is entered (Enter, leaving the field, an arrow step), not at every key typed: each is one
  // step of Edit > Undo, and the workspace keeps it.
  for (QCheckBox* c : {use_budget_, use_fps_, use_runtime_, use_loop_, use_sustained_}) {
    connect(c, &QCheckBox::toggled, this, &PlatformView::recompute);
    connect(c, &QCheckBox::clicked, this, &PlatformView::user_changed);
  }
  for (QDoubleSpinBox* s : {budget_, fps_, runtime_, extra_load_}) {
    s->setKeyboardTracking(false);
    connect(s, &QDoubleSpinBox::valueChanged, this, &PlatformView::recompute);
    connect(s, &QDoubleSpinBox::valueChanged, this, &PlatformView::user_changed);
  }
  connect(battery_, &QComboBox::currentIndexChanged, this, [this](int i) {
    if (i == 0 && has_tab_setup_) {  // the Battery tab's setup brings its parallel load and mission along
      const QSignalBlocker b1(extra_load_), b2(mission_);
      extra_load_->setValue(setups_.front().extra_load_w);
      mission_->setEditText(QString::fromStdString(setups_.front().mission));
    }
    // A preset saved with a mission brings it along (the user can still change it).
    else if (i >= 0 && i < static_cast<int>(setups_.size()) && !setups_[static_cast<std::size_t>(i)].mission.empty()) {
      const QSignalBlocker block(mission_);
      mission_->setEditText(QString::fromStdString(setups_[static_cast<std::size_t>(i)].mission));
    }
    recompute();
    user_changed();
  });
  connect(mission_, &QComboBox::activated, this, &PlatformView::recompute);
  connect(mission_, &QComboBox::activated, this, &PlatformView::user_changed);
  for (QLineEdit* e : {loop_, sustained_, mission_->lineEdit()}) {
    connect(e, &QLineEdit::editingFinished, this, &PlatformView::recompute);
    connect(e, &QLineEdit::editingFinished, this, &PlatformView::user_changed);
  }
  connect(candidates_, &CandidatesPanel::selection_edited, this, &PlatformView::user_changed);
  connect(export_tex, &QPushButton::clicked, this, [this] { export_table(true); });
  connect(export_csv, &QPushButton::clicked, this, [this] { export_table(false); });
  connect(table_, &QTableWidget::cellDoubleClicked, this, [this](int row, int col) {
    const QTableWidgetItem* item = table_->item(row, col);
    if (!item) return;
    const int index = item->data(Qt::UserRole).toInt();
    if (index >= 0 && index < static_cast<int>(rows_.size()))
      emit source_requested(rows_[static_cast<std::size_t>(index)], item->data(kColumnRole).toString());
  });
}

PlatformView::~PlatformView() { delete frozen_; }

QString PlatformView::summary_text() const { return summary_->text(); }  // before the table and its model go

void PlatformView::set_data(std::vector<FlopsRun> runs, std::vector<PowerTrace> traces,
                            std::vector<PipelineRun> pipelines) {
  set_data(std::move(runs), share_traces(std::move(traces)), std::move(pipelines));
}

void PlatformView::set_data(std::vector<FlopsRun> runs, SharedTraces traces, std::vector<PipelineRun> pipelines) {
  runs_ = std::move(runs);
  traces_ = std::move(traces);
  pipelines_ = pipeline_timings(pipelines);
  pipeline_runs_ = std::move(pipelines);
  recompute();
}

void PlatformView::set_inference_runs(std::vector<DnnRun> runs) {
  dnn_runs_ = runs;
  inference_->set_runs(std::move(runs));
  recompute();
}

void PlatformView::set_result_sets(std::vector<ResultSet> sets) {
  result_sets_ = std::move(sets);
  recompute();
}

void PlatformView::fill_battery_choices() {
  const QSignalBlocker b1(battery_), b2(mission_);
  const QString current = battery_->currentData().toString(), typed = mission_->currentText();
  battery_->clear();
  mission_->clear();
  mission_->addItem(QString());  // none: a constant load
  mission_->setItemData(0, tr("No mission: the computer's mean power plus the parallel load, constant"),
                        Qt::ToolTipRole);
  for (std::size_t i = 0; i < setups_.size(); ++i) {
    const BatterySetup& s = setups_[i];
    if (i == 0 && has_tab_setup_) {
      battery_->addItem(tab_setup_label_, QStringLiteral("\x01battery-tab"));  // a data key no preset name can have
      battery_->setItemData(0,
                            tr("The pack as the Battery tab shows it now (%1 V, %2 mAh, %3 % usable), with its "
                               "parallel load and mission")
                                .arg(s.pack.nominal_v(), 0, 'f', 1)
                                .arg(s.pack.capacity_ah * 1000, 0, 'f', 0)
                                .arg(s.depth_of_discharge * 100, 0, 'f', 0),
                            Qt::ToolTipRole);
    } else {
      battery_->addItem(QString::fromStdString(s.pack.description.empty() ? s.pack.name : s.pack.description),
                        QString::fromStdString(s.pack.name));
    }
    if (s.mission.empty() || mission_->findText(QString::fromStdString(s.mission)) >= 0) continue;
    mission_->addItem(QString::fromStdString(s.mission));
    mission_->setItemData(mission_->count() - 1,
                          tr("Mission of the battery preset %1").arg(QString::fromStdString(s.pack.name)),
                          Qt::ToolTipRole);
  }
  // The Battery tab's example mission (servo loads of a walking robot; the paper's robot peaks at 225 W).
  const QString example = QStringLiteral("idle:60:12,walk:30:140,kick:5:225");
  if (mission_->findText(example) < 0) {
    mission_->addItem(example);
    mission_->setItemData(mission_->count() - 1,
                          tr("Example: idle 60 s at 12 W, walk 30 s at 140 W, kick 5 s at 225 W (servos), repeated"),
                          Qt::ToolTipRole);
  }
  const int again = battery_->findData(current);
  battery_->setCurrentIndex(again >= 0 ? again : 0);
  mission_->setEditText(typed);
}

void PlatformView::set_workspace(const Workspace* ws) {
  std::vector<BatterySetup> setups = all_battery_setups(ws);
  if (has_tab_setup_) setups.insert(setups.begin(), setups_.front());
  setups_ = std::move(setups);
  fill_battery_choices();
  // The decision as the workspace keeps it (issue #43.2): what was set before closing is set again on opening.
  std::optional<StoredDecision> stored;
  QString problem;
  if (ws) {
    try {
      stored = stored_decision(*ws);
    } catch (const std::exception& e) {
      // A stored value out of range (a hand-edited file): the defaults, and the reason said where the decision shows.
      stored.reset();
      problem = QString::fromUtf8(e.what());
    }
  }
  apply_decision(stored, problem);
}

void PlatformView::set_battery_tab_setup(const BatterySetup& setup, bool modified) {
  const bool follow = !has_tab_setup_ || battery_->currentIndex() == 0;
  if (has_tab_setup_)
    setups_.front() = setup;
  else
    setups_.insert(setups_.begin(), setup);
  has_tab_setup_ = true;
  tab_setup_label_ = modified ? tr("Battery tab: %1, modified").arg(QString::fromStdString(setup.pack.name))
                              : tr("Battery tab: %1").arg(QString::fromStdString(setup.pack.name));
  fill_battery_choices();
  if (follow) {
    const QSignalBlocker b1(battery_), b2(extra_load_), b3(mission_);
    battery_->setCurrentIndex(0);
    extra_load_->setValue(setup.extra_load_w);
    mission_->setEditText(QString::fromStdString(setup.mission));
  }
  recompute();
}

void PlatformView::battery_tab_edited() {
  if (decision_stored_ && has_tab_setup_ && battery_->currentIndex() == 0) user_changed();
}

void PlatformView::set_mission(const QString& spec) {
  mission_->setEditText(spec);
  recompute();
}

QString PlatformView::mission() const { return mission_->currentText().trimmed(); }

ComparisonOptions PlatformView::options() const {
  ComparisonOptions o;
  const int i = battery_->currentIndex();
  if (i >= 0 && i < static_cast<int>(setups_.size())) {
    const BatterySetup& s = setups_[static_cast<std::size_t>(i)];
    o.battery_nominal_v = s.pack.nominal_v();
    o.battery_capacity_ah = s.pack.capacity_ah;
    o.usable_fraction = s.depth_of_discharge;
  }
  o.extra_load_w = extra_load_->value();
  o.mission = mission().toStdString();
  return o;
}

StoredDecision PlatformView::decision() const {
  StoredDecision d;
  if (use_budget_->isChecked()) d.power_budget_w = budget_->value();
  if (use_fps_->isChecked()) d.min_fps = fps_->value();
  if (use_runtime_->isChecked()) d.min_runtime_min = runtime_->value();
  const QString battery = battery_->currentData().toString();
  d.battery = battery.startsWith(QChar(0x01)) ? std::string() : battery.toStdString();
  d.extra_load_w = extra_load_->value();
  d.mission = mission().toStdString();
  d.candidates = candidates_->selection().toStdString();
  // The control loop as it counts: a requirement that does not parse is ignored by the verdicts (the summary says
  // why), so it is not part of the decision either.
  if (const auto loop = loop_requirement()) d.loop = loop->text;
  if (const auto sustained = sustained_requirement()) d.sustained = sustained->text;
  return d;
}

void PlatformView::apply_decision(const std::optional<StoredDecision>& stored, const QString& problem) {
  decision_problem_ = problem;
  decision_stored_ = stored.has_value();
  const StoredDecision d = stored.value_or(StoredDecision{});
  {
    const QSignalBlocker b1(use_budget_), b2(use_fps_), b3(use_runtime_), b4(budget_), b5(fps_), b6(runtime_),
        b7(battery_), b8(extra_load_), b9(mission_), b10(use_loop_), b11(loop_), b12(use_sustained_), b13(sustained_);
    use_budget_->setChecked(d.power_budget_w.has_value());
    if (d.power_budget_w) budget_->setValue(*d.power_budget_w);
    use_fps_->setChecked(d.min_fps.has_value());
    if (d.min_fps) fps_->setValue(*d.min_fps);
    use_runtime_->setChecked(d.min_runtime_min.has_value());
    if (d.min_runtime_min) runtime_->setValue(*d.min_runtime_min);
    // No stored requirement leaves the text as it is (the example, or what was typed) with the check box off.
    use_loop_->setChecked(!d.loop.empty());
    if (!d.loop.empty()) loop_->setText(QString::fromStdString(d.loop));
    use_sustained_->setChecked(!d.sustained.empty());
    if (!d.sustained.empty()) sustained_->setText(QString::fromStdString(d.sustained));
    // "" follows the Battery tab (the first choice while it is known); a preset that is gone falls back to it too.
    const int preset = d.battery.empty() ? -1 : battery_->findData(QString::fromStdString(d.battery));
    battery_->setCurrentIndex(preset >= 0 ? preset : 0);
    if (stored) {
      extra_load_->setValue(d.extra_load_w);
      mission_->setEditText(QString::fromStdString(d.mission));
    } else if (has_tab_setup_) {  // nothing stored: the Battery tab's setup, as on a first start
      extra_load_->setValue(setups_.front().extra_load_w);
      mission_->setEditText(QString::fromStdString(setups_.front().mission));
    } else {
      extra_load_->setValue(0);
      mission_->setEditText(QString());
    }
  }
  candidates_->set_selection(QString::fromStdString(d.candidates));
  recompute();
  last_decision_ = decision();
}

void PlatformView::user_changed() {
  const StoredDecision d = decision();
  if (d == last_decision_) return;
  last_decision_ = d;
  decision_stored_ = true;
  emit decision_edited(d);
}

Constraints PlatformView::constraints() const {
  Constraints c;
  if (use_budget_->isChecked()) c.power_budget_w = budget_->value();
  if (use_fps_->isChecked()) c.min_fps = fps_->value();
  if (use_runtime_->isChecked()) c.min_runtime_h = runtime_->value() / 60.0;
  return c;
}

void PlatformView::set_power_budget(std::optional<double> watts) {
  if (watts) budget_->setValue(*watts);
  use_budget_->setChecked(watts.has_value());
}
void PlatformView::set_min_fps(std::optional<double> fps) {
  if (fps) fps_->setValue(*fps);
  use_fps_->setChecked(fps.has_value());
}
void PlatformView::set_min_runtime_min(std::optional<double> minutes) {
  if (minutes) runtime_->setValue(*minutes);
  use_runtime_->setChecked(minutes.has_value());
}

QString PlatformView::recommendation() const {
  for (const auto& v : verdicts_)
    if (v.recommended) return QString::fromStdString(v.platform);
  return {};
}

void PlatformView::recompute() {
  ComparisonOptions o = options();
  mission_error_.clear();
  try {
    rows_ = compare_platforms(runs_, traces_->traces, pipelines_, o);
  } catch (const std::invalid_argument& e) {
    // A mistyped mission: say why, and show the constant-load numbers meanwhile.
    mission_error_ = QString::fromStdString(e.what());
    o.mission.clear();
    rows_ = compare_platforms(runs_, traces_->traces, pipelines_, o);
  }
  verdicts_ = recommend(rows_, constraints());
  // The control loop's checks join each verdict: no headroom measurement is unknown, never passing.
  loop_verdicts_.clear();
  // The loop's verdicts, when a requirement is in force, judge the candidates too: no pick the verdict rejects.
  std::optional<std::vector<headroom::LoopVerdict>> candidate_loop;
  std::vector<std::string> names;
  for (const PlatformRow& row : rows_) names.push_back(row.platform);
  QString loop_text;
  if (use_loop_->isChecked())
    loop_text = judge_requirement(
        loop_, tr("<br><span style='color:#b00020'>Control loop ignored: %1</span>"), [&](const std::string& text) {
          const headroom::LoopRequirement r = headroom::parse_loop_requirement(text);
          loop_verdicts_ = headroom::evaluate_loop(r, headroom_, names);
          headroom::apply_loop(verdicts_, loop_verdicts_);
          candidate_loop = loop_verdicts_;
          QStringList parts;
          for (const headroom::LoopVerdict& v : loop_verdicts_)
            parts << verdict_text(v.platform, to_string(v.status), v.reason) +
                         (!v.measurement.empty() && !v.realtime ? tr(" ⚠ non-real-time measurement") : QString());
          return tr("<br>Control loop %1: %2.")
              .arg(QString::fromStdString(headroom::describe(r)).toHtmlEscaped(), parts.join("; "));
        });
  // The sustained requirement's checks join them the same way: no sustained record is unknown, never passing.
  sustained_verdicts_.clear();
  std::optional<std::vector<sustain::SustainVerdict>> candidate_sustained;
  QString sustained_text;
  if (use_sustained_->isChecked())
    sustained_text =
        judge_requirement(sustained_, tr("<br><span style='color:#b00020'>Sustained requirement ignored: %1</span>"),
                          [&](const std::string& text) {
                            const sustain::SustainRequirement r = sustain::parse_sustain_requirement(text);
                            sustained_verdicts_ = sustain::evaluate_sustain(r, sustained_runs_, names);
                            sustain::apply_sustain(verdicts_, sustained_verdicts_);
                            candidate_sustained = sustained_verdicts_;
                            QStringList parts;
                            for (const sustain::SustainVerdict& v : sustained_verdicts_)
                              parts << verdict_text(v.platform, to_string(v.status),
                                                    v.status == RequirementStatus::Pass ? v.margin : v.reason);
                            return tr("<br>Sustained %1: %2.")
                                .arg(QString::fromStdString(sustain::describe(r)).toHtmlEscaped(), parts.join("; "));
                          });
  loop_text += sustained_text;
  fill_table();
  candidates_->set_own(rows_, pipeline_runs_, dnn_runs_, result_sets_, constraints(), o, std::move(candidate_loop),
                       std::move(candidate_sustained));
  const QString hidden =
      empty_columns_.isEmpty()
          ? QString()
          : tr("<br><span style='color:gray'>No data yet (hidden): %1.</span>").arg(empty_columns_.join(", "));
  if (rows_.empty()) {
    summary_->setText(
        tr("No FLOPS runs or power logs in the workspace yet: import some (File ▸ Import) to compare platforms."));
  } else if (!constrained()) {
    summary_->setText(tr("Most compute among the platforms with a power log: <b>%1</b>. Set constraints above to see "
                         "which platforms meet them.")
                          .arg(recommendation().isEmpty() ? tr("none") : recommendation()));
  } else {
    summary_->setText(
        recommendation().isEmpty()
            ? tr("<b>No platform meets every constraint</b>; the last column says which one each fails and by how "
                 "much.")
            : tr("Recommended: <b>%1</b> (the most compute among the platforms that meet every constraint).")
                  .arg(recommendation()));
  }
  if (!decision_problem_.isEmpty())
    summary_->setText(tr("<span style='color:#b00020'>The decision stored in the workspace could not be read (%1); "
                         "the defaults are shown, and a change here replaces it.</span><br>")
                          .arg(decision_problem_.toHtmlEscaped()) +
                      summary_->text());
  // Logs that give no power are not in the power columns: say which and why (issue #32.2).
  QString left_out = left_out_logs_text(traces_->traces).toHtmlEscaped();
  if (!left_out.isEmpty())
    left_out = QStringLiteral("<br><span style='color:#8a5a00'>%1</span>").arg(left_out.replace('\n', "<br>"));
  if (rows_.empty()) {
    summary_->setText(summary_->text() + left_out);
    return;
  }
  // A flagged peak is shown (marked in the table) but never decides: say whose compute was ranked by what.
  QStringList ranking;
  for (const auto& v : verdicts_)
    if (!v.ranking_note.empty())
      ranking << tr("%1: %2")
                     .arg(QString::fromStdString(v.platform), QString::fromStdString(v.ranking_note))
                     .toHtmlEscaped();
  if (!ranking.isEmpty())
    summary_->setText(summary_->text() +
                      tr("<br><span style='color:#8a4b00'>⚠ Ranking: %1.</span>").arg(ranking.join("; ")));
  // What the battery column assumes: the pack, and the mission with each platform's mean load on the pack.
  QString battery = tr("<br>Battery runtime: %1, constant-power model").arg(battery_->currentText().toHtmlEscaped());
  if (!mission_error_.isEmpty()) {
    battery += tr(" — <span style='color:#b00020'>mission ignored: %1</span>").arg(mission_error_.toHtmlEscaped());
  } else if (!o.mission.empty()) {
    QStringList loads;
    for (const PlatformRow& r : rows_)
      if (r.battery_load_w)
        loads << tr("%1 %2 W").arg(QString::fromStdString(r.platform)).arg(*r.battery_load_w, 0, 'f', 1);
    battery += tr(", mission <tt>%1</tt> repeated with each computer in parallel (mean load: %2)")
                   .arg(QString::fromStdString(o.mission).toHtmlEscaped(), loads.join(", "));
  } else if (o.extra_load_w > 0) {
    battery += tr(", computer + %1 W parallel load").arg(o.extra_load_w, 0, 'f', 1);
  }
  summary_->setText(summary_->text() + battery + "." + loop_text + hidden + left_out);
}

bool PlatformView::constrained() const {
  const Constraints c = constraints();
  return c.power_budget_w || c.min_fps || c.min_runtime_h || (use_loop_->isChecked() && !loop_->text().isEmpty()) ||
         (use_sustained_->isChecked() && !sustained_->text().isEmpty());
}

std::optional<sustain::SustainRequirement> PlatformView::sustained_requirement() const {
  return requirement_in_force(use_sustained_, sustained_, sustain::parse_sustain_requirement);
}

void PlatformView::set_sustained(std::vector<SustainRun> runs) {
  sustained_runs_ = std::move(runs);
  recompute();
}

void PlatformView::set_sustained_requirement(const QString& text) {
  show_requirement(use_sustained_, sustained_, text);
  recompute();
}

std::optional<headroom::LoopRequirement> PlatformView::loop_requirement() const {
  return requirement_in_force(use_loop_, loop_, headroom::parse_loop_requirement);
}

void PlatformView::set_headroom(std::vector<headroom::HeadroomMeasurement> measurements) {
  headroom_ = std::move(measurements);
  recompute();
}

void PlatformView::set_loop_requirement(const QString& text) {
  show_requirement(use_loop_, loop_, text);
  recompute();
}

void PlatformView::fill_table() {
  const bool with_verdicts = constrained();
  const ExportTable t = platform_table(
      rows_, with_verdicts ? std::span<const PlatformVerdict>(verdicts_) : std::span<const PlatformVerdict>());
  const auto ids = platform_table_columns(with_verdicts);
  table_->setSortingEnabled(false);
  table_->clear();
  table_->setColumnCount(static_cast<int>(t.header.size()));
  table_->setRowCount(static_cast<int>(t.rows.size()));
  std::vector<QString> header_tips(t.header.size());
  for (int c = 0; c < table_->columnCount(); ++c) {
    const std::string& id = ids[static_cast<std::size_t>(c)];
    QString& tip = header_tips[static_cast<std::size_t>(c)];
    if (id == column::kFramesPerWh)
      tip =
          tr("Frames per watt-hour: frames preprocessed and detected per Wh of the computer, 3600 / energy per "
             "frame (J); energy per frame = mean power × (preprocessing + detection) mean time, or the logged "
             "energy over the pipeline run when the log covers it.");
    else if (id == column::kBattery)
      tip =
          tr("Battery runtime on the chosen pack (constant-power model): the computer's mean power plus the "
             "parallel load, or over the mission profile when one is set.");
  }
  // The best value per numeric column among the platforms that have one.
  std::vector<double> best(t.header.size(), std::numeric_limits<double>::quiet_NaN());
  std::vector<std::vector<ColumnValue>> values;
  for (const auto& r : rows_) values.push_back(column_values(r));
  const std::size_t numeric_columns = values.empty() ? 0 : values.front().size();
  for (std::size_t col = 1; col < numeric_columns; ++col)
    for (std::size_t i = 0; i < values.size(); ++i) {
      const ColumnValue& cv = values[i][col];
      if (std::isnan(cv.value) || cv.better == 0) continue;
      if (col < ids.size() && rows_[i].flags.count(ids[col])) continue;  // an implausible number is never "best"
      if (std::isnan(best[col]) || (cv.better > 0 ? cv.value > best[col] : cv.value < best[col])) best[col] = cv.value;
    }
  const int with_data = static_cast<int>(rows_.size());
  // The verdict sits next to the platform's name (the table's own order puts it last, which is off-screen on a
  // small window): view column c shows table column order[c].
  std::vector<std::size_t> order{0};
  if (with_verdicts && t.header.size() >= 2)
    for (std::size_t c = t.header.size() - 2; c < t.header.size(); ++c) order.push_back(c);
  // Then the columns a choice rests on (peaks, mean power, GFLOPS/W, battery runtime), so they show without
  // scrolling on a 1280x800 window (issue #32.7); the pipeline and energy details follow.
  for (const char* key :
       {column::kGpuPeak, column::kCpuPeak, column::kPower, "gflops_w_mean", "gflops_w_paper", column::kBattery})
    for (std::size_t c = 1; c < ids.size() && c < t.header.size(); ++c)
      if (ids[c] == key && std::find(order.begin(), order.end(), c) == order.end()) {
        order.push_back(c);
        break;
      }
  for (std::size_t c = 1; c < t.header.size(); ++c)
    if (std::find(order.begin(), order.end(), c) == order.end()) order.push_back(c);
  QStringList ordered_header;
  for (std::size_t c : order) ordered_header << QString::fromStdString(t.header[c]);
  table_->setHorizontalHeaderLabels(ordered_header);
  for (int c = 0; c < table_->columnCount(); ++c)
    if (auto* h = table_->horizontalHeaderItem(c); h && !header_tips[order[static_cast<std::size_t>(c)]].isEmpty())
      h->setToolTip(header_tips[order[static_cast<std::size_t>(c)]]);
  for (int r = 0; r < static_cast<int>(t.rows.size()); ++r) {
    const PlatformVerdict* verdict =
        with_verdicts && r < static_cast<int>(verdicts_.size()) ? &verdicts_[static_cast<std::size_t>(r)] : nullptr;
    // A platform that fails a constraint is dimmed, with the reason on every cell of its row.
    const bool fails = verdict && !verdict->meets_all;
    const QString fail_reason =
        fails ? tr("Fails the constraints: %1").arg(QString::fromStdString(t.rows[r].back())) : QString();
    const PlatformRow& row = rows_[static_cast<std::size_t>(r)];
    for (int c = 0; c < static_cast<int>(order.size()); ++c) {
      const std::size_t cu = order[static_cast<std::size_t>(c)];
      QString text = QString::fromStdString(t.rows[r][cu]);
      // The table's footnote marker " [n]" (for LaTeX/CSV) becomes "⚠" here: the reason is in the tooltip.
      if (row.flags.count(ids[cu]))
        text.replace(QRegularExpression(QStringLiteral(" \\[[0-9,]+\\]$")), QStringLiteral(" ⚠"));
      auto* item = new NumericItem(text);
      item->setData(Qt::UserRole, r);
      item->setData(kColumnRole, QString::fromStdString(ids[cu]));
      if (cu < values[static_cast<std::size_t>(r)].size() && cu > 0) {
        const double v = values[static_cast<std::size_t>(r)][cu].value;
        item->setData(kSortRole, v);
        item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        if (!std::isnan(v) && v == best[cu] && with_data > 1 && !fails) {
          QFont f = item->font();
          f.setBold(true);
          item->setFont(f);
          item->setBackground(QColor(0xd9, 0xf2, 0xd9));
        }
      }
      QString tip = flagged_tooltip(row, ids[cu], tooltip_for(row, ids[cu]));
      if (row.flags.count(ids[cu])) item->setBackground(QColor(0xff, 0xe0, 0xb2));  // flagged: see the tooltip
      if (fails) {
        item->setForeground(QColor(0x8a, 0x8a, 0x8a));
        tip = tip.isEmpty() ? fail_reason : fail_reason + "\n\n" + tip;
      }
      if (!tip.isEmpty()) item->setToolTip(tip);
      if (cu == 0 && verdict && verdict->recommended) {
        QFont f = item->font();
        f.setBold(true);
        item->setFont(f);
        item->setBackground(QColor(0xd6, 0xe4, 0xf5));
        item->setToolTip(
            tr("Recommended: the most compute among the platforms with a power log that meet every constraint"));
      }
      table_->setItem(r, c, item);
    }
  }
  // Columns nobody has data for yet (no pipeline runs imported, no theoretical peaks) are hidden, and named in
  // the summary, so the columns that matter fit the window.
  empty_columns_.clear();
  for (int c = 1; c < table_->columnCount(); ++c) {
    bool empty = true;
    for (int r = 0; r < table_->rowCount() && empty; ++r)
      empty = table_->item(r, c)->text() == QString::fromUtf8("\u2013");
    table_->setColumnHidden(c, empty && table_->rowCount() > 0);
    if (empty && table_->rowCount() > 0) empty_columns_ << table_->horizontalHeaderItem(c)->text();
  }
  table_->setSortingEnabled(true);
  table_->resizeColumnsToContents();
  // Numbers need little room; headers wrap onto three lines instead of widening their columns.
  for (int c = 0; c < table_->columnCount(); ++c) {
    const QString id = table_->item(0, c) ? table_->item(0, c)->data(kColumnRole).toString() : QString();
    const int cap = c == 0                                                                                     ? 200
                    : id == "meets"                                                                            ? 150
                    : id == "failed"                                                                           ? 220
                    : (id == QString::fromUtf8(column::kGpuPeak) || id == QString::fromUtf8(column::kCpuPeak)) ? 160
                                                                                                               : 104;
    table_->setColumnWidth(c, std::min(table_->columnWidth(c), cap));
  }
  table_->horizontalHeader()->setMinimumHeight(64);
  table_->resizeRowsToContents();
  frozen_->sync_columns();
  fit_split();  // its rows may need more or less room now
}

void PlatformView::export_table(bool latex) {
  const QString filter = latex ? tr("LaTeX (*.tex)") : tr("CSV (*.csv)");
  const QString path = QFileDialog::getSaveFileName(this, latex ? tr("Export LaTeX table") : tr("Export CSV table"),
                                                    latex ? "platforms.tex" : "platforms.csv", filter);
  if (path.isEmpty()) return;
  const bool with_verdicts = constrained();
  const ExportTable t = platform_table(
      rows_, with_verdicts ? std::span<const PlatformVerdict>(verdicts_) : std::span<const PlatformVerdict>());
  const std::string text = latex ? to_latex(t) : to_csv(t);
  QFile f(path);
  if (!f.open(QIODevice::WriteOnly) ||
      f.write(text.data(), static_cast<qint64>(text.size())) != static_cast<qint64>(text.size()))
    QMessageBox::warning(this, tr("Export failed"), tr("Cannot write %1: %2").arg(path, f.errorString()));
}

}  // namespace bs::ui
