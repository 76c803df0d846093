// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One typed description per stored entity, used both to write a row and to read it back (store/tables.h): the
// column names, where each value lives in the model, and the rule a value read back must meet. A workspace is
// input like any file (anyone can edit or damage it), so reading applies the import rules: SQLite types checked,
// counts and sizes bounded by the import limits before anything is allocated, numbers finite, times > 0,
// enumerations known, JSON parsed with the importers' depth and size limits. A violation is a Flaw naming the
// column, in the importers' error categories, and the reader leaves that item out (store/workspace.cpp).
#include <cmath>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "model/error_category.h"
#include "model/import_limits.h"
#include "store/sqlite_db.h"

namespace bs::store {

// Why a value read back breaks its rule.
struct Flaw {
  std::string column;  // "run_samples.workers"; empty for a rule across columns
  ImportErrorCategory category = ImportErrorCategory::InvalidValue;
  std::string reason;  // "-256 is not 1 or more"
};
using Check = std::optional<Flaw>;

inline Flaw flaw(ImportErrorCategory category, std::string reason) { return {{}, category, std::move(reason)}; }

// Shortest text that reads back as the same double (for messages that quote a stored value).
std::string number_text(double v);

// Parses JSON read from a workspace with the importers' limits: at most max_json_bytes of text, nesting at most
// max_json_depth, at most max_json_values values (stopped while the tree is built, never after).
Check parse_json(std::string_view text, const ImportLimits& limits, nlohmann::json& out);

template <class T>
struct Column {
  std::string sql;  // the column (a read-only column may be an expression, e.g. length(pixels))
  std::function<void(sqlite::Statement&, int, const T&)> bind;                        // empty: not written
  std::function<Check(const sqlite::Statement&, int, T&, const ImportLimits&)> read;  // empty: not read
};

template <class T>
struct Table {
  std::string name;  // SQL table
  std::string noun;  // what one row is to a user ("run", "power trace"), for messages
  bool has_id = true;
  std::vector<std::string> keys;  // references (import_id, device_id, trace_id): written first, read after the id
  std::vector<Column<T>> columns;
  std::function<Check(const T&, const ImportLimits&)> rule;  // a rule across columns, after each column's own
};

// One row read back: its id (0 for tables without one), its keys in Table::keys order, the value, and its flaw.
template <class T>
struct Row {
  std::int64_t id = 0;
  std::vector<std::int64_t> keys;
  T value{};
  std::optional<Flaw> flaw;
};

namespace detail {

// SQLite keeps a column's declared type as an affinity only: a hand-edited row can hold text where a number
// belongs. Null, wrong types and oversize values are refused here, once, for every codec.
Check expect(const sqlite::Statement& st, int col, int sqlite_type, bool nullable, const ImportLimits& limits);
Check in_range(std::int64_t v, std::int64_t min, std::int64_t max);
enum class Bound { Finite, NonNegative, Positive };
Check bounded(double v, Bound bound);
Check json_rule(std::string_view text, const ImportLimits& limits, bool allow_empty);

}  // namespace detail

using detail::Bound;

// --- codecs: each names its column, reaches its member through `get` (a lambda taking const T& or T&) ---------

template <class T, class Get>
Column<T> text(std::string sql, Get get) {
  return {std::move(sql), [get](sqlite::Statement& st, int i, const T& r) { st.bind(i, std::string_view(get(r))); },
          [get](const sqlite::Statement& st, int i, T& r, const ImportLimits& l) -> Check {
            if (auto f = detail::expect(st, i, SQLITE_TEXT, false, l)) return f;
            get(r) = st.text(i);
            return std::nullopt;
          }};
}

// An integer member (int, std::int64_t, std::size_t) within [min, max].
template <class T, class Get>
Column<T> integer(std::string sql, Get get, std::int64_t min, std::int64_t max) {
  return {std::move(sql),
          [get](sqlite::Statement& st, int i, const T& r) { st.bind(i, static_cast<std::int64_t>(get(r))); },
          [get, min, max](const sqlite::Statement& st, int i, T& r, const ImportLimits& l) -> Check {
            if (auto f = detail::expect(st, i, SQLITE_INTEGER, false, l)) return f;
            const std::int64_t v = st.int64(i);
            if (auto f = detail::in_range(v, min, max)) return f;
            auto& m = get(r);
            m = static_cast<std::remove_reference_t<decltype(m)>>(v);
            return std::nullopt;
          }};
}

template <class T, class Get>
Column<T> flag(std::string sql, Get get) {
  return {std::move(sql), [get](sqlite::Statement& st, int i, const T& r) { st.bind(i, get(r) ? 1 : 0); },
          [get](const sqlite::Statement& st, int i, T& r, const ImportLimits& l) -> Check {
            if (auto f = detail::expect(st, i, SQLITE_INTEGER, false, l)) return f;
            if (auto f = detail::in_range(st.int64(i), 0, 1)) return f;
            get(r) = st.int64(i) != 0;
            return std::nullopt;
          }};
}

template <class T, class Get>
Column<T> real(std::string sql, Get get, Bound bound) {
  return {std::move(sql), [get](sqlite::Statement& st, int i, const T& r) { st.bind(i, static_cast<double>(get(r))); },
          [get, bound](const sqlite::Statement& st, int i, T& r, const ImportLimits& l) -> Check {
            if (auto f = detail::expect(st, i, SQLITE_FLOAT, false, l)) return f;
            if (auto f = detail::bounded(st.real(i), bound)) return f;
            get(r) = st.real(i);
            return std::nullopt;
          }};
}

// NULL is "not stated"; a stated value meets `bound`.
template <class T, class Get>
Column<T> optional_real(std::string sql, Get get, Bound bound) {
  return {std::move(sql), [get](sqlite::Statement& st, int i, const T& r) { st.bind(i, get(r)); },
          [get, bound](const sqlite::Statement& st, int i, T& r, const ImportLimits& l) -> Check {
            if (auto f = detail::expect(st, i, SQLITE_FLOAT, true, l)) return f;
            const std::optional<double> v = st.optional_real(i);
            if (v)
              if (auto f = detail::bounded(*v, bound)) return f;
            get(r) = v;
            return std::nullopt;
          }};
}

// An enumeration stored as text; `names` lists every value with its stored name, and any other text is refused.
template <class T, class Get, class E>
Column<T> enumeration(std::string sql, Get get, std::vector<std::pair<E, const char*>> names) {
  return {std::move(sql),
          [get, names](sqlite::Statement& st, int i, const T& r) {
            for (const auto& [e, name] : names)
              if (e == get(r)) st.bind(i, std::string_view(name));
          },
          [get, names](const sqlite::Statement& st, int i, T& r, const ImportLimits& l) -> Check {
            if (auto f = detail::expect(st, i, SQLITE_TEXT, false, l)) return f;
            const std::string v = st.text(i);
            for (const auto& [e, name] : names)
              if (v == name) {
                get(r) = e;
                return std::nullopt;
              }
            std::string known;
            for (const auto& n : names) known += (known.empty() ? "" : ", ") + std::string(n.second);
            return flaw(ImportErrorCategory::InvalidValue, "unknown value '" + v + "' (known: " + known + ")");
          }};
}

// A string member that holds JSON text (kept as text in the model); read back only when it parses within the
// limits. `allow_empty`: the empty string means "none".
// `empty_as`: what an empty member is written as ("{}" for read options that are JSON even when there are none).
template <class T, class Get>
Column<T> json_text(std::string sql, Get get, bool allow_empty, std::string empty_as = {}) {
  return {std::move(sql),
          [get, empty_as](sqlite::Statement& st, int i, const T& r) {
            st.bind(i, std::string_view(get(r).empty() ? empty_as : get(r)));
          },
          [get, allow_empty](const sqlite::Statement& st, int i, T& r, const ImportLimits& l) -> Check {
            if (auto f = detail::expect(st, i, SQLITE_TEXT, false, l)) return f;
            std::string v = st.text(i);
            if (auto f = detail::json_rule(v, l, allow_empty)) return f;
            get(r) = std::move(v);
            return std::nullopt;
          }};
}

// A value of any type kept as a JSON text column through `to` (value -> json) and `from` (parsed json -> value,
// or a Flaw): provenance, measurement values, channel statistics.
template <class T, class Get, class To, class From>
Column<T> json(std::string sql, Get get, To to, From from) {
  return {std::move(sql),
          [get, to](sqlite::Statement& st, int i, const T& r) { st.bind(i, std::string_view(to(get(r)).dump())); },
          [get, from](const sqlite::Statement& st, int i, T& r, const ImportLimits& l) -> Check {
            if (auto f = detail::expect(st, i, SQLITE_TEXT, false, l)) return f;
            nlohmann::json j;
            if (auto f = parse_json(st.text(i), l, j)) return f;
            return from(j, get(r), l);
          }};
}

// Written as a fixed SQL value, never read: columns kept for older readers (schema 5's empty sample BLOBs).
template <class T>
Column<T> written_as(std::string sql, std::function<void(sqlite::Statement&, int, const T&)> bind) {
  return {std::move(sql), std::move(bind), {}};
}

// Read only: a check on an expression against what the row's earlier columns hold (e.g. a BLOB's length).
template <class T>
Column<T> checked(std::string sql_expression,
                  std::function<Check(const sqlite::Statement&, int, T&, const ImportLimits&)> read) {
  return {std::move(sql_expression), {}, std::move(read)};
}

// --- SQL and rows -------------------------------------------------------------------------------------------

template <class T>
std::string insert_sql(const Table<T>& t) {
  std::string cols, marks;
  const auto add = [&](const std::string& c) {
    cols += (cols.empty() ? "" : ", ") + c;
    marks += marks.empty() ? "?" : ",?";
  };
  for (const auto& k : t.keys) add(k);
  for (const auto& c : t.columns)
    if (c.bind) add(c.sql);
  return "INSERT INTO " + t.name + "(" + cols + ") VALUES (" + marks + ")";
}

template <class T>
std::string select_sql(const Table<T>& t, const std::string& tail) {
  std::string cols = t.has_id ? "id" : "0";
  for (const auto& k : t.keys) cols += ", " + k;
  for (const auto& c : t.columns)
    if (c.read) cols += ", " + c.sql;
  return "SELECT " + cols + " FROM " + t.name + (tail.empty() ? "" : " " + tail);
}

// A prepared INSERT for one table, reused for every row.
template <class T>
class Inserter {
 public:
  Inserter(const sqlite::Db& db, const Table<T>& t) : db_(db), t_(t), st_(db, insert_sql(t).c_str()) {}
  // Writes `value` with `keys` (in Table::keys order) and returns the new row's id.
  std::int64_t insert(std::initializer_list<std::int64_t> keys, const T& value) {
    int i = 1;
    for (const std::int64_t k : keys) st_.bind(i++, k);
    for (const auto& c : t_.columns)
      if (c.bind) c.bind(st_, i++, value);
    st_.run();
    return sqlite3_last_insert_rowid(db_.get());
  }

