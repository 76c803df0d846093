// SPDX-License-Identifier: GPL-3.0-or-later
#include "commands/bench_dnn_grammar.h"

#include <cmath>
#include <cstdio>

#include "vision/pipeline/dnn_architectures.h"

namespace bs::commands {
namespace {

void read_input(const std::string& text, BenchDnnSettings& s) {
  int w = 0, h = 0;
  char x = 0, extra = 0;
  if (std::sscanf(text.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || (x != 'x' && x != 'X') || w < 32 || h < 32 ||
      w > 4096 || h > 4096)
    throw UsageError("--input must be WxH with sides of 32 to 4096 px, e.g. 640x640 (got '" + text + "')");
  s.input_width = w;
  s.input_height = h;
}

}  // namespace

std::vector<std::string> to_words(const BenchDnnSettings& s) {
  std::vector<std::string> a = {
      "bench", "dnn", "--runs", std::to_string(s.runs), "--batch", std::to_string(s.batch), "--backend", s.backend};
  write_option(a, "--model", s.model);
  write_option(a, "--arch", s.arch);
  if (s.input_width > 0)
    a.insert(a.end(), {"--input", std::to_string(s.input_width) + "x" + std::to_string(s.input_height)});
  write_option(a, "--platform", s.platform);
  write_option(a, "--workspace", s.workspace);
  if (s.json) a.push_back("--json");
  write_power(s.power, a);
  return a;
}

BenchDnnSettings bench_dnn_from_words(const std::vector<std::string>& words) {
  std::set<std::string> valued = {"--model", "--arch",    "--input",    "--batch",
                                  "--runs",  "--backend", "--platform", "--workspace"};
  valued.insert(kPowerWordOptions.begin(), kPowerWordOptions.end());
  const Words args = read_words(words, {"--json"}, valued);
  if (!args.positional.empty())
    throw UsageError("bench dnn takes no positional arguments (got '" + args.positional.front() + "')");
  BenchDnnSettings s;
  s.model = args.value("--model");
  s.arch = args.value("--arch");
  if (s.model && s.arch) throw UsageError("give --model or --arch, not both");
  const double runs = args.number("--runs", 20);
  if (!(runs >= 1 && runs <= 100000) || runs != std::floor(runs))
    throw UsageError("--runs must be a whole number from 1 to 100,000");  // whole_number would write "100000"
  s.runs = static_cast<int>(runs);
  s.batch = static_cast<int>(whole_number(args, "--batch", 1, 1, 256));
  if (const auto input = args.value("--input")) read_input(*input, s);
  s.backend = args.value("--backend").value_or("all");
  if (s.backend != "all" && s.backend != "cpu" && s.backend != "opencl" && s.backend != "cuda")
    throw UsageError("--backend must be cpu, opencl, cuda or all (got '" + s.backend + "')");
  if (s.arch && !vision::architecture_from_string(*s.arch))
    throw UsageError("--arch must be mobilenet-ssd or yolo-n (got '" + *s.arch + "')");
  s.platform = args.value("--platform");
  s.workspace = args.value("--workspace");
  s.json = args.has("--json");
  s.power = read_power(args);
  return s;
}

}  // namespace bs::commands
