// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <QWidget>
#include <string>
#include <utility>
#include <vector>

#include "analysis/platform/platform_battery.h"
#include "power/shared_traces.h"
#include "store/battery_preset_store.h"

class QComboBox;
class QCustomPlot;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QTableWidget;

namespace bs {
class Workspace;
}

namespace bs::ui {

// Battery life per platform on a LiPo pack: the pack (a preset, built-in or saved in the workspace, with its
// voltage, capacity, usable depth of discharge, internal resistance), an extra parallel load (servos), the model
// (the paper's constant power, or a LiPo curve) and an optional mission profile; a table of runtimes and a plot of
// state of charge over time per platform with the pack voltage of the LiPo model. Every edit recomputes at once
// (analysis/platform_battery.h: a few thousand time steps per platform). Presets are saved into the workspace.
class BatteryView : public QWidget {
  Q_OBJECT
 public:
  explicit BatteryView(QWidget* parent = nullptr);
  // The workspace whose presets are listed and into which "Save preset" writes (may be null: built-ins only).
  // Called again with the same workspace (after an import or a run), it refreshes the preset list and keeps what
  // the fields show. A newly opened workspace brings back the setup last edited in it ("battery-tab/current").
  void set_workspace(Workspace* workspace);
  // The traces are shared with the other views (widgets/power/shared_traces.h), never copied.
  void set_data(SharedTraces traces, std::vector<std::pair<std::string, int>> colors = {});
  void set_data(std::vector<PowerTrace> traces, std::vector<std::pair<std::string, int>> colors = {});
  // The setup the fields show now.
  BatterySetup setup() const;
  // Loads a preset by name into the fields; false when there is none.
  bool select_preset(const QString& name);
  // Saves the fields as a workspace preset named `name`; false (with the reason shown) when it cannot.
  bool save_preset(const QString& name);

  const std::vector<PlatformBattery>& rows() const { return rows_; }
  QTableWidget* table() const { return table_; }
  QCustomPlot* plot() const { return plot_; }
  QComboBox* preset_box() const { return preset_; }
  QDoubleSpinBox* volts_box() const { return volts_; }
  QDoubleSpinBox* capacity_box() const { return capacity_; }
  QDoubleSpinBox* dod_box() const { return dod_; }
  QDoubleSpinBox* extra_load_box() const { return extra_; }
  QComboBox* model_box() const { return model_; }
  QLineEdit* mission_edit() const { return mission_; }
  QString error_text() const;
  QString left_out_text() const;  // the logs that give no power, and why (hidden when none)
  // Whether the fields differ from the selected preset (shown as "modified" in the preset box).
  bool modified() const;

 signals:
  // The setup changed: an edit, another preset, or a workspace that brought its own back.
  void setup_changed();
  // The user edited the setup and it was saved in the workspace (after setup_changed): never on opening.
  void setup_edited();

 private:
  void reload_presets(const QString& select, bool keep_fields = false);
  void show_setup(const BatterySetup& s);
  void show_fields(const BatterySetup& s);
  void restore_saved_setup();
  bool remember_setup();  // true when it wrote an edit into the workspace
  void mark_modified();
  void recompute();
  void fill_table();
  void fill_plot();
  void ask_save();
  void delete_preset();

  Workspace* workspace_ = nullptr;
  SharedTraces traces_ = share_traces(std::vector<PowerTrace>{});
  std::vector<std::pair<std::string, int>> colors_;
  std::vector<BatterySetup> presets_;
  BatterySetup base_;  // the selected preset: keeps what the fields do not show (description, curve, cut-off)
  std::vector<PlatformBattery> rows_;
  std::vector<QString> preset_texts_;  // the preset box's texts without the "modified" mark
  std::string remembered_;             // the setup JSON last written to the workspace
  bool restoring_ = false;             // a newly opened workspace's setup is being read back
  QComboBox* preset_;
  QDoubleSpinBox* volts_;
  QDoubleSpinBox* capacity_;
  QDoubleSpinBox* dod_;
  QDoubleSpinBox* extra_;
  QDoubleSpinBox* resistance_;
  QComboBox* model_;
  QLineEdit* mission_;
  QLabel* pack_label_;
  QLabel* error_;
  QLabel* left_out_ = nullptr;
  QPushButton* save_;
  QPushButton* delete_;
  QTableWidget* table_;
  QCustomPlot* plot_;
};

}  // namespace bs::ui
