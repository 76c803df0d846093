// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The ImportError a parse throws, for tests that check category, place and wording. Input that is accepted fails
// the test (an exception Qt Test reports) instead of returning a stand-in error a careless check could pass on.
#include <stdexcept>
#include <utility>

#include "common/import_error.h"

namespace bs::test {

template <class Parse>
ImportError import_error_of(Parse&& parse) {
  try {
    (void)std::forward<Parse>(parse)();
  } catch (const ImportError& e) {
    return e;
  }
  throw std::runtime_error("expected an ImportError, but the input was accepted");
}

}  // namespace bs::test
