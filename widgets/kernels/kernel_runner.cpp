// SPDX-License-Identifier: GPL-3.0-or-later
#include "kernels/kernel_runner.h"

#include <QCheckBox>
#include <QColor>
#include <QComboBox>
#include <QFormLayout>
#include <QFutureWatcher>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QTableWidget>
#include <QtConcurrent>

#include <algorithm>

#include "analysis/peaks/ceiling_check.h"
#include "analysis/peaks/flops.h"
#include "analysis/peaks/plausibility.h"
#include "analysis/power/sweep_energy.h"
#include "analysis/stats/stats.h"
#include "analysis/stats/units.h"
#include "commands/run_flops_grammar.h"
#include "common/reading_label.h"
#include "kernels/ceilings/ceiling_cache.h"
#include "kernels/sweep.h"
#include "kernels/worker_spec.h"
#include "power/power_sensor_box.h"
#include "remote/remote_run.h"
#include "remote/robot_queue_dialog.h"
#include "remote/robot_target.h"
#include "remote/run_here_or_robot.h"
#include "sensors/recorder.h"

namespace bs::ui {
namespace {
constexpr int kEnergyColumns = 8;  // D, W, GFLOPS, mean W, J (point), J per run, GFLOPS/W, n samples
}  // namespace

KernelRunner::KernelRunner(QWidget* parent)
    : QWidget(parent),
      backend_(new QComboBox(this)),
      variant_(new QComboBox(this)),
      workers_(new QLineEdit("1,2,4,8,16,32,64,128,256,512,1024", this)),
      dims_(new QLineEdit("1,2,4", this)),
      iterations_(new QSpinBox(this)),
      repeats_(new QSpinBox(this)),
      details_(reading_label(this)),
      input_error_(new QLabel(this)),
      ceilings_(reading_label(this)),
      measure_ceilings_(new QPushButton(tr("Measure ceilings"), this)),
      run_(new QPushButton(tr("Run"), this)),
      stop_(new QPushButton(tr("Cancel"), this)),
      progress_(new QProgressBar(this)),
      power_(new PowerSensorBox(this)),
      energy_(new QTableWidget(this)),
      target_(new RobotTarget(this)),
      robot_power_(new QCheckBox(tr("On the robot (auto)"), this)),
      several_(new QPushButton(tr("Several robots…"), this)),
      remote_log_(reading_label(this)),
      controller_(new RunHereOrRobot(target_, this)) {
  qRegisterMetaType<bs::FlopsRun>();
  qRegisterMetaType<std::vector<bs::FlopsRun>>();
  iterations_->setRange(1, 100'000'000);
  iterations_->setValue(40000);
  iterations_->setGroupSeparatorShown(true);
  iterations_->setToolTip(tr("N: rotations per point (the paper uses 40,000)"));
  repeats_->setRange(1, 100);
  repeats_->setValue(3);
  repeats_->setToolTip(tr("Timings per point; the plot shows mean ± SD"));
  workers_->setToolTip(
      tr("Worker counts: 1,2,4,8 or start:stop:step such as 256:1024000:256 (paper GPUs) or "
         "1:4096:32 (paper CPUs)"));
  dims_->setToolTip(tr("D values: 2D points per worker (paper: 1, 2, 4)"));
  variant_->addItem(tr("throughput (fills the vector units)"), "throughput");
  variant_->addItem(tr("paper (one task per worker)"), "paper");
  variant_->setToolTip(tr("Which kernel variant; views label curves with it"));
  ceilings_->setObjectName("ceilingsLabel");
  measure_ceilings_->setToolTip(
      tr("Measure this CPU's empirical ceilings now (~5 s): the rotation kernel's instruction "
         "mix and plain FMA with enough independent chains, and the memory bandwidth. Stored "
         "per host and in the workspace (peak table, roofline)"));
  stop_->setEnabled(false);
  run_->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_R));
  run_->setToolTip(tr("Start the sweep (Ctrl+R); every output is checked against the closed form"));
  stop_->setToolTip(tr("Stop after the current chunk; completed points are kept"));
  progress_->setRange(0, 1000);
  progress_->setValue(0);

  energy_->setColumnCount(kEnergyColumns);
  energy_->setHorizontalHeaderLabels({tr("D"), tr("W"), tr("GFLOPS"), tr("Mean W"), tr("J (point)"), tr("J per run"),
                                      tr("GFLOPS/W"), tr("n samples")});
  energy_->verticalHeader()->hide();
  energy_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  energy_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  energy_->setVisible(false);

  auto* form = new QFormLayout;
  form_ = form;
  form->addRow(tr("Target"), target_);
  form->addRow(tr("Backend"), backend_);
  form->addRow(QString(), details_);
  auto* ceiling_row = new QHBoxLayout;
  ceiling_row_ = ceiling_row;
  ceiling_row->addWidget(ceilings_, 1);
  ceiling_row->addWidget(measure_ceilings_, 0, Qt::AlignTop);
  form->addRow(tr("Ceilings"), ceiling_row);
  form->addRow(tr("Variant"), variant_);
  form->addRow(tr("Workers"), workers_);
  form->addRow(tr("D"), dims_);
  form->addRow(tr("N"), iterations_);
  form->addRow(tr("Repeats"), repeats_);
  input_error_->setWordWrap(true);
  input_error_->setStyleSheet(QStringLiteral("color: #b00020;"));
  input_error_->hide();
  form->addRow(QString(), input_error_);
  form->addRow(tr("Record power"), power_);
  robot_power_->setObjectName("robotPower");
  robot_power_->setToolTip(
      tr("The robot records its own power sensors during the sweep (run flops --power auto): "
         "readings stream to the desk, and the trace comes home with the runs"));
  form->addRow(tr("Record power"), robot_power_);
  several_->setObjectName("severalRobots");
  several_->setToolTip(
      tr("Run this sweep on several robots, one after another; each robot's results appear as "
         "they arrive"));
  remote_log_->setObjectName("remoteLog");
  remote_log_->hide();
  auto* buttons = new QHBoxLayout;
  buttons->addWidget(run_);
  buttons->addWidget(stop_);
  buttons->addWidget(several_);
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(form);
  layout->addLayout(buttons);
  layout->addWidget(progress_);
  layout->addWidget(remote_log_);
  layout->addWidget(energy_, 1);
  layout->addStretch(0);

  connect(run_, &QPushButton::clicked, this, &KernelRunner::start);
  connect(workers_, &QLineEdit::textChanged, this, &KernelRunner::validate_inputs);
  connect(dims_, &QLineEdit::textChanged, this, &KernelRunner::validate_inputs);
  connect(measure_ceilings_, &QPushButton::clicked, this, &KernelRunner::measure_ceilings);
  connect(stop_, &QPushButton::clicked, this, &KernelRunner::cancel);
  // Device and variant names can be long ("OpenCL: pthread-Intel(R) Xeon(R) Platinum …"): the open list shows them
  // whole, the closed boxes do not set the dock's (and so the window's) minimum width.
  for (QComboBox* box : {backend_, variant_}) {
    box->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    box->setMinimumContentsLength(16);
  }
  connect(backend_, &QComboBox::currentIndexChanged, this, &KernelRunner::show_backend_details);
  connect(target_, &RobotTarget::changed, this, &KernelRunner::on_target_changed);
  connect(several_, &QPushButton::clicked, this, &KernelRunner::choose_robots);
  connect(controller_, &RunHereOrRobot::busy_changed, this, &KernelRunner::busy_changed);
  connect(controller_, &RunHereOrRobot::progress, this, &KernelRunner::relay_progress);
  connect(controller_, &RunHereOrRobot::here_finished, this, &KernelRunner::here_finished);
  connect(controller_, &RunHereOrRobot::robot_started, this, &KernelRunner::robot_started);
  connect(controller_, &RunHereOrRobot::robot_finished, this, &KernelRunner::robot_finished);
  connect(controller_, &RunHereOrRobot::robot_text, this,
          [this](const QString& line) { remote_log_->setText(QStringLiteral("%1: %2").arg(robot_name_, line)); });
  connect(controller_, &RunHereOrRobot::failed, this, &KernelRunner::run_failed);
  populate();
  restore_parameters();
  on_target_changed();
}

