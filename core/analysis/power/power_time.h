// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Absolute times in power logs (ISO 8601 columns, tegrastats' "MM-DD-YYYY HH:MM:SS" prefix) as seconds since the
// Unix epoch, so a trace can be lined up with a benchmark run's start and end. No locale, no time zone database:
// a time without an offset is taken as written (local time of the logger), which is what lining up two logs
// from the same machine needs.
#include <optional>
#include <string>
#include <string_view>

namespace bs {

// Days since 1970-01-01 of a proleptic Gregorian date (exact for every year, month and day boundary).
long long days_from_civil(int year, unsigned month, unsigned day) noexcept;

// "2026-11-22T10:00:01.250Z", "2026-11-22 10:00:01", "2026-11-22T10:00:01+01:00" -> seconds since the epoch.
// Empty when the text is not such a date-time or a field is out of range.
std::optional<double> parse_iso8601(std::string_view text) noexcept;

// Any of the date-time forms power logs write, each with optional fractional seconds and (like ISO 8601) an
// optional "Z" or "+01:00" offset: ISO 8601 ("2026-11-22T10:00:01.5", "2026-11-22 10:00:01"), nvidia-smi's
// "2026/11/22 10:00:01.250", and the US "11-22-2026 10:00:01.250" (month first, as tegrastats prints it; not
// "11/22/2026", which is as often day first). The date and time are separated by 'T' or one space.
// `has_offset` (optional) tells whether the text carried a zone. Empty when none of these fits.
std::optional<double> parse_date_time(std::string_view text, bool* has_offset = nullptr) noexcept;

// tegrastats' "11-22-2026" "10:00:01" (month-day-year as the tool prints it).
std::optional<double> parse_month_day_year(std::string_view date, std::string_view time) noexcept;

// Seconds since the epoch -> "2026-11-22T10:00:01.250" (milliseconds only when not whole).
std::string format_iso8601(double epoch_s);

}  // namespace bs
