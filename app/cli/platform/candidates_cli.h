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

// What `--library SPEC` ranks the own platforms `rows` against (rows must outlive the result): the loaded pipeline
// runs, dnn runs and result sets beside the bundled library's results that SPEC selects. Throws std::runtime_error
// when the bundled library could not be read, UsageError naming --library when SPEC is not a valid selection.
CandidateInputs library_candidate_inputs(std::span<const PlatformRow> rows, const LoadedData& data,
                                         const std::string& spec);

}  // namespace bs::cli