// The sweep's parameters are remembered from the last sweep started (QSettings), so a restart does not reset them.
void KernelRunner::restore_parameters() {
  QSettings s;
  s.beginGroup(QStringLiteral("kernel-runner"));
  if (const QString w = s.value("workers").toString(); !w.isEmpty()) workers_->setText(w);
  if (const QString d = s.value("dims").toString(); !d.isEmpty()) dims_->setText(d);
  if (const int n = s.value("iterations", 0).toInt(); n >= iterations_->minimum() && n <= iterations_->maximum())
    iterations_->setValue(n);
  if (const int r = s.value("repeats", 0).toInt(); r >= repeats_->minimum() && r <= repeats_->maximum())
    repeats_->setValue(r);
  if (const int v = variant_->findData(s.value("variant").toString()); v >= 0) variant_->setCurrentIndex(v);
  if (const int b = backend_->findText(s.value("backend").toString()); b >= 0) backend_->setCurrentIndex(b);
}

void KernelRunner::save_parameters() const {
  QSettings s;
  s.beginGroup(QStringLiteral("kernel-runner"));
  s.setValue("workers", workers_->text());
  s.setValue("dims", dims_->text());
  s.setValue("iterations", iterations_->value());
  s.setValue("repeats", repeats_->value());
  s.setValue("variant", variant_->currentData().toString());
  s.setValue("backend", backend_->currentText());
}

