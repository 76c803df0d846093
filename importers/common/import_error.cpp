// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/import_error.h"

namespace bs {
namespace {

std::string format_message(const ErrorLocation& loc, const std::string& reason) {
  std::string msg = loc.file.empty() ? std::string("<input>") : loc.file;
  if (loc.line > 0) {
    msg += ':' + std::to_string(loc.line);
    if (loc.column > 0) msg += ':' + std::to_string(loc.column);
  }
  msg += ": ";
  if (!loc.field.empty()) msg += loc.field + ": ";
  msg += reason;
  return msg;
}

}  // namespace

ImportError::ImportError(ImportErrorCategory category, ErrorLocation location, std::string reason)
    : std::runtime_error(format_message(location, reason)),
      category_(category),
      location_(std::move(location)),
      reason_(std::move(reason)) {}

}  // namespace bs
