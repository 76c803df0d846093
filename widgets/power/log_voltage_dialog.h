// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// "Supply voltage…" on a power log (workspace tree, issue #32.2): how a current-only log gets its power. None,
// a typed supply voltage (the CLI's --supply-volts), or the voltage channel of another log of the workspace.
#include <QDialog>
#include <optional>
#include <vector>

#include "store/log_settings_store.h"

class QComboBox;
class QDoubleSpinBox;
class QRadioButton;

namespace bs::ui {

struct LogVoltageChoice {
  std::optional<double> supply_v;       // typed voltage, or none
  std::optional<VoltageSource> source;  // another log's voltage channel, or none
};

// Another log's voltage channel the user may borrow.
struct VoltageChannelOption {
  VoltageSource source;
  QString text;  // "bench supply — V_out (NUC)"
};

class LogVoltageDialog : public QDialog {
  Q_OBJECT
 public:
  LogVoltageDialog(const QString& log_label, const LogVoltageChoice& current,
                   std::vector<VoltageChannelOption> channels, QWidget* parent = nullptr);
  LogVoltageChoice choice() const;
  // For tests and keyboard users: what the radio buttons and fields would be set to.
  void choose_none();
  void choose_volts(double volts);
  bool choose_channel(const VoltageSource& source);  // false when it is not among the options

 private:
  QRadioButton *none_, *typed_, *borrowed_;
  QDoubleSpinBox* volts_;
  QComboBox* channel_;
  std::vector<VoltageChannelOption> channels_;
};

}  // namespace bs::ui