KernelRunner::~KernelRunner() {
  delete controller_;  // cancels and waits for a sweep here, or drops the robot's connection, before the panel goes
  if (ceiling_cancel_) ceiling_cancel_->cancel();
  QThreadPool::globalInstance()->waitForDone();  // the ceilings' thread refers to our backends
}

bool KernelRunner::running() const { return on_robots_ || controller_->running(); }

void KernelRunner::populate() {
  cpu_ = kernels::detect_cpu();  // ~0.1 s clock calibration, once
  backends_ = kernels::available_backends(cpu_);
  ceiling_set_ = kernels::cached_ceilings(cpu_);  // measured earlier on this host: no re-measuring on every start
  device_ceilings_.clear();
  for (const auto& b : backends_)
    if (auto set = kernels::cached_device_ceilings(b)) device_ceilings_[b.id] = std::move(*set);
  fill_backends();
}

void KernelRunner::fill_backends() {
  const bool robot = target_->is_robot();
  {
    const QSignalBlocker block(backend_);
    backend_->clear();
    robot_backend_ids_.clear();
    if (robot) {
      if (const auto& check = target_->check(); check && check->ok)
        for (const remote::RobotBackend& b : check->info.backends) {
          backend_->addItem(
              QStringLiteral("%1 — %2").arg(QString::fromStdString(b.label), QString::fromStdString(b.device)));
          robot_backend_ids_.push_back(b.id);
        }
    } else {
      for (const auto& b : backends_)
        backend_->addItem(
            QStringLiteral("%1 — %2").arg(QString::fromStdString(b.label), QString::fromStdString(b.device_name)));
    }
  }
  show_backend_details();
}

void KernelRunner::on_target_changed() {
  const bool robot = target_->is_robot();
  form_->setRowVisible(ceiling_row_, !robot);
  form_->setRowVisible(power_, !robot);
  form_->setRowVisible(robot_power_, robot);
  fill_backends();
  if (robot && backend_->count() == 0)
    details_->setText(target_->checking()
                          ? tr("<small>The robot's backends come with its check…</small>")
                          : tr("<small>No backend: the robot's check did not succeed (above).</small>"));
  validate_inputs();
}

void KernelRunner::show_backend_details() {
  const int i = backend_->currentIndex();
  if (i < 0) return;
  if (target_->is_robot()) {
    const auto& check = target_->check();
    if (!check || static_cast<std::size_t>(i) >= check->info.backends.size()) return;
    const remote::RobotBackend& b = check->info.backends[static_cast<std::size_t>(i)];
    details_->setText(tr("<small>on %1: %2 (%3)<br>theoretical peak %4</small>")
                          .arg(QString::fromStdString(check->info.hostname).toHtmlEscaped(),
                               QString::fromStdString(b.id).toHtmlEscaped(), QString::fromStdString(b.kind),
                               QString::fromStdString(format_si(b.theoretical_peak_flops, "FLOPS"))));
    return;
  }
  const auto& b = backends_[static_cast<std::size_t>(i)];
  details_->setText(QStringLiteral("<small>%1<br>theoretical peak %2</small>")
                        .arg(QString::fromStdString(b.details).toHtmlEscaped(),
                             QString::fromStdString(format_si(b.theoretical_peak_flops, "FLOPS"))));
  show_ceilings();
}

