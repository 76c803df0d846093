// SPDX-License-Identifier: GPL-3.0-or-later
// benchscope-cli report: one page per platform (peaks, % of theoretical peak, power, GFLOPS/W, battery runtime,
// pipeline timings, where each number came from) with the figures embedded, as self-contained HTML and/or PDF.
#include <filesystem>
#include <iostream>
#include <set>

#include "common/args.h"
#include "common/command.h"
#include "common/signals.h"
#include "platform/figure_cli.h"
#include "platform/platform_args.h"
#include "workspace/inputs.h"

#ifdef BENCHSCOPE_WITH_FIGURES
#include <QBuffer>
#include "analysis/library/candidates.h"

#include "candidates_figure.h"
#include "platform/candidates_cli.h"
#include "report/candidates_section.h"
#include "report_writer.h"
#endif

namespace bs::cli {
namespace {

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

int run_report(const std::vector<std::string>& raw, std::ostream& out, std::ostream& err) {
  std::set<std::string> values = platform_value_options();
  values.insert({"--out", "--pdf", "--preset", "--width-mm", "--height-mm", "--font-pt", "--template", "--library"});
  const ParsedArgs args = parse_args(raw, {"--quiet", "--no-stored"}, values);
  if (args.positional.empty()) throw UsageError("report needs a workspace or files");
  std::string html = args.value("--out").value_or("");
  std::string pdf = args.value("--pdf").value_or("");
  if (ends_with(html, ".pdf") && pdf.empty()) std::swap(html, pdf);  // --out report.pdf means the PDF
  if (html.empty() && pdf.empty()) throw UsageError("report needs --out report.html and/or --pdf report.pdf");
  const PlatformArgs platform = parse_platform_args(args);
#ifndef BENCHSCOPE_WITH_FIGURES
  (void)out;
  (void)err;
  (void)platform;
  throw std::runtime_error(
      "this benchscope-cli was built without Qt (BENCHSCOPE_GUI=OFF), so it cannot render the "
      "report's figures; use a build with the GUI, or the GUI's File > Export report");
#else
  const ui::FigureOptions o = parse_figure_options(args);
  const auto templates = figure_templates(args);
  const LoadedData data = load_inputs(args.positional, interrupt_token());
  const ui::FigureData fd = figure_data(args.positional, data, interrupt_token());
  if (fd.runs.empty() && fd.traces.empty()) throw std::runtime_error("no FLOPS runs or power logs to report on");
  // The "Candidates" section: the library's results named by --library beside the own platforms.
  std::vector<CandidateClass> classes;
  std::vector<PeakClass> peaks;
  // The library computers given, else those the workspace's Platforms tab stored.
  const auto spec = args.value("--library")    ? args.value("--library")
                    : platform.library.empty() ? std::nullopt
                                               : std::optional<std::string>(platform.library);
  if (spec) {
    const auto rows = compare_platforms(fd.runs, fd.traces, fd.pipelines, platform.options);
    CandidateInputs in = library_candidate_inputs(rows, data, *spec);
    // No class picks what the control loop's verdict rejects (the report's verdicts judge it the same way).
    const RequirementVerdicts judged = judge_requirements(platform, rows, data);
    if (platform.loop) in.loop = &judged.loop;
    if (platform.sustained) in.sustained = &judged.sustained;
    classes = rank_candidates(in, platform.constraints, platform.options);
    peaks = peak_candidates(in);
  }
  const auto app = offscreen_application();
  std::optional<CandidatesSectionInput> candidates;
  if (spec) {
    // The candidates figure is embedded in the HTML (a PDF gets the tables only).
    std::string figure;
    if (pdf.empty()) {
      QByteArray png;
      QBuffer buffer(&png);
      buffer.open(QIODevice::WriteOnly);
      ui::render_candidates(classes, 900, 560).save(&buffer, "PNG");
      figure = "data:image/png;base64," + png.toBase64().toStdString();
    }
    candidates = CandidatesSectionInput{classes, peaks, *spec, ui::describe_constraints(platform.constraints), figure};
  }
  ui::ReportRequest request;
  request.workspace_name = QString::fromStdString(std::filesystem::path(args.positional.front()).filename().string());
  request.html_path = QString::fromStdString(html);
  request.pdf_path = QString::fromStdString(pdf);
  request.constraints = platform.constraints;
  request.comparison = platform.options;
  request.candidates = std::move(candidates);
  request.loop = platform.loop;
  request.sustained = platform.sustained;
  request.chosen_log_platforms = platform.chosen_log_platforms;
  const bool quiet = args.has("--quiet");
  if (!quiet && !platform.stored.empty())
    err << "report: stored in the workspace (Platforms tab; --no-stored ignores it): " << platform.stored << '\n';
  const QStringList files =
      ui::write_report(request, templates, fd, o, interrupt_token(), [&](int done, int total, const QString& what) {
        if (!quiet) err << "\r[" << done << "/" << total << "] " << what.toStdString() << "        " << std::flush;
      });
  if (!quiet) err << '\n';
  for (const QString& f : files) out << f.toStdString() << '\n';
  return 0;
#endif
}

const CommandRegistrar registrar({
    "report",
    "one-page-per-platform report with the figures embedded (HTML and/or PDF)",
    "usage: benchscope-cli report (WORKSPACE | PATH...) --out report.html [--pdf report.pdf]\n"
    "                             [--budget W] [--min-fps FPS] [--min-runtime MIN] [--battery PRESET]\n"
    "                             [--extra-load W] [--mission SPEC] [--supply-volts V] [--template FILE] [--font-pt "
    "8]\n"
    "                             [--library COMPUTERS] [--require-loop SPEC] [--require-sustained SPEC]\n"
    "                             [--no-stored] [--quiet]\n"
    "  --require-loop: a control-loop requirement as in `platforms` (a section \"Control-loop headroom\" with each\n"
    "  headroom measurement and the verdict per platform; unknown never passes).\n"
    "  --require-sustained: a sustained requirement as in `platforms` (a section \"Sustained performance\" with the\n"
    "  verdict per platform, its margin and the run that judged it; unknown never passes).\n"
    "  The platform comparison, then one page per platform: best GPU and CPU peak with device, backend and % of\n"
    "  theoretical peak, pipeline timings (ms, mean ± SD (n)), mean and max power, GFLOPS/W (the paper's and at\n"
    "  mean power), energy per frame, battery runtime (constant-power model, --battery preset, over --mission when\n"
    "  given, as in `platforms`), and where each\n"
    "  number came from; then the template's figures. The HTML embeds the figures (one self-contained file); the\n"
    "  PDF is A4, printed by Qt. With constraints, the recommended platform is named. --out report.pdf alone\n"
    "  writes only the PDF. --library orin,pi5 adds a \"Candidates\" section: published results from the library\n"
    "  beside the own platforms, ranked like with like under the same constraints (as `platforms --library`).\n"
    "  A workspace's stored Platforms-tab settings and chosen power logs apply as in `platforms` (--no-stored).\n"
    "  Needs a build with Qt.",
    run_report,
});

}  // namespace
}  // namespace bs::cli
