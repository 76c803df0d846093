// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Where and when a measurement was made, for provenance: this machine's host name and the current UTC time.
#include <string>

namespace bs {

std::string host_name();      // gethostname(), or "unknown host"
std::string utc_timestamp();  // ISO 8601 to the second, e.g. "2026-11-23T10:31:58Z"

}  // namespace bs
