// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/file_command.h"

#include <QFileDialog>
#include <QMessageBox>
#include <exception>

namespace bs::ui {

void run_file_command(QWidget* parent, const FileCommand& command, const std::function<void(const QString&)>& act) {
  const QString path = command.kind == FileCommand::Open
                           ? QFileDialog::getOpenFileName(parent, command.title, command.suggested, command.filter)
                           : QFileDialog::getSaveFileName(parent, command.title, command.suggested, command.filter);
  if (path.isEmpty()) return;
  try {
    act(path);
  } catch (const std::exception& e) {
    QMessageBox::warning(parent, command.failure_title.isEmpty() ? command.title : command.failure_title,
                         QString::fromStdString(e.what()));
  }
}

}  // namespace bs::ui
