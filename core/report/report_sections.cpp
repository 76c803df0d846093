// SPDX-License-Identifier: GPL-3.0-or-later
#include "report/report_sections.h"

#include <algorithm>
#include <cmath>

#include "analysis/platform/inference_table.h"
#include "analysis/stats/units.h"
#include "headroom/headroom_table.h"
#include "report/table_fit.h"
#include "util/text.h"

namespace bs {
namespace {

std::string percent(double fraction) { return fixed(100 * fraction, 1) + " %"; }

std::string peak_detail(const PeakRow& p) {
  std::string s = fixed(p.peak.flops / 1e9, 2) + " GFLOPS on " + p.device + " (" + p.backend;
  if (p.dims > 0) s += ", D = " + std::to_string(p.dims);
  s += ", " + std::to_string(p.peak.workers) + " workers)";
  if (p.fraction_of_theoretical) s += "; " + percent(*p.fraction_of_theoretical) + " of the theoretical peak";
  if (p.ratio_to_reported) s += "; " + percent(*p.ratio_to_reported) + " of the figure the vendor reports";
  if (p.fraction_of_spec && p.spec)
    s += "; " + percent(*p.fraction_of_spec) + " of the " + p.spec->name + "'s FP32 peak";
  return s;
}

// "power budget (mean power): 9.48 W against at most 10 W (0.52 W to spare)".
std::string check_text(const ConstraintCheck& k) {
  if (!k.actual) return k.name + ": no data";
  const bool at_most = is_ceiling(k);
  return k.name + ": " + fixed(*k.actual, 2) + " " + k.unit + " against " + (at_most ? "at most " : "at least ") +
         fixed(k.required, 2) + " " + k.unit + " (" + fixed(std::abs(k.margin), 2) + " " + k.unit +
         (k.met ? " to spare)" : " short)");
}

}  // namespace

void decision_section(const ReportInput& in, ReportBuilder& b) {
  b.heading(1, "BenchScope report: " + in.workspace);
  std::string meta = "Generated " + in.generated + " by " + in.tool + " from " + std::to_string(in.rows.size()) +
                     (in.rows.size() == 1 ? " platform" : " platforms");
  if (!in.data_selection.empty()) meta += " (" + in.data_selection + ")";
  b.paragraph(meta + ". Sources and provenance of every number: Appendix A.", "note");

  b.heading(2, "Decision");
  const PlatformVerdict* chosen = nullptr;
  for (const PlatformVerdict& v : in.verdicts)
    if (v.recommended) chosen = &v;
  if (chosen) {
    b.html("<p class=\"decision\"><b>" + html_escape(recommendation_text(in)) + "</b>");
    b.html(in.constraints.empty()
               ? " &#8212; no constraints were set: the highest trusted peak among the platforms with a power log."
               : " &#8212; the highest trusted peak among the platforms that meet every constraint.");
    for (const ConstraintCheck& k : chosen->checks) b.html(" Met: " + html_escape(check_text(k)) + ".");
    b.html("</p>\n");
  } else if (!in.verdicts.empty()) {
    b.paragraph("No platform can be recommended" +
                    (in.constraints.empty() ? std::string() : " under " + in.constraints) +
                    ": none meets every constraint with a power log and a FLOPS run.",
                "decision");
  }
  // What else the decision rests on: which power log each platform's numbers come from, the library candidates.
  if (const std::string basis = decision_basis_text(in); !basis.empty()) b.paragraph(basis, "note");
  // Why the others were not chosen, in a line: platforms with the same reason share it.
  std::vector<std::pair<std::string, std::string>> reasons;  // reason -> platforms
  for (std::size_t i = 0; i < in.verdicts.size(); ++i) {
    const PlatformVerdict& v = in.verdicts[i];
    if (v.recommended) continue;
    // Every check that decided it, those without a value too (an unknown control loop, a frame rate without a
    // pipeline run): before #50 those were left out, and a platform that met nothing was said to meet everything.
    std::string why = v.note.starts_with("no power log") ? "no power log" : v.note;
    for (const ConstraintCheck& k : v.checks)
      if (!k.met) why += (why.empty() ? "" : "; ") + unmet_text(k);
    if (why.empty()) why = chosen ? "meets the constraints with less trusted peak compute" : "not ranked";
    auto it = std::find_if(reasons.begin(), reasons.end(), [&](const auto& r) { return r.first == why; });
    if (it == reasons.end())
      reasons.push_back({why, v.platform});
    else
      it->second += ", " + v.platform;
  }
  std::string others;
  for (const auto& [why, platforms] : reasons) others += (others.empty() ? "" : "; ") + platforms + ": " + why;
  if (!others.empty()) others += ".";
  // A flagged peak is shown as measured but ranked at most at its device's peak: said in a line, the detail with
  // the platform.
  std::string capped;
  for (const PlatformVerdict& v : in.verdicts)
    if (!v.ranking_note.empty()) capped += (capped.empty() ? "" : ", ") + v.platform;
  // One paragraph for both, so that page one keeps its room for the table.
  if (!others.empty() || !capped.empty()) {
    b.html("<p class=\"note\">");
    if (!others.empty()) b.html("Not chosen: " + html_escape(others) + " ");
    if (!capped.empty())
      b.html("<span class=\"flags\">&#9888; Ranked at their device's peak, not at their flagged value: " +
             html_escape(capped) + " (Platform details).</span>");
    b.html("</p>\n");
  }

  if (in.comparison_chart) b.figure(*in.comparison_chart);
  for (const ReportTable& t : platform_summary_tables(in.rows, in.verdicts)) b.table(t);
}

void platform_details_section(const ReportInput& in, ReportBuilder& b) {
  if (in.rows.empty()) return;
  b.heading(2, "Platform details");
  for (const PlatformRow& row : in.rows) {
    b.heading(3, row.platform);
    if (row.gpu) b.paragraph("GPU peak: " + peak_detail(*row.gpu) + ".");
    if (row.cpu) b.paragraph("CPU peak: " + peak_detail(*row.cpu) + ".");
    if (!row.gpu && !row.cpu) b.paragraph("No FLOPS runs.");
    for (const PlatformVerdict& v : in.verdicts)
      if (v.platform == row.platform && !v.ranking_note.empty())
        b.html("<p class=\"flags\">&#9888; Ranking: " + html_escape(v.ranking_note) + ".</p>\n");
    if (!row.power_measurement.empty())
      b.paragraph("Power measured by: " + row.power_measurement + ".");
    else if (!row.mean_power_w)
      b.paragraph("No power log: its power, efficiency and battery runtime are unknown.");
    const auto flags = row.all_flags();
    if (!flags.empty()) {
      b.html("<ul class=\"flags\">\n");
      for (const PlausibilityFlag& f : flags)
        b.html("<li><b>&#9888; " + html_escape(f.code) + "</b>: " + html_escape(f.reason) + "</li>\n");
      b.html("</ul>\n");
    }
  }
}

void inference_section(const ReportInput& in, ReportBuilder& b) {
  if (in.inference_runs.empty()) return;
  const ExportTable inf = inference_table(in.inference_runs);
  b.heading(2, "Detection network inference");
  ReportTable t;
  t.caption = "Detection networks timed with bench dnn: time per image mean \xC2\xB1 SD (n).";
  t.header = {inf.header};
  t.rows = inf.rows;
  t.notes = inf.notes;
  b.table(t);
}

void headroom_section(const ReportInput& in, ReportBuilder& b) {
  if (in.headroom.empty() && !in.loop) return;
  b.heading(2, "Control-loop headroom");
  if (in.loop) {
    ReportTable t;
    t.caption = "Control-loop requirement: " + headroom::describe(*in.loop) +
                ". A platform without a headroom measurement is unknown and never passes.";
    t.header = {{"Platform", "Verdict", "Why / measurement"}};
    t.numeric_right = false;
    for (const headroom::LoopVerdict& v : in.loop_verdicts)
      t.rows.push_back({v.platform, std::string(to_string(v.status)),
                        v.reason + (v.reason.empty() || v.measurement.empty() ? "" : "; ") + v.measurement});
    b.table(t);
  }
  for (const headroom::HeadroomMeasurement& m : in.headroom) {
    const ExportTable h =
        headroom::headroom_table(m, m.provenance.source_file.empty() ? m.command : m.provenance.source_file);
    const headroom::KernelFacts& k = m.kernel;
    b.paragraph(m.platform + ", " + std::string(headroom::to_string(m.kind)) + " (" + m.tool + ", " +
                (m.provenance.date.empty() ? "undated" : m.provenance.date) + "): kernel " +
                (k.release.empty() ? "unknown" : k.release) + ", " +
                (k.preemption.empty() ? "preemption unknown" : k.preemption) + ", governor " +
                (k.governor.empty() ? "unknown" : k.governor) + ", isolcpus " +
                (k.isolcpus.empty() ? "none" : k.isolcpus) + ", nohz_full " +
                (k.nohz_full.empty() ? "none" : k.nohz_full) +
                (m.realtime() ? "." : ". NON-REAL-TIME: not comparable with real-time results."));
    ReportTable t;
    t.caption = h.caption;
    t.header = {h.header};
    t.rows = h.rows;
    t.notes = h.notes;
    b.table(t);
  }
}

void sustained_section(const ReportInput& in, ReportBuilder& b) {
  if (!in.sustained) return;
  b.heading(2, "Sustained performance");
  ReportTable t;
  t.caption = "Sustained requirement: " + sustain::describe(*in.sustained) +
              ". A platform without a sustained run that answers every term is unknown and never passes.";
  t.header = {{"Platform", "Verdict", "Margin / why", "Run judged"}};
  t.numeric_right = false;
  for (const sustain::SustainVerdict& v : in.sustained_verdicts)
    t.rows.push_back({v.platform, std::string(to_string(v.status)),
                      v.status == RequirementStatus::Pass ? v.margin : v.reason, v.record});
  b.table(t);
}

void figures_section(const ReportInput& in, ReportBuilder& b) {
  if (in.figures.empty()) return;
  b.heading(2, "Figures", true);
  for (const ReportFigure& f : in.figures) b.figure(f);
}

void sources_appendix(const ReportInput& in, ReportBuilder& b) {
  b.heading(2, "Appendix A. Sources and provenance", true);
  b.paragraph("Workspace " + in.workspace + "; report generated " + in.generated + " by " + in.tool +
              (in.data_selection.empty() ? "" : "; data: " + in.data_selection) +
              ". Power figures use the supply voltage of each log; peaks are the highest mean over repetitions.");
  ReportTable t;
  t.caption = "Where each number of Table 1 comes from.";
  t.header = {{"Platform", "Measure", "Source file", "Origin", "How"}};
  t.numeric_right = false;
  // The columns fit the text width as the other tables' do (report/table_fit.h): a long file name ran past the
  // page's edge and took the last column's words with it ("peak o").
  for (const PlatformRow& row : in.rows)
    for (const auto& [column, src] : row.sources)
      t.rows.push_back({row.platform, column, src.source_file, std::string(to_string(src.origin)), src.how});
  if (!t.rows.empty())
    for (const ReportTable& part : split_to_width(t, 2)) b.table(part);
  // The figures' data, numbered as in the report: page one's chart is Figure 1 when there is one.
  int n = in.comparison_chart ? 1 : 0;
  if (in.comparison_chart && !in.comparison_chart->sources.empty())
    b.paragraph("Figure 1: " + in.comparison_chart->sources, "note");
  for (const ReportFigure& f : in.figures) {
    ++n;
    if (!f.sources.empty())
      b.paragraph("Figure " + std::to_string(n) + (f.id.empty() ? "" : " (" + f.id + ")") + ": " + f.sources, "note");
  }
}

void candidates_section(const ReportInput& in, ReportBuilder& b) {
  if (in.candidates) write_candidates_section(*in.candidates, b);
}

std::vector<ReportSection> report_sections() {
  return {decision_section,  platform_details_section, inference_section, headroom_section,
          sustained_section, candidates_section,       figures_section,   sources_appendix};
}

}  // namespace bs
