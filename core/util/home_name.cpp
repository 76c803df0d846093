// SPDX-License-Identifier: GPL-3.0-or-later
#include "util/home_name.h"

namespace bs {

std::string home_name(std::string_view where, std::string_view platform, std::string_view date) {
  std::string name(where);
  name += " (";
  name += platform;
  name += ", ";
  name += date;
  name += ')';
  return name;
}

}  // namespace bs
