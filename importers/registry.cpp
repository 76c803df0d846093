// SPDX-License-Identifier: GPL-3.0-or-later
#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "clpeak_text.h"
#include "google_benchmark_json.h"
#include "importer.h"
#include "power_csv.h"
#include "run_json.h"
#include "tegrastats.h"

namespace bs {
namespace {

std::vector<std::unique_ptr<Importer>> make_importers() {
  std::vector<std::unique_ptr<Importer>> list;
  list.push_back(std::make_unique<RunJsonImporter>());
  list.push_back(std::make_unique<GoogleBenchmarkJsonImporter>());
  list.push_back(std::make_unique<ClpeakTextImporter>());
  list.push_back(std::make_unique<PowerCsvImporter>());
  list.push_back(std::make_unique<TegrastatsImporter>());
  return list;
}

[[noreturn]] void io_error(const std::string& path, const std::string& what) {
  throw ImportError(ImportErrorCategory::Io, {path, 0, 0, {}}, what);
}

std::ifstream open_or_throw(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) io_error(path, "is a folder, not a file");
  std::ifstream f(path, std::ios::binary);
  if (!f) io_error(path, std::string("cannot open: ") + std::strerror(errno));
  return f;
}

}  // namespace

const std::vector<std::unique_ptr<Importer>>& all_importers() {
  static const auto importers = make_importers();
  return importers;
}

const Importer* find_importer(std::string_view id) {
  for (const auto& imp : all_importers())
    if (imp->id() == id) return imp.get();
  return nullptr;
}

std::string read_head(const std::string& path, std::size_t max_bytes) {
  std::ifstream f = open_or_throw(path);
  std::string head(max_bytes, '\0');
  f.read(head.data(), static_cast<std::streamsize>(max_bytes));
  head.resize(static_cast<std::size_t>(f.gcount()));
  if (f.bad()) io_error(path, "read error");
  return head;
}

std::string read_whole_file(const std::string& path, std::size_t max_bytes) {
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  if (ec) io_error(path, "cannot read size: " + ec.message());
  // Checked before allocating: the size comes from the file system, never from the file's own claims.
  if (size > max_bytes)
    throw ImportError(ImportErrorCategory::TooLarge, {path, 0, 0, {}},
                      "file is " + std::to_string(size) + " bytes; the limit for this format is " +
                          std::to_string(max_bytes) + " bytes");
  std::ifstream f = open_or_throw(path);
  std::string text(static_cast<std::size_t>(size), '\0');
  f.read(text.data(), static_cast<std::streamsize>(size));
  text.resize(static_cast<std::size_t>(f.gcount()));
  if (f.bad()) io_error(path, "read error");
  return text;
}

void check_text(std::string_view head, const std::string& path) {
  const ErrorLocation at{path, 0, 0, {}};
  if (head.find_first_not_of(" \t\r\n") == std::string_view::npos)
    throw ImportError(ImportErrorCategory::Empty, at, head.empty() ? "file is empty" : "file holds only whitespace");
  if (head.starts_with("\xFF\xFE") || head.starts_with("\xFE\xFF"))
    throw ImportError(ImportErrorCategory::Encoding, at, "file is UTF-16 (or UTF-32); save it as UTF-8");
  const std::size_t nul = head.find('\0');
  if (nul != std::string_view::npos) {
    // Text in UTF-16 without a BOM has a NUL in every other byte.
    std::size_t nuls = std::count(head.begin(), head.end(), '\0');
    if (head.size() >= 4 && nuls * 2 >= head.size() - 1 && nuls * 2 <= head.size() + 1)
      throw ImportError(ImportErrorCategory::Encoding, at, "file looks like UTF-16 without a byte-order mark");
    throw ImportError(ImportErrorCategory::Binary, at,
                      "file is binary (NUL byte at offset " + std::to_string(nul) + "), not a text format");
  }
}

ImportBatch import_file(const std::string& path, const CancelToken& cancel, const ImportLimits& limits) {
  std::string head = read_head(path);
  check_text(head, path);
  std::string_view view = head;
  if (view.starts_with("\xEF\xBB\xBF")) view.remove_prefix(3);
  const Importer* best = nullptr;
  int best_score = 0;
  for (const auto& imp : all_importers()) {
    const int score = imp->sniff(view, path);
    if (score > best_score) {
      best_score = score;
      best = imp.get();
    }
  }
  if (!best) {
    std::string tried;
    for (const auto& imp : all_importers()) tried += (tried.empty() ? "" : ", ") + std::string(imp->description());
    throw ImportError(ImportErrorCategory::UnknownFormat, {path, 0, 0, {}},
                      "not a format BenchScope reads (tried: " + tried + ")");
  }
  ImportBatch batch = best->parse(path, limits, cancel);
  batch.source_path = path;
  batch.format = std::string(best->id());
  return batch;
}

}  // namespace bs
