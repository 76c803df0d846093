// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Text helpers every floor needs, written once (issue #52: trim was written 7 times, lower 8). ASCII only and
// locale-free on purpose: the GUI's QCoreApplication sets the C library's locale from the environment, and
// std::tolower/std::isspace would then treat the bytes of UTF-8 text by that locale's rules.
#include <string>
#include <string_view>
#include <vector>

namespace bs {

// Without ASCII white space (space, tab, CR, LF, FF, VT) at both ends.
std::string_view trim(std::string_view s);
// A..Z to a..z; every other byte as it is (UTF-8 stays intact).
std::string lower(std::string_view s);
// Whether `text` ends with `suffix`, A..Z and a..z alike ("x.PNG" ends with ".png").
bool ends_with_ci(std::string_view text, std::string_view suffix);
// Whether `text` ends with one of `endings`, written space-separated (".tif .tiff"), A..Z and a..z alike.
bool ends_with_any_ci(std::string_view text, std::string_view endings);
// "1kHz, p99.9 <= 200us,,load=idle" -> {"1kHz", "p99.9<=200us", "load=idle"}: a comma-separated list of terms (a
// requirement, a list of loads) split at its commas, every space dropped (no term needs one), empty terms skipped.
std::vector<std::string> comma_terms(std::string_view text);
// The parts one after the other, `separator` between each two: {"a", "b"}, ", " -> "a, b" (empty parts too).
std::string join(const std::vector<std::string>& parts, std::string_view separator);

// One double through a printf format ("%.2f", "%.3g", "%+.1f %%"): the one number formatter of the tables, the
// report and the CLI (issue #52: six copies, each with its own buffer size). Any length fits.
std::string format_number(const char* printf_format, double v);
// `v` with exactly `digits` decimals (0..17), as printf's "%.*f" writes it; any finite double fits.
std::string fixed(double v, int digits);

}  // namespace bs
