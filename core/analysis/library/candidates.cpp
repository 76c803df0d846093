// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/library/candidates.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <tuple>

#include "analysis/stats/units.h"
#include "util/text.h"

namespace bs {
namespace {

std::string join(const std::vector<std::string>& parts, const char* sep = "; ") {
  std::string s;
  for (const std::string& p : parts)
    if (!p.empty()) s += (s.empty() ? "" : sep) + p;
  return s;
}

// The settings a MLPerf import keeps, by key.
std::string setting(const Provenance& p, std::string_view key) {
  for (const auto& [k, v] : p.settings)
    if (k == key) return v;
  return {};
}

// Hours on the comparison's battery at a constant load (the constant-power model of the Platforms view).
std::optional<double> runtime_h(std::optional<double> power_w, const ComparisonOptions& o) {
  if (!power_w || *power_w + o.extra_load_w <= 0) return std::nullopt;
  return o.battery_nominal_v * o.battery_capacity_ah * o.usable_fraction / (*power_w + o.extra_load_w);
}

const PlatformRow* platform_row(std::span<const PlatformRow> rows, const std::string& name) {
  for (const PlatformRow& r : rows)
    if (r.platform == name) return &r;
  return nullptr;
}

// How a platform's mean power was measured, with how it was derived ("mean of nuc-current.csv x 16 V": a supply
// current times the supply voltage), so power_kind_of() can tell a DC supply from a wall meter.
std::string platform_power_how(const PlatformRow& p) {
  const auto src = p.sources.find(column::kPower);
  return "platform mean power (" + p.power_measurement +
         (src != p.sources.end() && !src->second.how.empty() ? "; " + src->second.how : std::string()) + ")";
}

Candidate from_library(const LibraryResult& r, const Library* lib) {
  Candidate c;
  c.platform = lib ? lib->computer_name(r.computer) : r.computer;
  c.origin = DataOrigin::Published;
  c.network = canonical_network(r.network);
  c.scenario = r.scenario;
  c.precision = r.precision.empty() ? "not stated" : r.precision;
  c.latency_s = r.latency_s;
  c.latency_statistic = r.latency_statistic;
  c.throughput_per_s = r.throughput_per_s;
  c.throughput_statistic = r.throughput_statistic;
  c.power_w = r.mean_power_w;
  c.power_how = r.power_measurement;
  c.power_kind = r.power_kind.empty() ? power_kind_of(r.power_measurement) : r.power_kind;
  c.power_samples_w = r.power_samples_w;
  c.energy_per_inference_j = r.energy_per_sample_j;
  c.not_ranked = r.not_ranked;
  std::vector<std::string> cond;
  if (const std::string ps = r.condition("power setting"); !ps.empty()) cond.push_back(ps.substr(0, ps.find(' ')));
  cond.push_back((r.kind == "mlperf-inference" ? "MLPerf " : "") + r.round +
                 (r.date.empty() ? "" : " (" + r.date + ")"));
  if (!r.division.empty()) cond.push_back(r.division + (r.submitter.empty() ? "" : ", " + r.submitter));
  c.conditions = join(cond);
  c.software = r.software;
  c.framework = framework_of(r.software + " " + r.system);
  c.source = r.source.url;
  c.flags = r.flags;
  return c;
}

// An own imported LoadGen result (workspace result set).
std::optional<Candidate> from_loadgen(const ResultSet& s) {
  if (s.source_format != "mlperf-loadgen") return std::nullopt;
  Candidate c;
  c.platform = s.platform;
  c.origin = s.provenance.origin;
  c.network = canonical_network(setting(s.provenance, "network"));
  c.scenario = setting(s.provenance, "scenario");
  c.precision = setting(s.provenance, "precision");
  if (c.precision.empty()) c.precision = "not stated";
  for (const Measurement& m : s.measurements) {
    if (m.values.empty()) continue;
    const double v = m.values.front();
    if (m.metric.starts_with("result: ") && m.unit == "s") {
      c.latency_s = v;
      const std::string es = m.metric.find("Early stopping") != std::string::npos ? " early-stopping estimate" : "";
      c.latency_statistic = m.metric.find("90th") != std::string::npos   ? "p90" + es
                            : m.metric.find("99th") != std::string::npos ? "p99" + es
                                                                         : m.metric.substr(8);
      // MultiStream's latency is per query of several samples: the importer says so in the library's words.
      if (const std::string said = setting(s.provenance, "latency statistic"); !said.empty())
        c.latency_statistic = said;
    }
    // SingleStream is rated in queries per second (one sample each), as the library rates it; the other
    // scenarios in samples per second.
    if (m.metric == "queries per second" && c.scenario == "SingleStream") {
      c.throughput_per_s = v;
      c.throughput_statistic = "queries per second";
    }
    if (m.metric == "samples per second" && c.scenario != "SingleStream") {
      c.throughput_per_s = v;
      // MultiStream: samples per query / the official latency, as the library rates it (the importer's words).
      const std::string how = setting(s.provenance, "throughput");
      c.throughput_statistic = how.empty() ? "samples per second" : how;
    }
    if (m.metric == "mean power") c.power_w = v;
    if (m.metric == "energy per sample") c.energy_per_inference_j = v;
  }
  if (c.power_w) {
    c.power_how = std::string(to_string(s.provenance.measurement)) + ", " + s.provenance.sensor;
    const std::string kind = setting(s.provenance, "power kind");
    c.power_kind = kind.empty() ? power_kind_of(c.power_how) : kind;
    // spl.txt without its detail log: the whole log's mean, not MLPerf's power window.
    if (const std::string window = setting(s.provenance, "power window"); window.starts_with("whole log"))
      c.flags.push_back(
          {"power_not_in_mlperf_window",
           "mean power over the whole spl.txt (" + window +
               "): it includes the time before and after LoadGen's queries, so it is not MLPerf's power"});
  }
  c.conditions = "MLPerf LoadGen run" + (s.provenance.date.empty() ? "" : " (" + s.provenance.date + ")");
  c.software = s.backend;
  c.framework = framework_of(s.backend + " " + setting(s.provenance, "framework"));
  c.source = s.provenance.source_file;
  if (!c.throughput_per_s && c.latency_s && *c.latency_s > 0) {
    c.throughput_per_s = 1 / *c.latency_s;
    c.throughput_statistic = "1 / latency";
  }
  if (!c.throughput_per_s) return std::nullopt;
  return c;
}

Candidate from_dnn(const DnnRun& r, std::span<const PlatformRow> rows) {
  Candidate c;
  c.platform = r.platform;
  c.origin = r.provenance.origin;
  c.network = canonical_network(r.model);
  c.scenario = r.batch == 1 ? "SingleStream" : "batch " + std::to_string(r.batch);
  c.precision = "fp32";  // cv::dnn runs the network's weights in FP32 on every target bench dnn offers
  c.latency_s = r.inference_s();
  c.latency_statistic = "mean of " + std::to_string(r.forward.n) + " passes";
  c.throughput_per_s = r.inferences_per_s();
  c.throughput_statistic = "1 / mean time per image";
  c.power_w = r.mean_power_w;
  if (c.power_w) c.power_how = std::string(to_string(r.provenance.measurement)) + " during the passes";
  if (!c.power_w)
    if (const PlatformRow* p = platform_row(rows, r.platform); p && p->mean_power_w) {
      c.power_w = p->mean_power_w;
      c.power_how = platform_power_how(*p);
    }
  c.power_kind = power_kind_of(c.power_how);
  c.energy_per_inference_j = r.energy_per_inference_j;
  if (!c.energy_per_inference_j && c.power_w && c.latency_s) c.energy_per_inference_j = *c.power_w * *c.latency_s;
  c.conditions =
      r.device + ", " + r.backend + (r.architecture_only ? ", " + std::string(kArchitectureTimingLabel) : "");
  c.software = r.provenance.tool;
  c.framework = "OpenCV dnn";
  c.source = r.provenance.source_file;
  return c;
}

// The detection stage of an own pipeline run: one frame at a time, so SingleStream; precision as run (FP32 for
// the paper's CPU and CUDA detectors: not stated in the paper, hence "not stated").
std::optional<Candidate> from_pipeline(const PipelineRun& r, std::span<const PlatformRow> rows) {
  const StageStats* d = r.stage(pipeline_stage::kDetect);
  if (!d || d->mean_s <= 0 || r.detector == "none") return std::nullopt;
  Candidate c;
  c.platform = r.platform;
  c.origin = r.provenance.origin;
  c.network = canonical_network(r.detector.empty() ? "detector not stated" : r.detector);
  c.scenario = "SingleStream";
  c.precision = "not stated";
  c.latency_s = d->mean_s;
  c.latency_statistic = "mean of " + std::to_string(d->n) + " frames, SD " + format_si(d->sd_s, "s", 2);
  c.throughput_per_s = 1 / d->mean_s;
  c.throughput_statistic = "1 / mean detection time";
  if (const PlatformRow* p = platform_row(rows, r.platform); p && p->mean_power_w) {
    c.power_w = p->mean_power_w;
    c.power_how = platform_power_how(*p);
    c.power_kind = power_kind_of(c.power_how);
    c.energy_per_inference_j = *c.power_w * d->mean_s;
  }
  c.conditions = r.device;
  c.software = r.provenance.tool;
  c.framework = framework_of(r.detector + " " + r.device);  // the paper's "SSD MobileNet (TensorFlow, MS COCO)"
  c.source = r.provenance.source_file;
  return c;
}

// What still differs between a row and its class's first row.
std::string difference(const Candidate& c, const Candidate& ref) {
  std::vector<std::string> d;
  const auto stat = [](const std::string& s) { return s.substr(0, s.find(' ')); };
  if (c.latency_s && ref.latency_s && stat(c.latency_statistic) != stat(ref.latency_statistic))
    d.push_back("latency " + c.latency_statistic + " vs " + ref.latency_statistic);
  if (c.throughput_statistic != ref.throughput_statistic)
    d.push_back("throughput " + c.throughput_statistic + " vs " + ref.throughput_statistic);
  const auto meter = [](const Candidate& x) {
    return !x.power_w ? std::string("no power") : x.power_how.substr(0, x.power_how.find(','));
  };
  if (meter(c) != meter(ref)) d.push_back("power: " + meter(c) + " vs " + meter(ref));
  if (c.origin != ref.origin) d.push_back(origin_label(c.origin) + " vs " + origin_label(ref.origin));
  if (!c.software.empty() && !ref.software.empty() && c.software != ref.software) d.push_back("software differs");
  return join(d);
}

void check(Candidate& c, const Constraints& k, const CandidateInputs& in) {
  c.checks.clear();
  if (in.loop)
    for (ConstraintCheck& x : headroom::loop_checks(c.platform, *in.loop)) c.checks.push_back(std::move(x));
  if (in.sustained)
    for (ConstraintCheck& x : sustain::sustain_checks(c.platform, *in.sustained)) c.checks.push_back(std::move(x));
  if (k.power_budget_w) {
    ConstraintCheck x{"power budget", "W", *k.power_budget_w, c.power_w};
    x.met = c.power_w && *c.power_w <= *k.power_budget_w;
    x.margin = c.power_w ? *k.power_budget_w - *c.power_w : 0;
    x.power_kind = c.power_w ? c.power_kind : std::string();
    if (!c.power_samples_w.empty()) {
      x.samples = c.power_samples_w.size();
      x.share_above = static_cast<double>(std::count_if(c.power_samples_w.begin(), c.power_samples_w.end(),
                                                        [&](double w) { return w > *k.power_budget_w; })) /
                      static_cast<double>(x.samples);
    }
    c.checks.push_back(x);
  }
  if (k.min_fps) {
    ConstraintCheck x{"inference rate", "1/s", *k.min_fps, c.throughput_per_s};
    x.met = c.throughput_per_s && *c.throughput_per_s >= *k.min_fps;
    x.margin = c.throughput_per_s ? *c.throughput_per_s - *k.min_fps : 0;
    c.checks.push_back(x);
  }
  if (k.min_runtime_h) {
    ConstraintCheck x{"battery runtime", "min", *k.min_runtime_h * 60,
                      c.battery_runtime_h ? std::optional<double>(*c.battery_runtime_h * 60) : std::nullopt};
    x.met = c.battery_runtime_h && *c.battery_runtime_h >= *k.min_runtime_h;
    x.margin = c.battery_runtime_h ? (*c.battery_runtime_h - *k.min_runtime_h) * 60 : 0;
    c.checks.push_back(x);
  }
  c.meets_all = std::all_of(c.checks.begin(), c.checks.end(), [](const ConstraintCheck& x) { return x.met; });
}

// "0.05 W under the 10 W budget, 21 % of 601 samples above it, AC wall power".
std::string budget_text(const ConstraintCheck& x) {
  std::string s = format_number("%.3g", std::abs(x.margin)) + " W " + (x.margin >= 0 ? "under" : "over") + " the " +
                  format_number("%.3g", x.required) + " W budget";
  if (x.share_above)
    s +=
        ", " + format_number("%.3g", *x.share_above * 100) + " % of " + std::to_string(x.samples) + " samples above it";
  else
    s += ", samples not known";
  return s + ", " + x.power_kind + " power";
}

// Hours on the battery; a load that is AC wall power of a whole system (MLPerf's meter) is not what the robot's
// DC pack supplies, and the cell says so.
std::string battery_cell(const Candidate& c) {
  if (!c.battery_runtime_h) return "–";
  return format_number("%.3g", *c.battery_runtime_h) +
         (c.power_kind == "AC wall" ? " (AC wall power taken as the load)" : "");
}

std::string ms(std::optional<double> s) { return s ? format_number("%.4g", *s * 1e3) : "–"; }

}  // namespace

std::string canonical_network(std::string_view name) {
  std::string n = lower(name);
  const auto has = [&](std::string_view w) { return n.find(w) != std::string::npos; };
  if (has("resnet") && (has("50") || n == "resnet")) return "resnet50";
  if (has("ssd") && has("mobilenet")) return "ssd-mobilenet";
  if (n == "ssd-small") return "ssd-mobilenet";
  if (n == "ssd-large" || (has("ssd") && has("resnet34"))) return "ssd-resnet34";
  return n;
}

std::string framework_of(std::string_view software) {
  // Most specific first: "TensorFlow Lite" before "TensorFlow", "TensorRT" (in "TensorRT 8.5.2") before either.
  static const std::pair<std::string_view, std::string_view> kNames[] = {{"tensorrt", "TensorRT"},
                                                                         {"tflite", "TFLite"},
                                                                         {"tensorflow lite", "TFLite"},
                                                                         {"tensorflow", "TensorFlow"},
                                                                         {"pytorch", "PyTorch"},
                                                                         {"onnxruntime", "ONNX Runtime"},
                                                                         {"onnx runtime", "ONNX Runtime"},
                                                                         {"openvino", "OpenVINO"},
                                                                         {"armnn", "ArmNN"},
                                                                         {"arm nn", "ArmNN"},
                                                                         {"cv::dnn", "OpenCV dnn"},
                                                                         {"opencv", "OpenCV dnn"},
                                                                         {"ncnn", "ncnn"},
                                                                         {"tvm", "TVM"}};
  const std::string s = lower(software);
  for (const auto& [key, name] : kNames)
    if (s.find(key) != std::string::npos) return std::string(name);
  return {};
}

std::string power_kind_of(std::string_view how) {
  const std::string h = lower(how);
  const auto has = [&](std::string_view w) { return h.find(w) != std::string::npos; };
  if (has("ac wall") || has("ptdaemon") || has("spl.txt")) return "AC wall";
  if (has("rail") || has("tegrastats") || has("jtop") || has("on-board") || has("rapl") || has("nvidia-smi"))
    return "module rail";
  if (has("supply") || has("current") || has("dc ") || has(" x ")) return "DC supply";
  if (has("wall")) return "wall (not stated whether AC or DC)";
  return how.empty() ? std::string() : "not stated";
}

std::string origin_label(DataOrigin origin) { return std::string(to_string(origin)); }

std::string CandidateClass::title() const {
  return network + ", " + scenario + ", " + precision + (framework.empty() ? "" : " (" + framework + ")");
}

std::vector<CandidateClass> rank_candidates(const CandidateInputs& in, const Constraints& constraints,
                                            const ComparisonOptions& options) {
  std::vector<Candidate> all;
  for (const PipelineRun& r : in.pipelines)
    if (auto c = from_pipeline(r, in.platforms)) all.push_back(std::move(*c));
  for (const DnnRun& r : in.dnn_runs) all.push_back(from_dnn(r, in.platforms));
  for (const ResultSet& s : in.result_sets)
    if (auto c = from_loadgen(s)) all.push_back(std::move(*c));
  for (const LibraryResult* r : in.library)
    if (r && r->is_inference()) all.push_back(from_library(*r, in.lib));
  using Key = std::tuple<std::string, std::string, std::string, std::string>;
  std::map<Key, CandidateClass> classes;
  std::vector<Key> order;
  for (Candidate& c : all) {
    c.battery_runtime_h = runtime_h(c.power_w, options);
    check(c, constraints, in);
    // A network not stated is never ranked with another: each such row is a class of its own.
    const bool unstated = c.network.empty() || c.network.find("not stated") != std::string::npos;
    // A precision not stated is ranked only with the same framework; without a framework either, alone.
    const bool no_precision = c.precision == "not stated";
    const std::string framework = !no_precision         ? std::string()
                                  : c.framework.empty() ? "framework not stated: " + c.source
                                                        : c.framework;
    const Key key{unstated ? c.network + " (" + c.source + ")" : c.network, c.scenario, c.precision, framework};
    auto [it, fresh] = classes.try_emplace(key);
    if (fresh) {
      it->second.network = c.network;
      it->second.scenario = c.scenario;
      it->second.precision = c.precision;
      if (no_precision) it->second.framework = c.framework.empty() ? "framework not stated" : c.framework;
      order.push_back(key);
    }
    it->second.rows.push_back(std::move(c));
  }
  std::vector<CandidateClass> out;
  for (const auto& key : order) {
    CandidateClass cls = std::move(classes[key]);
    // Rows that may be ranked first: constraints met first, then the most inferences per second; rows without a
    // rate after them; rows never ranked (one run of one image) last.
    std::stable_sort(cls.rows.begin(), cls.rows.end(), [](const Candidate& a, const Candidate& b) {
      if (a.not_ranked.empty() != b.not_ranked.empty()) return a.not_ranked.empty();
      if (a.meets_all != b.meets_all) return a.meets_all;
      return a.throughput_per_s.value_or(-1) > b.throughput_per_s.value_or(-1);
    });
    // A pick under a power budget compares watts: only watts of one kind. Rows that meet the budget with power of
    // different kinds (AC wall power of a whole system against a module rail) leave the class without a pick.
    std::vector<std::string> kinds;
    for (const Candidate& c : cls.rows)
      if (c.not_ranked.empty() && c.meets_all && constraints.power_budget_w &&
          std::find(kinds.begin(), kinds.end(), c.power_kind) == kinds.end())
        kinds.push_back(c.power_kind);
    if (kinds.size() > 1)
      cls.note = "no pick: the rows within the power budget were measured as different kinds of power (" +
                 join(kinds, " vs ") + "): their watts are not the same quantity";
    if (!cls.rows.empty() && cls.rows.front().not_ranked.empty() && cls.rows.front().meets_all &&
        cls.rows.front().throughput_per_s && cls.note.empty())
      cls.rows.front().recommended = true;
    for (std::size_t i = 1; i < cls.rows.size(); ++i) cls.rows[i].difference = difference(cls.rows[i], cls.rows[0]);
    out.push_back(std::move(cls));
  }
  // Classes with own rows first (what the lab can compare against), then by size.
  std::stable_sort(out.begin(), out.end(), [](const CandidateClass& a, const CandidateClass& b) {
    const auto own = [](const CandidateClass& c) {
      return std::any_of(c.rows.begin(), c.rows.end(),
                         [](const Candidate& r) { return r.origin != DataOrigin::Published; });
    };
    if (own(a) != own(b)) return own(a);
    return a.rows.size() > b.rows.size();
  });
  return out;
}

std::vector<PeakClass> peak_candidates(const CandidateInputs& in) {
  std::vector<PeakCandidate> all;
  for (const PlatformRow& p : in.platforms)
    for (const auto* row : {p.gpu ? &*p.gpu : nullptr, p.cpu ? &*p.cpu : nullptr}) {
      if (!row) continue;
      PeakCandidate c;
      c.platform = p.platform;
      c.origin = row->origin;
      c.device = row->device + " (" + row->backend + ")";
      c.kernel = "rotation2d (BenchScope, the paper's kernel)";
      c.precision = "fp32";
      c.flops = row->peak.flops;
      c.power_w = p.mean_power_w;
      c.source = row->source_file;
      c.flags = row->flags;
      all.push_back(std::move(c));
    }
  for (const LibraryResult* r : in.library) {
    if (!r || r->is_inference() || r->unit != "FLOP/s" || !r->value) continue;
    PeakCandidate c;
    c.platform = in.lib ? in.lib->computer_name(r->computer) : r->computer;
    c.origin = DataOrigin::Published;
    c.device = r->device;
    c.kernel = (r->kind == "clpeak" ? "clpeak " : "") + r->measure;
    c.precision = r->precision;
    c.flops = *r->value;
    c.power_w = r->mean_power_w;
    c.source = r->source.url;
    c.flags = r->flags;
    all.push_back(std::move(c));
  }
  std::vector<PeakClass> out;
  for (PeakCandidate& c : all) {
    if (c.power_w && *c.power_w > 0) c.flops_per_watt = c.flops / *c.power_w;
    auto it = std::find_if(out.begin(), out.end(), [&](const PeakClass& k) { return k.precision == c.precision; });
    if (it == out.end()) it = out.insert(out.end(), PeakClass{c.precision, {}});
    it->rows.push_back(std::move(c));
  }
  for (PeakClass& k : out) {
    std::stable_sort(k.rows.begin(), k.rows.end(),
                     [](const PeakCandidate& a, const PeakCandidate& b) { return a.flops > b.flops; });
    for (std::size_t i = 1; i < k.rows.size(); ++i)
      if (k.rows[i].kernel != k.rows[0].kernel)
        k.rows[i].difference = "kernel: " + k.rows[i].kernel + " vs " + k.rows[0].kernel;
  }
  return out;
}

ExportTable candidates_table(std::span<const CandidateClass> classes, bool with_verdicts) {
  ExportTable t;
  t.caption =
      "Candidates: own and published inference results, compared within one network, scenario and "
      "precision";
  t.label = "tab:candidates";
  t.header = {"Class",        "Rank",
              "Platform",     "Origin",
              "Latency (ms)", "Throughput (1/s)",
              "Power (W)",    "Energy per inference (mJ)",
              "Battery (h)"};
  if (with_verdicts) t.header.push_back("Meets constraints");
  t.header.insert(t.header.end(), {"Differences and conditions", "Source"});
  t.align = "lrllrrrrr" + std::string(with_verdicts ? "l" : "") + "ll";
  int flag_no = 0;
  for (const CandidateClass& k : classes)
    for (std::size_t i = 0; i < k.rows.size(); ++i) {
      const Candidate& c = k.rows[i];
      std::string platform = c.platform;
      for (const PlausibilityFlag& f : c.flags) {
        platform += " [" + std::to_string(++flag_no) + "]";
        t.notes.push_back("[" + std::to_string(flag_no) + "] " + f.code + ": " + f.reason);
      }
      std::vector<std::string> row{
          k.title(),
          !c.not_ranked.empty() ? "not ranked" : std::to_string(i + 1) + (c.recommended ? " (pick)" : ""),
          platform,
          origin_label(c.origin),
          ms(c.latency_s) + (c.latency_s ? " " + c.latency_statistic : ""),
          c.throughput_per_s ? format_number("%.4g", *c.throughput_per_s) : "–",
          c.power_w ? format_number("%.3g", *c.power_w) : "–",
          c.energy_per_inference_j ? format_number("%.4g", *c.energy_per_inference_j * 1e3) : "–",
          battery_cell(c)};
      if (with_verdicts) {
        std::vector<std::string> failed, said;
        for (const ConstraintCheck& x : c.checks) {
          if (!x.met)
            failed.push_back(x.name +
                             (x.actual ? " (" + format_number("%+.3g", x.margin) + " " + x.unit + ")" : " (no data)"));
          if (x.actual && !x.power_kind.empty()) said.push_back(budget_text(x));
        }
        std::string verdict = c.meets_all ? "yes" : "no: " + join(failed, ", ");
        if (!said.empty()) verdict += " [" + join(said) + "]";
        if (!c.not_ranked.empty()) verdict = "not ranked: " + c.not_ranked;
        row.push_back(verdict);
      }
      row.push_back(join({c.difference, c.conditions, k.note.empty() || i > 0 ? std::string() : k.note}));
      row.push_back(c.source);
      t.rows.push_back(std::move(row));
    }
  return t;
}

ExportTable peak_candidates_table(std::span<const PeakClass> classes) {
  ExportTable t;
  t.caption = "Candidates: own and published compute peaks, compared within one precision";
  t.label = "tab:candidate-peaks";
  t.header = {"Precision", "Platform", "Origin", "Device",      "Peak (GFLOPS)",
              "Power (W)", "GFLOPS/W", "Kernel", "Differences", "Source"};
  t.align = "lllllrrrlll";
  int flag_no = 0;
  for (const PeakClass& k : classes)
    for (const PeakCandidate& c : k.rows) {
      std::string platform = c.platform;
      for (const PlausibilityFlag& f : c.flags) {
        platform += " [" + std::to_string(++flag_no) + "]";
        t.notes.push_back("[" + std::to_string(flag_no) + "] " + f.code + ": " + f.reason);
      }
      t.rows.push_back({k.precision, platform, origin_label(c.origin), c.device, format_number("%.4g", c.flops / 1e9),
                        c.power_w ? format_number("%.3g", *c.power_w) : "–",
                        c.flops_per_watt ? format_number("%.3g", *c.flops_per_watt / 1e9) : "–", c.kernel, c.difference,
                        c.source});
    }
  return t;
}

}  // namespace bs
