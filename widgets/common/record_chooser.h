// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The box a tab of stored records picks the one it shows with (Headroom, Sustained): one entry per record, its
// description as text and its id as data. Refilled when the workspace changes, it keeps the record shown while that
// is still there, except that a record newer than any seen before (a higher id: a run just stored or imported) comes
// to the front. The tabs did this alike, each with its own copy.
#include <QString>
#include <cstdint>
#include <type_traits>
#include <vector>

class QComboBox;

namespace bs::ui {

// `tip` as the box's tooltip, and the width of a record's description set by its contents' length: the open list
// shows a description whole, the closed box does not widen the tab.
void shape_record_chooser(QComboBox* chooser, const QString& tip);

struct RecordEntry {
  QString text;
  std::int64_t id;
};

// Fills `chooser` with `entries` (signals blocked: the tab shows the choice itself), choosing the record shown before
// when it is still there and no newer one came. `newest_seen` is the highest id the tab has shown so far, kept by the
// tab and updated here.
void refill_record_chooser(QComboBox* chooser, const std::vector<RecordEntry>& entries, std::int64_t& newest_seen);

// The same for stored records that have an `id`, `describe` giving each one's text (a tab's own function: its type
// is not deduced, so that an overloaded name picks the one for `Stored`).
template <class Stored>
void refill_record_chooser(QComboBox* chooser, const std::vector<Stored>& records,
                           std::type_identity_t<QString (*)(const Stored&)> describe, std::int64_t& newest_seen) {
  std::vector<RecordEntry> entries;
  for (const Stored& s : records) entries.push_back({describe(s), s.id});
  refill_record_chooser(chooser, entries, newest_seen);
}

}  // namespace bs::ui
