// SPDX-License-Identifier: GPL-3.0-or-later
#include "power/left_out_logs.h"

#include <QObject>
#include <QStringList>

#include "analysis/power/borrowed_voltage.h"

namespace bs::ui {

QString left_out_logs_text(const std::vector<PowerTrace>& traces) {
  QStringList lines;
  for (const PowerTrace& t : traces)
    if (const auto why = why_no_power(t))
      lines << QObject::tr("Left out: %1 (%2): %3")
                   .arg(QString::fromStdString(t.label),
                        t.platform.empty() ? QObject::tr("no platform") : QString::fromStdString(t.platform),
                        QString::fromStdString(*why));
  return lines.join('\n');
}

}  // namespace bs::ui