void KernelRunner::select_backend(const QString& id) {
  for (std::size_t i = 0; i < backends_.size(); ++i)
    if (QString::fromStdString(backends_[i].id) == id) backend_->setCurrentIndex(static_cast<int>(i));
}

const kernels::Backend* KernelRunner::current_backend() const {
  if (target_->is_robot()) return nullptr;  // the box lists the robot's backends
  const int i = backend_->currentIndex();
  return i >= 0 && static_cast<std::size_t>(i) < backends_.size() ? &backends_[static_cast<std::size_t>(i)] : nullptr;
}

const kernels::CeilingSet* KernelRunner::device_ceilings(const std::string& backend_id) const {
  const auto it = device_ceilings_.find(backend_id);
  return it == device_ceilings_.end() ? nullptr : &it->second;
}

void KernelRunner::show_ceilings(const std::vector<FlopsRun>& last_runs) {
  const kernels::Backend* b = current_backend();
  const bool simd = b && b->id == "cpu-simd", device = b && b->ceiling_kernels;
  measure_ceilings_->setVisible(simd || device);
  measure_ceilings_->setEnabled(!measuring_ceilings());
  measure_ceilings_->setToolTip(
      device ? tr("Measure this device's empirical ceilings now (a few seconds): FMA, the rotation kernel's "
                  "instruction mix and a device-memory copy, timed on the device, each result checked. Stored per "
                  "host and in the workspace (peak table, roofline)")
             : tr("Measure this CPU's empirical ceilings now (~5 s): the rotation kernel's instruction "
                  "mix and plain FMA with enough independent chains, and the memory bandwidth. Stored "
                  "per host and in the workspace (peak table, roofline)"));
  if (!simd && !device) {
    ceilings_->setText(tr("<small>Empirical ceilings are measured for the CPU SIMD backend and for OpenCL and "
                          "CUDA devices, not for %1.</small>")
                           .arg(QString::fromStdString(b ? b->label : std::string()).toHtmlEscaped()));
    ceilings_->setToolTip({});
    return;
  }
  const kernels::CeilingSet* set = simd ? (ceiling_set_ ? &*ceiling_set_ : nullptr) : device_ceilings(b->id);
  if (!set || !set->rotation_mix.measured()) {
    ceilings_->setText(simd ? tr("<small>No empirical ceiling measured for %1 with %2 threads yet: "
                                 "“% of peak” rests on the computed model alone.</small>")
                                  .arg(QString::fromStdString(cpu_.simd.name))
                                  .arg(cpu_.threads)
                            : tr("<small>No empirical ceiling measured for this device yet: "
                                 "“% of peak” rests on the computed model alone.</small>"));
    ceilings_->setToolTip({});
    return;
  }
  const kernels::CeilingSet& c = *set;
  const Summary mix = summarize(c.rotation_mix.values);
  const auto own = compare_to_ceilings(mix.mean, c.computed_peak_flops, std::nullopt, "The rotation-mix ceiling");
  QString text =
      tr("<small>rotation mix %1 ± %2 (n = %3) = %4 of the computed peak")
          .arg(QString::fromStdString(format_si(mix.mean, "FLOPS")), QString::fromStdString(format_si(mix.sd, "FLOPS")))
          .arg(mix.n)
          .arg(QString::fromStdString(fraction_text(own.fraction_of_peak, !own.flags.empty())));
  if (c.fma.measured())
    text += tr("; FMA %1").arg(QString::fromStdString(format_si(summarize(c.fma.values).mean, "FLOPS")));
  if (c.bandwidth.measured())
    text += (device ? tr("; device memory %1") : tr("; memory %1"))
                .arg(QString::fromStdString(format_si(summarize(c.bandwidth.values).mean, "B/s")));
  text += device ? tr("<br>measured %1, timed on the device").arg(QString::fromStdString(c.date))
                 : tr("<br>measured %1").arg(QString::fromStdString(c.date));
  std::vector<PlausibilityFlag> flags = own.flags;
  // The last sweep's peak against both: the Kernel Runner's own "% of peak" and "% of empirical ceiling".
  double best = 0;
  for (const FlopsRun& r : last_runs)
    if (const auto p = find_peak(r)) best = std::max(best, p->flops);
  if (best > 0) {
    const auto cmp = compare_to_ceilings(best, simd ? cpu_.peak_flops : b->theoretical_peak_flops, mix.mean,
                                         "The last sweep's peak", "rotation mix, measured " + c.date);
    text += tr("<br>last sweep: peak %1 = %2 of the computed peak, %3 of the empirical ceiling")
                .arg(QString::fromStdString(format_si(best, "FLOPS")),
                     QString::fromStdString(fraction_text(cmp.fraction_of_peak, !cmp.flags.empty())),
                     QString::fromStdString(fraction_text(cmp.fraction_of_ceiling, !cmp.flags.empty())));
    merge_flags(flags, cmp.flags);
  }
  ceilings_->setText(text + QStringLiteral("</small>"));
  ceilings_->setToolTip(QString::fromStdString((flags.empty() ? std::string() : flags_text(flags) + "\n\n") +
                                               c.rotation_mix.how + "\n" + c.fma.how +
                                               (c.bandwidth.measured() ? "\n" + c.bandwidth.how : std::string())));
}

