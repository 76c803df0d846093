// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/library/graph_benchmarks_table.h"

#include <string>

namespace bs {
namespace {

std::string source_text(const LibraryResult& r) {
  std::string s = r.source.url;
  std::string lines;
  for (const auto& [value, line] : r.source.lines) lines += (lines.empty() ? "" : ", ") + std::to_string(line);
  if (!lines.empty()) s += (r.source.lines.size() == 1 ? " line " : " lines ") + lines;
  return s;
}

std::string tool_name(const std::string& kind) {
  if (kind == "ros2-benchmark") return "ros2_benchmark";
  if (kind == "robotperf") return "RobotPerf";
  return kind;
}

}  // namespace

ExportTable graph_benchmarks_table(std::span<const GraphBenchmarkClass> classes, const Library& lib) {
  ExportTable t;
  t.caption = "ROS 2 graph benchmarks: published results compared within one tool, node, input, release and measure";
  t.label = "tab:graph-benchmarks";
  // What a reader compares first (measure, computer, value and what it is), then the rest of the class.
  t.header = {"Measure", "Computer", "Value", "What the value is", "Rank", "Benchmark", "Input",
              "Release", "Tool",     "Source"};
  t.align = "llrlllllll";
  int flag_no = 0;
  for (const GraphBenchmarkClass& k : classes)
    for (std::size_t i = 0; i < k.rows.size(); ++i) {
      const LibraryResult& r = *k.rows[i];
      std::string computer = lib.computer_name(r.computer);
      for (const PlausibilityFlag& f : r.flags) {
        computer += " [" + std::to_string(++flag_no) + "]";
        t.notes.push_back("[" + std::to_string(flag_no) + "] " + f.code + ": " + f.reason);
      }
      const std::string rank = k.rows.size() == 1 ? "only result" : std::to_string(i + 1);
      t.rows.push_back({r.measure, computer, graph_value_text(r), r.statistic, rank, r.benchmark, r.input, r.release,
                        tool_name(r.kind), source_text(r)});
    }
  return t;
}

}  // namespace bs
