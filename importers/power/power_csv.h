// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Current / voltage / power logs as delimited text, parsed in one streaming pass:
//  - separator sniffed from the header (, ; tab, counted outside quotes); decimal comma accepted with ; or tab;
//    UTF-8 BOM; CRLF; RFC 4180 quoting ("a, b" and "say ""hi""" are one cell; no line breaks inside quotes);
//    plain unquoted numbers take a fast path parsed in place;
//  - '#' comment lines; a '#'-prefixed line that names a time column is the header (Joulescope writes it so);
//  - header aliases with units from the name: "time_s", "Time [s]", "time_ms", "millis", "sec", "Timestamp (ns)",
//    "current_A", "Current (mA)", "I", "mA", "voltage", "bus_V", "power_mW", "mw", "total_watts", "Power Draw (W)",
//    "Processor Power_0(Watt)", "Main current (A)", German "Zeit/Strom/Spannung/Leistung"; a name without a
//    quantity ("total", "ch1") takes it from an electrical unit; an unknown unit in brackets is an error, never a
//    silent factor; power limits, cumulative energy and charge columns are not samples and are not read;
//  - the time column (an "Elapsed" one first when there are several; Power Gadget's "System Time" last): numbers
//    (relative, or Unix time in s/ms/us/ns when the value lands after 2000; integers beyond 2^53 such as Unix
//    nanoseconds are read exactly as int64), or date-times (ISO 8601 with or without zone, "2026/11/22
//    10:00:01.250", "11-22-2026 10:00:01.250"); "(UTC)" after the name is a zone. time_s counts from the first
//    row; PowerTrace::start_time is the first row's absolute time as ISO 8601 (from another time column when the
//    main one is relative);
//  - empty or N/A cells in a current/voltage/power column are missing samples (NaN), counted in a warning; a column
//    with no value at all is dropped (warning); a file without any current/power value is an error;
//  - several power (else current) columns are channels; the one named total/TOT/sum/package is
//    PowerTrace::total_channel, else none and a warning names the column the statistics use (the first);
//  - Intel Power Gadget's summary footer ("Total Elapsed Time (sec) = 1.04") goes to Provenance::settings;
//  - "# platform: NUC", "# supply_voltage_V: 16", "# meter: <name>", "# sensor: <name>" comments name what the
//    columns cannot say. Joulescope and Otii headers mark the trace as an external meter's (Provenance::sensor
//    names it), Power Gadget's as an on-board sensor (RAPL); otherwise the measurement kind stays unknown.
// Errors (bs::ImportError, each naming file:line:column and column name): no header, no time or no
// current/power column, header without rows, a non-numeric cell, a time cell that is neither number nor date-time,
// an unclosed quote, a row with too few or too many cells, mixed separators, negative time, time going backwards.
// Warnings: ignored columns, missing samples, repeated times (kept; they add no width to the integral), the
// channel statistics use, current without a supply.
#include <string>

#include "common/format_importer.h"

namespace bs {

// Streams the file (memory: the parsed columns plus one 1 MiB block).
extern const FileFormat kPowerCsvFileFormat;

}  // namespace bs
