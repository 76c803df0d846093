// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Which power log each platform's numbers come from (issue #43.4), above the Efficiency, Battery and Platforms tabs:
// "Power logs: NUC [nuc-second-session.csv ▾] · Jetson TX2: jetson-current.csv". A platform with several logs gets
// a choice ("Power log of NUC:"); picking another log asks for it to be stored (MainWindow keeps it in the workspace,
// one undo step, store/decision_store.h), and every view and the report then use it. The views use a platform's first
// log, so the logs come here in the order the views get them: each platform's chosen log first.
#include <QString>
#include <QWidget>
#include <cstdint>
#include <vector>

#include "model/power_trace.h"

namespace bs::ui {

class FlowLayout;

class LogChoiceBar : public QWidget {
  Q_OBJECT
 public:
  explicit LogChoiceBar(QWidget* parent = nullptr);
  // `ids[i]` is the workspace id of `traces[i]` (0: not stored: offered, but not choosable).
  void set_logs(const std::vector<PowerTrace>& traces, const std::vector<std::int64_t>& ids);
  QString text()
      const;  // what it says after "Power logs:", in one line ("NUC: a.csv (1 of 2 logs); Jetson TX2: b.csv")

 signals:
  void log_chosen(const QString& platform, qint64 trace_id);

 private:
  FlowLayout* flow_;
  QString text_;
};

}  // namespace bs::ui
