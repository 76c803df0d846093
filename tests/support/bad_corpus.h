// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The bad-input corpus (tests/data/bad/manifest.json): committed files, a few generated ones that are too big to
// commit, and a few real files other people published ("third_party": true), which are never committed and are read
// from the shared folder (BENCHSCOPE_PUBLIC_DATA_DIR/tests/data, tests/support/public_data.h). Shared by
// tests/importers/common/test_bad_corpus.cpp (categories and places) and tests/app/workspace/test_cli_bad_corpus.cpp
// (the CLI rejects each and leaves the workspace untouched); each checks the third-party entries in a test function
// of their own, which skips when that folder is absent.
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace bs::test {

struct BadCase {
  std::string path;                   // absolute, ready to import
  std::string category;               // to_string(ImportErrorCategory)
  bool place = false;                 // the error must name a line or a field
  std::vector<std::string> contains;  // text the error message must contain (a file:line:col prefix, the reason)
  bool third_party = false;           // under the shared folder's tests/data, not the project's
};

// The folder of the corpus's third-party files, relative to the shared folder (BENCHSCOPE_PUBLIC_DATA_DIR).
inline constexpr const char* kThirdPartyBadFolder = "tests/data/bad";

inline void write_generated(const std::string& kind, const std::string& path) {
  std::ofstream f(path, std::ios::binary);
  const auto repeat = [&](char c, std::size_t n) {
    const std::string block(1 << 20, c);
    for (; n >= block.size(); n -= block.size()) f << block;
    f << std::string(n, c);
  };
  if (kind == "json-deep-nesting") {
    f << R"({"format":"benchscope-run","version":1,"runs":)";
    repeat('[', 100000);
    repeat(']', 100000);
    f << "}";
  } else if (kind == "json-unclosed-brackets") {
    repeat('[', 100000);
  } else if (kind == "csv-50mb-line") {
    f << "time_s,current_A\n0,";
    repeat('1', 50'000'000);
    f << "\n";
  } else if (kind == "tegrastats-50mb-line") {
    f << "RAM 1/2MB CPU [1%@1] VDD_IN 1/1 ";
    repeat('A', 50'000'000);
    f << "\n";
  } else {
    throw std::runtime_error("manifest: unknown generator " + kind);
  }
  if (!f) throw std::runtime_error("cannot write " + path);
}

// Reads the manifest; generated inputs are written into `scratch_dir`. Paths of third-party entries are under
// `public_data_dir`/tests/data (BENCHSCOPE_PUBLIC_DATA_DIR), whether or not that folder exists.
inline std::vector<BadCase> load_bad_corpus(const std::string& data_dir, const std::string& public_data_dir,
                                            const std::string& scratch_dir) {
  std::ifstream in(data_dir + "/bad/manifest.json");
  if (!in) throw std::runtime_error("cannot read " + data_dir + "/bad/manifest.json");
  const auto doc = nlohmann::json::parse(in);
  std::vector<BadCase> out;
  for (const auto& e : doc.at("files")) {
    BadCase c{"", e.at("category").get<std::string>(), e.at("place").get<bool>(), {}, e.value("third_party", false)};
    // "contains": one text or a list of texts the error must contain.
    if (const auto it = e.find("contains"); it != e.end())
      c.contains =
          it->is_string() ? std::vector<std::string>{it->get<std::string>()} : it->get<std::vector<std::string>>();
    if (e.contains("generate")) {
      c.path = scratch_dir + "/" + e.at("file").get<std::string>();
      write_generated(e.at("generate").get<std::string>(), c.path);
    } else {
      c.path = (c.third_party ? public_data_dir + "/tests/data" : data_dir) + "/" + e.at("file").get<std::string>();
    }
    out.push_back(std::move(c));
  }
  return out;
}

// The cases that are (third_party) or are not (!third_party) real files of the shared folder.
inline std::vector<BadCase> bad_cases(const std::vector<BadCase>& all, bool third_party) {
  std::vector<BadCase> out;
  for (const BadCase& c : all)
    if (c.third_party == third_party) out.push_back(c);
  return out;
}

}  // namespace bs::test