 private:
  const sqlite::Db& db_;
  const Table<T>& t_;
  sqlite::Statement st_;
};

// Reads every row that `tail` (WHERE / ORDER BY) selects, checking each value against its column's rule, and
// calls `each(Row<T>&&)`. A flawed row is still handed over (with `flaw` set, the value partly filled), so the
// caller can name the damaged item and leave it out.
template <class T, class Each>
void read_rows(const sqlite::Db& db, const Table<T>& t, const ImportLimits& limits, const std::string& tail,
               Each&& each, const std::function<void(sqlite::Statement&)>& bind = {}) {
  sqlite::Statement st(db, select_sql(t, tail).c_str());
  if (bind) bind(st);
  while (st.step()) {
    Row<T> row;
    row.id = st.int64(0);
    int i = 1;
    for (std::size_t k = 0; k < t.keys.size(); ++k) row.keys.push_back(st.int64(i++));
    for (const auto& c : t.columns) {
      if (!c.read) continue;
      if (!row.flaw)
        if (auto f = c.read(st, i, row.value, limits)) {
          f->column = t.name + "." + c.sql;
          row.flaw = std::move(f);
        }
      ++i;
    }
    if (!row.flaw && t.rule)
      if (auto f = t.rule(row.value, limits)) row.flaw = std::move(f);
    each(std::move(row));
  }
}

}  // namespace bs::store
