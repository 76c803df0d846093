// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A command that reads or writes a file the user picks (the lens tools: load or save a lens, export a lookup table,
// save or load picked lines): ask for the file, do it, and say why in a warning when it fails; a cancelled dialog
// does nothing. Each such command spelled the dialog, the check and the warning out again.
#include <QString>
#include <functional>

class QWidget;

namespace bs::ui {

struct FileCommand {
  enum Kind { Open, Save };
  Kind kind;
  QString title;      // the file dialog's title, and the warning's unless `failure_title` is given
  QString suggested;  // the file name offered (Save), or the folder (empty: the dialog's own choice)
  QString filter;     // the dialog's file types, e.g. "Lens JSON (*.json)"
  QString failure_title = {};
};

// Asks for the file as `command` says, then calls `act` with its path; what `act` throws is shown in a warning over
// `parent`.
void run_file_command(QWidget* parent, const FileCommand& command, const std::function<void(const QString&)>& act);

}  // namespace bs::ui
