// SPDX-License-Identifier: GPL-3.0-or-later
#include "platform/figure_cli.h"

#ifdef BENCHSCOPE_WITH_FIGURES
#include <algorithm>
#include <cstdlib>
#include "device_palette.h"

#include "frames/frame_store.h"
#include "store/run_label_store.h"

namespace bs::cli {

const std::set<std::string>& figure_value_options() {
  static const std::set<std::string> names{"--preset",  "--width-mm", "--height-mm", "--dpi",
                                           "--font-pt", "--format",   "--template"};
  return names;
}

ui::FigureOptions parse_figure_options(const ParsedArgs& args) {
  ui::FigureOptions o;
  const std::string preset = args.value("--preset").value_or("lncs");
  const auto width = preset_width_mm(preset);
  if (!width && !args.value("--width-mm"))
    throw UsageError("unknown --preset '" + preset + "' (lncs, lncs-half, ieee, ieee-double)");
  o.width_mm = args.value("--width-mm") ? args.number("--width-mm", 0) : *width;
  o.height_mm = args.number("--height-mm", 0);
  o.dpi = static_cast<int>(args.number("--dpi", 300));
  o.font_pt = args.number("--font-pt", 8);
  if (!(o.width_mm >= 20 && o.width_mm <= 1000) || !(o.height_mm >= 0 && o.height_mm <= 1000))
    throw UsageError("--width-mm must be 20 to 1000 and --height-mm 0 (automatic) to 1000");
  if (o.dpi < 72 || o.dpi > 2400) throw UsageError("--dpi must be 72 to 2400");
  if (!(o.font_pt >= 4 && o.font_pt <= 24)) throw UsageError("--font-pt must be 4 to 24");
  o.formats = QString::fromStdString(args.value("--format").value_or("pdf")).split(',', Qt::SkipEmptyParts);
  if (o.formats.isEmpty()) throw UsageError("--format takes pdf, svg, png (comma-separated)");
  for (const QString& f : o.formats)
    if (f != "pdf" && f != "svg" && f != "png") throw UsageError("--format takes pdf, svg, png (comma-separated)");
  return o;
}

std::vector<FigureTemplate> figure_templates(const ParsedArgs& args) {
  return load_figure_templates(args.value("--template").value_or(ui::paper_template_path().toStdString()));
}

ui::FigureData figure_data(const std::vector<std::string>& paths, const LoadedData& data, const CancelToken& cancel) {
  ui::FigureData fd;
  fd.runs = data.runs;
  fd.traces = data.power_traces;
  fd.pipelines = pipeline_timings(data.pipeline_runs);
  fd.inference_runs = data.dnn_runs;
  fd.headroom = data.headroom;
  fd.sustain_runs = data.sustain_runs;
  if (!data.frames.empty()) {
    fd.frame = data.frames.front();
  } else if (paths.size() == 1 && looks_like_workspace(paths[0])) {
    const Workspace ws(paths[0], Workspace::OpenMode::ReadOnly);
    warn_damage(ws);
    if (const auto frames = ws.frames(); !frames.empty()) fd.frame = load_frame(ws, frames.front(), cancel);
  }
  // A workspace's devices keep their stored colours (the GUI's); loose files get colours in order. Its runs come
  // first in data.runs, in ws.runs() order (load_inputs), so their labels line up with them.
  if (paths.size() == 1 && looks_like_workspace(paths[0])) {
    const Workspace ws(paths[0], Workspace::OpenMode::ReadOnly);
    for (const DeviceRecord& d : ws.devices()) fd.colors[{d.platform, d.device}] = d.color_index;
    fd.run_labels = run_labels_in_order(ws);
    fd.run_labels.resize(std::min(fd.run_labels.size(), fd.runs.size()));
  }
  for (const FlopsRun& r : data.runs) fd.colors.try_emplace({r.platform, r.device}, static_cast<int>(fd.colors.size()));
  // A platform known only by its power log gets the colour the GUI's Power and Battery tabs give it.
  std::vector<std::pair<std::string, int>> device_colors;
  for (const auto& [key, index] : fd.colors) device_colors.emplace_back(key.first, index);
  std::vector<std::string> trace_platforms;
  for (const PowerTrace& t : data.power_traces) trace_platforms.push_back(t.platform);
  for (const auto& [platform, index] : ui::platform_color_indices(device_colors, trace_platforms))
    if (std::none_of(fd.colors.begin(), fd.colors.end(), [&](const auto& c) { return c.first.first == platform; }))
      fd.colors.try_emplace({platform, ""}, index);
  return fd;
}

std::unique_ptr<QApplication> offscreen_application() {
  if (!std::getenv("QT_QPA_PLATFORM")) setenv("QT_QPA_PLATFORM", "offscreen", 1);
  static int argc = 1;
  static char name[] = "benchscope-cli";
  static char* argv[] = {name, nullptr};
  return std::make_unique<QApplication>(argc, argv);
}

}  // namespace bs::cli
#endif
