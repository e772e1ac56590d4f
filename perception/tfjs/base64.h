// Base64 decoding (RFC 4648), as the proto3 JSON mapping stores `bytes`
// fields: the standard and the URL-safe alphabets, with or without padding.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace alplan::perception {

// The decoded bytes, or nothing if `text` is not base64.
std::optional<std::string> decode_base64(std::string_view text);

}  // namespace alplan::perception
