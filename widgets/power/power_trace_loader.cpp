// SPDX-License-Identifier: GPL-3.0-or-later
#include "power/power_trace_loader.h"

#include "store/log_settings_store.h"

#include <QFutureWatcher>
#include <QHBoxLayout>
#include <QLabel>
#include <QPointer>
#include <QProgressBar>
#include <QToolButton>
#include <QtConcurrent>
#include <atomic>

namespace bs::ui {

namespace {

struct LoadResult {
  std::vector<StoredPowerTrace> traces;
  QString error;  // empty on success
  bool cancelled = false;
};

QString samples_text(std::size_t n) {
  return n >= 1'000'000 ? QObject::tr("%1 M samples").arg(static_cast<double>(n) / 1e6, 0, 'f', 1)
                        : QObject::tr("%1 samples").arg(n);
}

}  // namespace

PowerTraceLoader::PowerTraceLoader(QWidget* parent) : QWidget(parent) {
  auto* row = new QHBoxLayout(this);
  row->setContentsMargins(0, 0, 0, 0);
  text_ = new QLabel(this);
  bar_ = new QProgressBar(this);
  bar_->setRange(0, 1000);
  bar_->setMaximumWidth(180);
  bar_->setFormat("%p %");
  cancel_button_ = new QToolButton(this);
  cancel_button_->setText(tr("Cancel"));
  cancel_button_->setToolTip(tr("Stop loading the power logs' samples; their summaries stay shown"));
  row->addWidget(text_);
  row->addWidget(bar_);
  row->addWidget(cancel_button_);
  connect(cancel_button_, &QToolButton::clicked, this, &PowerTraceLoader::cancel);
  hide();
}

PowerTraceLoader::~PowerTraceLoader() {
  if (cancel_) cancel_->cancel();
  // The worker holds only its own copies and connection; QThreadPool's global instance waits for it at exit.
}

std::size_t PowerTraceLoader::sample_count(const std::vector<StoredPowerTrace>& traces) {
  std::size_t n = 0;
  for (const StoredPowerTrace& t : traces)
    if (!t.samples_loaded) n += t.summary.samples * (1 + t.trace.channels.size());
  return n;
}

void PowerTraceLoader::load_now(const Workspace& ws, std::vector<StoredPowerTrace>& traces, const CancelToken* cancel) {
  for (StoredPowerTrace& t : traces) ws.load_power_samples(t, cancel);
  apply_voltage_sources(ws, traces);  // a current-only log's voltage borrowed from another log (issue #32.2)
}

void PowerTraceLoader::cancel() {
  if (cancel_) cancel_->cancel();
}

void PowerTraceLoader::abandon() {
  cancel();
  cancel_.reset();
  ++generation_;
  hide();
}

void PowerTraceLoader::start(const std::string& path, std::vector<StoredPowerTrace> traces) {
  abandon();
  const int generation = ++generation_;
  auto token = std::make_shared<CancelToken>();
  cancel_ = token;
  const std::size_t total = sample_count(traces);
  text_->setText(tr("Loading power logs (%1)…").arg(samples_text(total)));
  bar_->setValue(0);
  show();
  // Progress is reported per 2 MiB chunk; one queued update per thousandth is enough for the bar.
  QPointer<QProgressBar> bar(bar_);
  auto last = std::make_shared<std::atomic<int>>(-1);
  std::vector<std::size_t> weights;
  for (const StoredPowerTrace& t : traces) weights.push_back(t.summary.samples * (1 + t.trace.channels.size()));
  auto done_before = std::make_shared<std::atomic<std::size_t>>(0);
  auto current = std::make_shared<std::atomic<std::size_t>>(0);
  token->set_progress([bar, last, done_before, current, total](double fraction, std::string_view) {
    const double all = total == 0 ? 1.0
                                  : (static_cast<double>(*done_before) + fraction * static_cast<double>(*current)) /
                                        static_cast<double>(total);
    const int permille = static_cast<int>(std::clamp(all, 0.0, 1.0) * 1000);
    if (last->exchange(permille) == permille) return;
    QMetaObject::invokeMethod(
        bar.data(),
        [bar, permille] {
          if (bar) bar->setValue(permille);
        },
        Qt::QueuedConnection);
  });
  auto* watcher = new QFutureWatcher<LoadResult>(this);
  connect(watcher, &QFutureWatcher<LoadResult>::finished, this, [this, watcher, generation] {
    LoadResult r = watcher->future().takeResult();  // moved out: a long log is not copied on its way to the views
    watcher->deleteLater();
    if (generation != generation_) return;  // superseded by a newer load (another workspace, a reload)
    cancel_.reset();
    hide();
    if (r.error.isEmpty())
      emit loaded(share_traces(std::move(r.traces)));
    else
      emit failed(r.error);
  });
  watcher->setFuture(
      QtConcurrent::run([path, traces = std::move(traces), token, weights, done_before, current]() mutable {
        LoadResult r;
        try {
          // SQLite connections are per thread. Read-only: this second connection of the GUI's only reads, and never
          // checkpoints on closing (store/sqlite_db.cpp).
          const Workspace ws(path, Workspace::OpenMode::ReadOnly);
          for (std::size_t i = 0; i < traces.size(); ++i) {
            *current = weights[i];
            ws.load_power_samples(traces[i], token.get());
            *done_before += weights[i];
          }
          apply_voltage_sources(ws, traces);
          r.traces = std::move(traces);
        } catch (const Cancelled&) {
          r.cancelled = true;
          r.error = QObject::tr(
              "Loading the power logs was cancelled; the Power, Efficiency, Battery and Platforms "
              "tabs show no power data until the workspace is opened again");
        } catch (const std::exception& e) {
          r.error = QObject::tr("Could not load the power logs' samples: %1").arg(QString::fromUtf8(e.what()));
        }
        return r;
      }));
}

}  // namespace bs::ui
