// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/signals.h"

#include <csignal>

namespace bs::cli {
namespace {

CancelToken token;

extern "C" void on_interrupt(int) { token.cancel(); }  // an atomic store: async-signal-safe

}  // namespace

const CancelToken& interrupt_token() {
  static const bool installed = [] {
    std::signal(SIGINT, on_interrupt);
    std::signal(SIGTERM, on_interrupt);
    return true;
  }();
  (void)installed;
  return token;
}

}  // namespace bs::cli
