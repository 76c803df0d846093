// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The candidates tables (own and published platforms, core/analysis/library/candidates.h) for a terminal and as
// JSON, shared by `platforms --library` and `library compare`.
#include <iosfwd>
#include <span>
#include <string>

#include <nlohmann/json.hpp>

#include "analysis/library/candidates.h"
#include "workspace/inputs.h"

namespace bs::cli {

// One block per class: the ranked rows with origin, latency, throughput, power, energy, battery, the verdict when
// constrained and what still differs, then each row's source.
void print_candidates(std::ostream& out, std::span<const CandidateClass> classes, std::span<const PeakClass> peaks,
                      bool constrained);
nlohmann::json candidates_json(std::span<const CandidateClass> classes, std::span<const PeakClass> peaks);

// The chosen library results' ROS 2 graph benchmarks (ros2_benchmark, RobotPerf), one block per class (tool, node,
// input, release, measure) with what each value is and its source; nothing when there are none. As JSON: the classes
// with their rows (id, computer, value, unit, what the value is, release, source URL, flags).
void print_graph_benchmarks(std::ostream& out, const std::vector<const LibraryResult*>& chosen, const Library& lib);
nlohmann::json graph_benchmarks_json(const std::vector<const LibraryResult*>& chosen, const Library& lib);

// What `--library SPEC` ranks the own platforms `rows` against (rows must outlive the result): the loaded pipeline
// runs, dnn runs and result sets beside the bundled library's results that SPEC selects. Throws std::runtime_error
// when the bundled library could not be read, UsageError naming --library when SPEC is not a valid selection.
CandidateInputs library_candidate_inputs(std::span<const PlatformRow> rows, const LoadedData& data,
                                         const std::string& spec);

}  // namespace bs::cli
