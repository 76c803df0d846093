// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Base64 (RFC 4648, with padding) for the bytes of result files carried inside JSON events.
#include <optional>
#include <string>
#include <string_view>

namespace bs::remote {

std::string base64_encode(std::string_view bytes);
// The bytes, or nothing when `text` is not canonical padded base64 (wrong length, a foreign character).
std::optional<std::string> base64_decode(std::string_view text);

}  // namespace bs::remote
