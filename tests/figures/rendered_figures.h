// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What the figure tests of this room render and read back: the paper template's figures of one kind, rendered alone
// as `benchscope-cli figures` renders them, and the manifest (figures.json) render_figures writes beside the files.
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

#include <string>
#include <vector>

#include "../support/file_bytes.h"
#include "paper_figures.h"
#include "report/figure_template.h"

namespace bs::test {

// The paper template's figures of `kind` ("inference", "headroom": each an optional figure of its own).
inline std::vector<FigureTemplate> paper_figures_of_kind(const std::string& kind) {
  std::vector<FigureTemplate> out;
  for (const auto& t : load_figure_templates(ui::paper_template_path().toStdString()))
    if (t.kind == kind) out.push_back(t);
  return out;
}

// figures.json in `dir`: the files written with their sources, and the figures left out or skipped, with why.
inline QJsonObject figures_manifest(const QTemporaryDir& dir) {
  return QJsonDocument::fromJson(bytes_of(dir.filePath("figures.json"))).object();
}

}  // namespace bs::test
