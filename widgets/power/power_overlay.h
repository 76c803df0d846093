// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The Power tab's overlay controls: per trace whether it is shown and its time offset (s) on the shared axis,
// typed, or set for all traces at once so that a chosen phase or marker starts at 0 s on every trace
// (analysis/trace_align.h). Traces from different files and platforms then lie over each other, and the
// selection and phase tables give their statistics side by side.
#include <QWidget>
#include <string>
#include <vector>

#include "model/power_trace.h"

class QComboBox;
class QPushButton;
class QTableWidget;

namespace bs::ui {

class PowerOverlayPanel : public QWidget {
  Q_OBJECT
 public:
  explicit PowerOverlayPanel(QWidget* parent = nullptr);
  // One row per trace: its name and phases (for alignment). Offsets reset to 0, every trace shown.
  void set_traces(const std::vector<QString>& names, std::vector<std::vector<TracePhase>> phases);
  // New phases to align at (detected ones added or removed), offsets and visibility kept.
  void set_phases(std::vector<std::vector<TracePhase>> phases);
  double offset(std::size_t trace) const { return trace < offsets_.size() ? offsets_[trace] : 0.0; }
  bool visible(std::size_t trace) const { return trace < visible_.size() ? visible_[trace] : true; }
  void set_offset(std::size_t trace, double seconds);  // emits changed()
  void set_visible(std::size_t trace, bool on);        // emits changed()
  // Offsets that put the first phase named `name` of each trace at 0 s; traces without it keep theirs. Returns
  // how many traces were aligned.
  int align_at(const std::string& name);
  QComboBox* phase_box() const { return phase_box_; }
  QTableWidget* table() const { return table_; }

 signals:
  void changed();

 private:
  void fill_table();
  QTableWidget* table_;
  QComboBox* phase_box_;
  QPushButton* align_;
  QPushButton* reset_;
  std::vector<double> offsets_;
  std::vector<bool> visible_;
  std::vector<std::vector<TracePhase>> phases_;
};

}  // namespace bs::ui
