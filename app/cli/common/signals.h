// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include "util/cancel.h"

namespace bs::cli {

// A CancelToken that SIGINT/SIGTERM cancel, so Ctrl+C stops long work cleanly (transactions roll back).
const CancelToken& interrupt_token();

}  // namespace bs::cli