void KernelRunner::measure_ceilings() {
  if (measuring_ceilings()) return;
  const kernels::Backend* current = current_backend();
  if (!current || (current->id != "cpu-simd" && !current->ceiling_kernels)) return;
  ceiling_cancel_ = std::make_shared<CancelToken>();
  measure_ceilings_->setEnabled(false);
  ceilings_->setText(tr("<small>Measuring the empirical ceilings…</small>"));
  auto cancel = ceiling_cancel_;
  const kernels::CpuInfo cpu = cpu_;
  const bool device = current->id != "cpu-simd";
  const kernels::Backend backend = *current;  // the closures share the device; the copy outlives a repopulate
  auto* watcher = new QFutureWatcher<kernels::CeilingSet>(this);
  connect(watcher, &QFutureWatcher<kernels::CeilingSet>::finished, this, [this, watcher, device, id = backend.id] {
    watcher->deleteLater();
    ceiling_cancel_.reset();
    try {
      const kernels::CeilingSet set = watcher->result();
      if (device)
        device_ceilings_[id] = set;
      else
        ceiling_set_ = set;
      try {
        kernels::store_ceilings(set);
      } catch (const std::runtime_error& e) {
        emit failed(tr("Ceilings measured but not cached: %1").arg(QString::fromUtf8(e.what())));
      }
      emit ceilings_measured(kernels::ceiling_result_set(set));
    } catch (const std::exception& e) {
      emit failed(tr("Measuring the ceilings: %1").arg(QString::fromUtf8(e.what())));
    }
    show_ceilings();
  });
  watcher->setFuture(QtConcurrent::run([cpu, cancel, device, backend] {
    return device ? kernels::measure_device_ceilings(backend, {}, *cancel)
                  : kernels::measure_ceilings(cpu, {}, *cancel);
  }));
}

std::optional<PowerTrace> KernelRunner::take_power_trace() {
  auto t = std::move(trace_);
  trace_.reset();
  return t;
}

