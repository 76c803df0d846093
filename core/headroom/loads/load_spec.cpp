// SPDX-License-Identifier: GPL-3.0-or-later
#include "headroom/loads/load_spec.h"

#include <cstdlib>
#include <stdexcept>

#include "headroom/loads/kernel_load.h"
#include "headroom/loads/vision_loads.h"
#include "util/text.h"

namespace bs::headroom {
namespace {

constexpr const char* kAccepted = "pipeline[@FPS], dnn[:mobilenet-ssd|yolo-n|hog][@RATE] or flops[:W]";

[[noreturn]] void bad(const std::string& token, const std::string& why) {
  throw std::invalid_argument("load '" + token + "': " + why + " (loads: " + kAccepted + ")");
}

double positive(const std::string& token, std::string text, const char* unit) {
  if (text.size() > std::string(unit).size() && text.ends_with(unit))
    text.resize(text.size() - std::string(unit).size());
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !(v > 0)) bad(token, "'" + text + "' is not a positive number");
  return v;
}

struct Parsed {
  std::string kind, arg;
  std::optional<double> rate;
};

Parsed parse(const std::string& token) {
  Parsed p;
  std::string rest = token;
  if (const auto at = rest.find('@'); at != std::string::npos) {
    p.rate = positive(token, rest.substr(at + 1), rest.rfind("pipeline", 0) == 0 ? "fps" : "/s");
    rest.resize(at);
  }
  if (const auto colon = rest.find(':'); colon != std::string::npos) {
    p.arg = rest.substr(colon + 1);
    rest.resize(colon);
    if (p.arg.empty()) bad(token, "nothing after ':'");
  }
  p.kind = rest;
  if (p.kind != "pipeline" && p.kind != "dnn" && p.kind != "flops") bad(token, "unknown load '" + p.kind + "'");
  if (p.kind == "pipeline" && !p.arg.empty()) bad(token, "the pipeline takes no ':' argument (use --detector)");
  if (p.kind == "flops" && p.rate) bad(token, "the flops load takes no rate");
  return p;
}

std::unique_ptr<Load> make_one(const std::string& token, const LoadOptions& options) {
  const Parsed p = parse(token);
  if (p.kind == "pipeline") {
    PipelineLoadConfig c;
    c.fps = p.rate.value_or(30);
    c.detector = options.pipeline_detector;
    c.mosaics = options.frames;
    c.frames_note = options.frames_note;
    return std::make_unique<PipelineLoad>(std::move(c));
  }
  if (p.kind == "dnn") {
    DetectorLoadConfig c;
    if (!p.arg.empty()) c.network = p.arg;
    c.rate = p.rate;
    return std::make_unique<DetectorLoad>(std::move(c));
  }
  KernelLoadConfig c;
  if (!p.arg.empty()) {
    const double w = positive(token, p.arg, "");
    if (w != static_cast<double>(static_cast<std::int64_t>(w))) bad(token, "W must be a whole number");
    c.workers = static_cast<std::int64_t>(w);
  }
  return std::make_unique<KernelLoad>(c);
}

}  // namespace

std::vector<std::unique_ptr<Load>> make_loads(const std::string& specs, const LoadOptions& options) {
  std::vector<std::unique_ptr<Load>> loads;
  for (const std::string& t : comma_terms(specs)) {
    try {
      loads.push_back(make_one(t, options));
    } catch (const std::invalid_argument& e) {
      const std::string what = e.what();
      if (what.rfind("load '", 0) == 0) throw;
      bad(t, what);
    }
  }
  return loads;
}

std::string canonical_load_name(const std::string& token) {
  const Parsed p = parse(token);
  char rate[32] = "";
  if (p.rate) std::snprintf(rate, sizeof rate, "%g", *p.rate);
  if (p.kind == "pipeline") return "pipeline@" + std::string(p.rate ? rate : "30") + "fps";
  if (p.kind == "dnn")
    return "dnn:" + (p.arg.empty() ? std::string("mobilenet-ssd") : p.arg) + (p.rate ? "@" + std::string(rate) : "");
  return p.arg.empty() ? "flops" : "flops:" + p.arg;
}

std::vector<std::string> canonical_load_names(const std::string& specs) {
  std::vector<std::string> names;
  for (const std::string& t : comma_terms(specs)) names.push_back(canonical_load_name(t));
  return names;
}

}  // namespace bs::headroom
