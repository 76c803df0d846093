// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One fuzz input through one importer (or, for "any", through sniffing + the chosen importer, as the CLI does).
// Shared by the libFuzzer targets (scripts/fuzz) and the ctest replay of their corpora (tests/fuzz/replay_main.cpp).
#include <cstddef>
#include <cstdint>
#include <string>

namespace bs::fuzz {

// The importer id this executable exercises: defined by the one-line source tests/fuzz/CMakeLists.txt generates for
// each target, so that this harness and the replay's main are compiled once for all targets.
const char* importer_id();

// Writes `data` to a private temporary file and parses it. An ImportError is the expected outcome for most inputs;
// anything else (another exception type, a crash, a sanitizer report) is a finding and aborts.
void run_one(const std::uint8_t* data, std::size_t size);

}  // namespace bs::fuzz