void KernelRunner::show_energies(const std::vector<FlopsRun>& runs) {
  const std::vector<PointEnergy> points = trace_ ? sweep_point_energies(*trace_, runs) : std::vector<PointEnergy>{};
  energy_->setVisible(trace_.has_value());
  energy_->setRowCount(static_cast<int>(points.size()));
  for (std::size_t r = 0; r < points.size(); ++r) {
    const PointEnergy& p = points[r];
    // The numbers as `run flops --power` prints them and the Power tab's Phases table shows the point's phase.
    const QString texts[] = {QString::number(p.dims),
                             QString::number(p.workers),
                             QString::number(p.gflops, 'f', 3),
                             QString::number(p.mean_power_w, 'f', 4),
                             QString::number(p.energy_j, 'f', 4),
                             QString::number(p.joules_per_run, 'f', 4),
                             QString::number(p.gflops_per_watt, 'f', 3),
                             QString::number(p.samples) + QString::fromStdString(short_point_mark(p.samples))};
    for (int c = 0; c < kEnergyColumns; ++c) {
      auto* item = new QTableWidgetItem(texts[c]);
      item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
      item->setToolTip(
          p.too_short() ? tr("The sensor sampled this point %n time(s), fewer than %1: its energy leans "
                             "on interpolation between samples outside it",
                             nullptr, static_cast<int>(p.samples))
                              .arg(kMinSamplesPerPoint)
                        : tr("%n timed run(s) over %1 s", nullptr, static_cast<int>(p.runs)).arg(p.seconds, 0, 'f', 3));
      if (p.too_short()) item->setBackground(QColor(0xff, 0xe0, 0xb2));
      energy_->setItem(static_cast<int>(r), c, item);
    }
  }
  if (trace_)
    energy_->setToolTip(tr("Energy per sweep point, %1: %2")
                            .arg(QString::fromUtf8(to_string(trace_->provenance.measurement).data()),
                                 QString::fromStdString(trace_->provenance.sensor)));
}

void KernelRunner::set_workers_spec(const QString& spec) { workers_->setText(spec); }
QString KernelRunner::workers_spec() const { return workers_->text(); }

namespace {
// The parser's reason for `text`, or empty when it parses.
template <class Parse>
QString parse_error(const QLineEdit* field, Parse parse) {
  try {
    parse(field->text().toStdString());
    return {};
  } catch (const std::invalid_argument& e) {
    return QString::fromUtf8(e.what());
  }
}
}  // namespace

QString KernelRunner::input_error() const {
  if (const QString why = parse_error(workers_, [](std::string_view t) { return kernels::parse_worker_spec(t); });
      !why.isEmpty())
    return tr("Workers: %1").arg(why);
  if (const QString why = parse_error(dims_, [](std::string_view t) { return kernels::parse_dims_list(t); });
      !why.isEmpty())
    return tr("D: %1").arg(why);
  return {};
}

void KernelRunner::validate_inputs() {
  const QString workers_why = parse_error(workers_, [](std::string_view t) { return kernels::parse_worker_spec(t); });
  const QString dims_why = parse_error(dims_, [](std::string_view t) { return kernels::parse_dims_list(t); });
  for (auto [field, why] : {std::pair{workers_, workers_why}, std::pair{dims_, dims_why}}) {
    // Red field, the reason in its tooltip and under the form, so the user sees which field and why while typing.
    field->setStyleSheet(why.isEmpty() ? QString() : QStringLiteral("QLineEdit { background: #ffd7d7; }"));
    field->setProperty("invalid", !why.isEmpty());
  }
  const QString why = input_error();
  input_error_->setText(why);
  input_error_->setVisible(!why.isEmpty());
  const bool robot_ready = !target_->is_robot() || (target_->check() && target_->check()->ok && backend_->count() > 0);
  run_->setEnabled(why.isEmpty() && !running() && robot_ready);
  several_->setEnabled(why.isEmpty() && !running() && !target_->robots().empty());
}
void KernelRunner::set_dims(const QString& dims) { dims_->setText(dims); }
void KernelRunner::set_iterations(int n) { iterations_->setValue(n); }
void KernelRunner::set_repeats(int r) { repeats_->setValue(r); }

