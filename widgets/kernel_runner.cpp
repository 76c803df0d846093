// SPDX-License-Identifier: GPL-3.0-or-later
#include "kernel_runner.h"

#include <QComboBox>
#include <QFormLayout>
#include <QFutureWatcher>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QtConcurrent>

#include "analysis/units.h"
#include "kernels/sweep.h"
#include "kernels/worker_spec.h"

namespace bs::ui {

KernelRunner::KernelRunner(QWidget* parent)
    : QWidget(parent),
      backend_(new QComboBox(this)),
      variant_(new QComboBox(this)),
      workers_(new QLineEdit("1,2,4,8,16,32,64,128,256,512,1024", this)),
      dims_(new QLineEdit("1,2,4", this)),
      iterations_(new QSpinBox(this)),
      repeats_(new QSpinBox(this)),
      details_(new QLabel(this)),
      run_(new QPushButton(tr("Run"), this)),
      stop_(new QPushButton(tr("Cancel"), this)),
      progress_(new QProgressBar(this)) {
  qRegisterMetaType<bs::FlopsRun>();
  qRegisterMetaType<std::vector<bs::FlopsRun>>();
  iterations_->setRange(1, 100'000'000);
  iterations_->setValue(40000);
  iterations_->setGroupSeparatorShown(true);
  iterations_->setToolTip(tr("N: rotations per point (the paper uses 40,000)"));
  repeats_->setRange(1, 100);
  repeats_->setValue(3);
  repeats_->setToolTip(tr("Timings per point; the plot shows mean ± SD"));
  workers_->setToolTip(tr("Worker counts: 1,2,4,8 or start:stop:step such as 256:1024000:256 (paper GPUs) or "
                          "1:4096:32 (paper CPUs)"));
  dims_->setToolTip(tr("D values: 2D points per worker (paper: 1, 2, 4)"));
  variant_->addItem(tr("throughput (fills the vector units)"), "throughput");
  variant_->addItem(tr("paper (one task per worker)"), "paper");
  variant_->setToolTip(tr("Which kernel variant; views label curves with it"));
  details_->setWordWrap(true);
  details_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  stop_->setEnabled(false);
  run_->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_R));
  run_->setToolTip(tr("Start the sweep (Ctrl+R); every output is checked against the closed form"));
  stop_->setToolTip(tr("Stop after the current chunk; completed points are kept"));
  progress_->setRange(0, 1000);
  progress_->setValue(0);

  auto* form = new QFormLayout;
  form->addRow(tr("Backend"), backend_);
  form->addRow(QString(), details_);
  form->addRow(tr("Variant"), variant_);
  form->addRow(tr("Workers"), workers_);
  form->addRow(tr("D"), dims_);
  form->addRow(tr("N"), iterations_);
  form->addRow(tr("Repeats"), repeats_);
  auto* buttons = new QHBoxLayout;
  buttons->addWidget(run_);
  buttons->addWidget(stop_);
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(form);
  layout->addLayout(buttons);
  layout->addWidget(progress_);
  layout->addStretch(1);

  connect(run_, &QPushButton::clicked, this, &KernelRunner::start);
  connect(stop_, &QPushButton::clicked, this, &KernelRunner::cancel);
  connect(backend_, &QComboBox::currentIndexChanged, this, &KernelRunner::show_backend_details);
  populate();
}

KernelRunner::~KernelRunner() {
  if (cancel_) cancel_->cancel();
  QThreadPool::globalInstance()->waitForDone();  // the sweep thread refers to our backends
}

void KernelRunner::populate() {
  cpu_ = kernels::detect_cpu();  // ~0.1 s clock calibration, once
  backends_ = kernels::available_backends(cpu_);
  backend_->clear();
  for (const auto& b : backends_)
    backend_->addItem(QStringLiteral("%1 — %2").arg(QString::fromStdString(b.label), QString::fromStdString(b.device_name)));
  show_backend_details();
}

void KernelRunner::show_backend_details() {
  const int i = backend_->currentIndex();
  if (i < 0) return;
  const auto& b = backends_[static_cast<std::size_t>(i)];
  details_->setText(QStringLiteral("<small>%1<br>theoretical peak %2</small>")
                        .arg(QString::fromStdString(b.details).toHtmlEscaped(),
                             QString::fromStdString(format_si(b.theoretical_peak_flops, "FLOPS"))));
}

void KernelRunner::set_workers_spec(const QString& spec) { workers_->setText(spec); }
void KernelRunner::set_dims(const QString& dims) { dims_->setText(dims); }
void KernelRunner::set_iterations(int n) { iterations_->setValue(n); }
void KernelRunner::set_repeats(int r) { repeats_->setValue(r); }

void KernelRunner::start() {
  if (running() || backend_->currentIndex() < 0) return;
  kernels::SweepSpec spec;
  try {
    spec.workers = kernels::parse_worker_spec(workers_->text().toStdString());
    spec.dims = kernels::parse_dims_list(dims_->text().toStdString());
  } catch (const std::invalid_argument& e) {
    emit failed(tr("Workers/D: %1").arg(QString::fromUtf8(e.what())));
    return;
  }
  spec.iterations = iterations_->value();
  spec.repeats = repeats_->value();
  spec.variant = variant_->currentData().toString() == "paper" ? kernels::Variant::Paper : kernels::Variant::Throughput;
  const kernels::Backend backend = backends_[static_cast<std::size_t>(backend_->currentIndex())];
  cancel_ = std::make_shared<CancelToken>();
  emit started();
  run_->setEnabled(false);
  stop_->setEnabled(true);
  progress_->setValue(0);
  auto cancel = cancel_;
  const kernels::CpuInfo cpu = cpu_;
  auto* watcher = new QFutureWatcher<kernels::SweepResult>(this);
  connect(watcher, &QFutureWatcher<kernels::SweepResult>::finished, this, [this, watcher] {
    watcher->deleteLater();
    cancel_.reset();
    run_->setEnabled(true);
    stop_->setEnabled(false);
    try {
      const kernels::SweepResult result = watcher->result();
      progress_->setValue(1000);
      emit finished(result.runs, result.cancelled);
    } catch (const std::exception& e) {
      emit failed(QString::fromUtf8(e.what()));
    }
  });
  QPointer<KernelRunner> self(this);
  watcher->setFuture(QtConcurrent::run([backend, cpu, spec, cancel, self] {
    return kernels::run_sweep(
        backend, cpu, spec, *cancel,
        [self](double f, std::string_view) {
          QMetaObject::invokeMethod(self.data(), [self, f] { if (self) self->progress_->setValue(static_cast<int>(f * 1000)); },
                                    Qt::QueuedConnection);
        },
        [self](const FlopsRun& run) {
          QMetaObject::invokeMethod(self.data(), [self, run] { if (self) emit self->live_run(run); }, Qt::QueuedConnection);
        });
  }));
}

void KernelRunner::cancel() {
  if (cancel_) cancel_->cancel();
}

}  // namespace bs::ui
