// SPDX-License-Identifier: GPL-3.0-or-later
// benchscope-cli figures: the paper's figures and tables from a workspace, as PDF/SVG/PNG + LaTeX/CSV +
// figures.json. Rendering needs Qt: a build without it (-DBENCHSCOPE_GUI=OFF, a robot) says so.
#include <iostream>
#include <set>

#include "common/args.h"
#include "common/command.h"
#include "common/signals.h"
#include "report/figure_template.h"
#include "workspace/inputs.h"

#include "platform/figure_cli.h"

namespace bs::cli {
namespace {

int run_figures(const std::vector<std::string>& raw, std::ostream& out, std::ostream& err) {
#ifdef BENCHSCOPE_WITH_FIGURES
  std::set<std::string> values = figure_value_options();
  values.insert("--out");
  values.insert("--data");
#else
  const std::set<std::string> values{"--out",       "--data", "--format",  "--preset",  "--width-mm",
                                     "--height-mm", "--dpi",  "--font-pt", "--template"};
#endif
  const ParsedArgs args = parse_args(raw, {"--quiet"}, values);
  if (args.positional.empty()) throw UsageError("figures needs a workspace or files");
  const auto out_dir = args.value("--out");
  if (!out_dir) throw UsageError("figures needs --out DIR");
#ifndef BENCHSCOPE_WITH_FIGURES
  (void)out;
  (void)err;
  throw std::runtime_error(
      "this benchscope-cli was built without Qt (BENCHSCOPE_GUI=OFF), so it cannot render "
      "figures; use a build with the GUI, or the GUI's File > Reproduce paper figures");
#else
  const ui::FigureOptions o = parse_figure_options(args);
  const auto templates = figure_templates(args);
  const std::string data = args.value("--data").value_or("all");
  if (data != "all" && data != "paper") throw UsageError("--data takes all or paper");
  const ui::FigureData fd = ui::select_figure_data(
      figure_data(args.positional, load_inputs(args.positional, interrupt_token()), interrupt_token()),
      data == "paper" ? ui::FigureDataChoice::PaperOnly : ui::FigureDataChoice::All);
  const auto app = offscreen_application();
  const bool quiet = args.has("--quiet");
  const auto result = ui::render_figures(templates, fd, QString::fromStdString(*out_dir), o, interrupt_token(),
                                         [&](int done, int total, const QString& what) {
                                           if (!quiet)
                                             err << "\r[" << done << "/" << total << "] " << what.toStdString()
                                                 << "        " << std::flush;
                                         });
  if (!quiet) {
    err << '\n' << "data: " << fd.selection << '\n';
    for (const QString& line : result.contents) err << "  " << line.toStdString() << '\n';
  }
  for (const QString& f : result.files) out << f.toStdString() << '\n';
  return 0;
#endif
}

const CommandRegistrar registrar({
    "figures",
    "render the paper's figures and tables (PDF/SVG/PNG, LaTeX/CSV, figures.json)",
    "usage: benchscope-cli figures (WORKSPACE | PATH...) --out DIR [--data all|paper] [--format pdf,svg,png]\n"
    "                              [--preset lncs|lncs-half|ieee|ieee-double | --width-mm MM] [--height-mm MM]\n"
    "                              [--dpi 300] [--font-pt 8] [--template FILE] [--quiet]\n"
    "  Renders every figure of the template (default: resources/figures/paper-2018.json: fig1a, fig1b, fig2a,\n"
    "  fig2b, fig3, fig4, and inference (bench dnn time per image, mean ± SD per platform, network and target;\n"
    "  architecture timings hatched) when the data has bench dnn runs) at the journal width (LNCS 122 mm by\n"
    "  default; height 0.62 x width unless given), text kept as text in PDF and SVG, PNG at --dpi; writes\n"
    "  table1/table2 as .tex (booktabs) and .csv, and figures.json naming every file with its data sources and\n"
    "  their provenance. --data paper keeps only the data reconstructed from the paper (a run measured here never\n"
    "  slips into a paper figure); figures.json records the choice, and what each figure shows and leaves out (and\n"
    "  why) is printed. Needs a build with Qt.",
    run_figures,
});

}  // namespace
}  // namespace bs::cli