void KernelRunner::start() {
  if (running() || backend_->currentIndex() < 0) return;
  if (target_->is_robot()) {
    const auto i = static_cast<std::size_t>(backend_->currentIndex());
    if (i >= robot_backend_ids_.size()) return;
    remote_backend_ = QString::fromStdString(robot_backend_ids_[i]);
    target_->remember_platform();
    start_on_robots({{target_->robot_name(), target_->platform()}});
    return;
  }
  kernels::SweepSpec spec;
  try {
    spec.workers = kernels::parse_worker_spec(workers_->text().toStdString());
    spec.dims = kernels::parse_dims_list(dims_->text().toStdString());
  } catch (const std::invalid_argument&) {
    emit failed(input_error());  // names the field; Run is disabled while a field is invalid, so rarely reached
    return;
  }
  spec.iterations = iterations_->value();
  spec.repeats = repeats_->value();
  spec.variant = variant_->currentData().toString() == "paper" ? kernels::Variant::Paper : kernels::Variant::Throughput;
  const kernels::Backend backend = backends_[static_cast<std::size_t>(backend_->currentIndex())];
  trace_.reset();
  recorder_.reset();
  try {
    recorder_ = power_->start_recorder();  // null when "Record power" is off
  } catch (const std::exception& e) {
    emit failed(tr("Record power: %1").arg(QString::fromUtf8(e.what())));
    return;
  }
  // Each point lasts long enough for the sensor to sample it kMinSamplesPerPoint times (issue #32.4).
  if (recorder_) spec.min_point_s = min_point_seconds(recorder_->interval_s());
  save_parameters();
  sweep_ = std::make_shared<std::optional<kernels::SweepResult>>();
  const kernels::CpuInfo cpu = cpu_;
  QPointer<KernelRunner> self(this);
  // The recorder's phase calls are thread-safe: the sweep thread marks each D's warm-up and each point.
  const bool started_here =
      controller_->start_here([backend, cpu, spec, self, rec = recorder_, output = sweep_](const CancelToken& token) {
        double last_end = rec ? rec->now_s() : 0;
        int current_d = -1;
        *output = kernels::run_sweep(
            backend, cpu, spec, token,
            [&token, rec, &last_end, &current_d, warmup = spec.warmup](double f, std::string_view step) {
              if (step == "cancelled") return;  // the sweep's last report: the bar stays where the sweep stopped
              token.report(f, step);
              const auto comma = step.find(", D=");
              if (!rec || !step.starts_with("W=") || comma == std::string_view::npos) return;
              const long long w = std::stoll(std::string(step.substr(2, comma - 2)));
              const int d = std::stoi(std::string(step.substr(comma + 4)));
              if (d != current_d) {
                current_d = d;
                if (warmup) rec->add_phase(sweep_warmup_phase(d), last_end, rec->now_s());
              }
              rec->begin_phase(sweep_point_phase(w, d));
            },
            [self, rec, &last_end](const FlopsRun& run) {
              if (rec) {
                rec->end_phase();
                last_end = rec->now_s();
              }
              QMetaObject::invokeMethod(
                  self.data(),
                  [self, run] {
                    if (self) emit self->live_run(run);
                  },
                  Qt::QueuedConnection);
            });
      });
  if (!started_here) {
    recorder_.reset();  // said through `failed`
    return;
  }
  progress_->setValue(0);
  progress_->setFormat(QStringLiteral("%p %"));
  emit started();
}

void KernelRunner::cancel() {
  remote_queue_.clear();  // the robots not started yet are not started
  controller_->cancel();
}

void KernelRunner::choose_robots() {
  if (running()) return;
  QString backend = remote_backend_;
  if (target_->is_robot() && backend_->currentIndex() >= 0 &&
      static_cast<std::size_t>(backend_->currentIndex()) < robot_backend_ids_.size())
    backend = QString::fromStdString(robot_backend_ids_[static_cast<std::size_t>(backend_->currentIndex())]);
  RobotQueueDialog dialog(target_->robots(), backend, this);
  if (dialog.exec() != QDialog::Accepted || dialog.chosen().empty()) return;
  remote_backend_ = dialog.backend();
  start_on_robots(dialog.chosen());
}

void KernelRunner::start_on_robots(const std::vector<std::pair<QString, QString>>& robots) {
  if (running() || robots.empty()) return;
  if (const QString why = input_error(); !why.isEmpty()) {
    emit failed(why);
    return;
  }
  commands::RunFlopsSettings settings;
  settings.backend = (remote_backend_.isEmpty() ? QStringLiteral("cpu") : remote_backend_).toStdString();
  settings.variant = variant_->currentData().toString().toStdString();
  settings.workers = workers_->text().trimmed().toStdString();
  settings.points = dims_->text().trimmed().toStdString();
  settings.iterations = iterations_->value();
  settings.repeats = repeats_->value();
  if (robot_power_->isChecked()) settings.power.sensor = "auto";  // the robot's own sensors
  remote_command_ = commands::to_words(settings);
  save_parameters();
  remote_queue_.assign(robots.begin(), robots.end());
  remote_total_ = static_cast<int>(robots.size());
  remote_failures_.clear();
  trace_.reset();
  energy_->setVisible(false);
  on_robots_ = true;
  emit started();
  remote_log_->clear();
  remote_log_->show();
  start_remote_next();
}

