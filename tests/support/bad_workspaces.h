// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The crafted-workspace corpus (tests/data/bad-workspaces/manifest.json, issue #37): each case is the paper
// workspace with one thing damaged, made at test time by applying the case's SQL (foreign keys and CHECK
// constraints off, as a hand edit with any SQLite tool) or an operation on the file. Shared by
// tests/app/workspace/test_cli_bad_workspaces.cpp, tests/app/gui/test_damage_banner.cpp and the
// make_bad_workspaces tool (scripts/make-bad-workspaces).
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <sqlite3.h>
#include <nlohmann/json.hpp>

namespace bs::test {

struct BadWorkspace {
  std::string name;
  std::string sql;                    // applied to a copy of the base workspace (op "sql")
  std::string op = "sql";             // "sql", "truncate", "replace", "other-sqlite"
  double keep_fraction = 0.5;         // truncate: the share of the file kept
  std::string content;                // replace: the file's new bytes
  std::string expect;                 // "damaged", "check", "error", "ok"
  std::string item;                   // damaged: the start of the item's name ("power trace #")
  std::string category;               // damaged: to_string(ImportErrorCategory)
  std::vector<std::string> contains;  // text the warning / error / check finding must contain
  bool in_samples = false;            // found: "samples" (when the samples load, not on opening)
};

inline std::vector<BadWorkspace> load_bad_workspaces(const std::string& data_dir) {
  std::ifstream in(data_dir + "/bad-workspaces/manifest.json");
  if (!in) throw std::runtime_error("cannot read " + data_dir + "/bad-workspaces/manifest.json");
  const auto doc = nlohmann::json::parse(in);
  std::vector<BadWorkspace> out;
  for (const auto& e : doc.at("cases")) {
    BadWorkspace c;
    c.name = e.at("name").get<std::string>();
    c.expect = e.at("expect").get<std::string>();
    c.sql = e.value("sql", "");
    c.op = e.value("op", "sql");
    c.keep_fraction = e.value("keep_fraction", 0.5);
    c.content = e.value("content", "");
    c.item = e.value("item", "");
    c.category = e.value("category", "");
    c.contains = e.value("contains", std::vector<std::string>{});
    c.in_samples = e.value("found", "") == "samples";
    out.push_back(std::move(c));
  }
  return out;
}

inline void exec_sql(const std::string& path, const std::string& sql) {
  sqlite3* db = nullptr;
  if (sqlite3_open(path.c_str(), &db) != SQLITE_OK) throw std::runtime_error("cannot open " + path);
  char* err = nullptr;
  const int rc = sqlite3_exec(db, sql.c_str(), nullptr, nullptr, &err);
  const std::string msg = err ? err : "";
  sqlite3_free(err);
  sqlite3_close(db);
  if (rc != SQLITE_OK) throw std::runtime_error(path + ": " + sql + ": " + msg);
}

// Writes case `c` as `dir`/<name>.bsw from the sound workspace `base` and returns its path.
inline std::string make_bad_workspace(const BadWorkspace& c, const std::string& base, const std::string& dir) {
  namespace fs = std::filesystem;
  const std::string path = dir + "/" + c.name + ".bsw";
  fs::remove(path);
  if (c.op == "replace") {
    std::ofstream(path, std::ios::binary) << c.content;
  } else if (c.op == "other-sqlite") {
    exec_sql(path, "CREATE TABLE notes(id INTEGER PRIMARY KEY, text TEXT); INSERT INTO notes(text) VALUES ('hello')");
  } else {
    fs::copy_file(base, path);
    if (c.op == "truncate") {
      fs::resize_file(path, static_cast<std::uintmax_t>(static_cast<double>(fs::file_size(path)) * c.keep_fraction));
    } else if (c.op == "sql") {
      // DELETE journal: the result is one self-contained file (a WAL would hold the change beside it).
      exec_sql(path, "PRAGMA journal_mode = DELETE; PRAGMA foreign_keys = OFF; PRAGMA ignore_check_constraints = ON; " +
                         c.sql);
    } else {
      throw std::runtime_error("manifest: unknown op " + c.op);
    }
  }
  return path;
}

}  // namespace bs::test