void KernelRunner::start_remote_next() {
  if (remote_queue_.empty()) {
    finish_remote();
    return;
  }
  const auto [name, platform] = remote_queue_.front();
  remote_queue_.pop_front();
  const int index = remote_total_ - static_cast<int>(remote_queue_.size());
  remote::SshTarget t;
  t.destination = name.toStdString();
  for (const remote::Robot& r : target_->robots())
    if (r.name == t.destination) t = r.target();
  robot_name_ = name;
  robot_platform_ = platform;
  robot_who_ = remote_total_ > 1 ? tr("%1 (%2 of %3)").arg(name).arg(index).arg(remote_total_) : name;
  last_power_.clear();
  progress_->setValue(0);
  progress_->setFormat(tr("%1: checking…").arg(robot_who_));
  if (!controller_->start_on(t, platform, remote_command_)) start_remote_next();  // said through `failed`
}

void KernelRunner::robot_started(RemoteRun* run) {
  connect(run, &RemoteRun::power, this, [this](double watts, const QString& channel) {
    last_power_ = QStringLiteral(" · %1 %2").arg(QString::fromStdString(format_si(watts, "W")), channel);
  });
  // Drawn under the platform name it will be stored with.
  connect(run, &RemoteRun::live_run, this, [this, platform = robot_platform_.toStdString()](const FlopsRun& r) {
    FlopsRun shown = r;
    shown.platform = platform;
    emit live_run(shown);
  });
}

void KernelRunner::robot_finished(RemoteRun* run, const QString& platform) {
  const bool cancelled = run->job().status == "cancelled";
  progress_->setFormat(cancelled ? tr("%1: cancelled at %p %").arg(robot_who_) : tr("%1: done").arg(robot_who_));
  if (!cancelled) progress_->setValue(1000);
  emit remote_finished(run, platform);
}

void KernelRunner::relay_progress(double fraction, const QString& step) {
  progress_->setValue(static_cast<int>(fraction * 1000));
  if (on_robots_) progress_->setFormat(QStringLiteral("%1: %p % %2%3").arg(robot_who_, step, last_power_));
}

void KernelRunner::run_failed(const QString& message) {
  if (!on_robots_) {
    if (recorder_) recorder_.reset();  // the sweep failed: its power recording stops with it, unused
    emit failed(message);
    return;
  }
  remote_failures_ << message;  // "robot: why" (the controller names the robot)
  remote_log_->setText(message);
}

void KernelRunner::busy_changed(bool busy) {
  if (busy) {
    run_->setEnabled(false);
    several_->setEnabled(false);
    stop_->setEnabled(true);
    return;
  }
  // Between the robots of a queue the controller is idle for a moment: the next one starts now.
  if (on_robots_) {
    start_remote_next();
    return;
  }
  stop_->setEnabled(false);
  validate_inputs();  // Run comes back only if the fields still parse
}

void KernelRunner::here_finished() {
  // run_sweep keeps what it completed when cancelled; with nothing (cancelled before it began) there is nothing.
  const kernels::SweepResult result = sweep_ && *sweep_ ? std::move(**sweep_) : kernels::SweepResult{{}, true};
  sweep_.reset();
  // A cancelled sweep keeps the bar where it stopped (issue #32.8), saying so; a finished one fills it.
  if (result.cancelled)
    progress_->setFormat(tr("cancelled at %p %"));
  else
    progress_->setValue(1000);
  if (recorder_) {
    const FlopsRun* first = result.runs.empty() ? nullptr : &result.runs.front();
    trace_ =
        recorder_->finish("Kernel Runner " + (first ? first->backend + " " + first->provenance.date : std::string()));
    if (first) trace_->platform = first->platform;  // paired with the run's platform in every view
    recorder_.reset();
  }
  show_energies(result.runs);
  show_ceilings(result.runs);
  emit finished(result.runs, result.cancelled);
}

void KernelRunner::finish_remote() {
  on_robots_ = false;
  stop_->setEnabled(false);
  validate_inputs();
  if (!remote_failures_.isEmpty()) emit failed(remote_failures_.join(QStringLiteral("\n\n")));
  remote_failures_.clear();
}

}  // namespace bs::ui
