// Footfall — what a user wrote, as an error message shows it: one line that
// no name, key or value can break, forge or colour.
#pragma once

#include <cstdio>
#include <string>

namespace footfall::detail {

/// `text` in single quotes, with control characters, backslashes and quotes
/// escaped (\n, \t, \x1b, \', \\), cut to `limit` characters with "...".
inline std::string user_text(const std::string& text, std::size_t limit = 80) {
  std::string out = "'";
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (i == limit) {
      out += "...";
      break;
    }
    const auto c = static_cast<unsigned char>(text[i]);
    if (c == '\n') {
      out += "\\n";
    } else if (c == '\t') {
      out += "\\t";
    } else if (c == '\'' || c == '\\') {
      out += '\\';
      out += static_cast<char>(c);
    } else if (c < 0x20 || c == 0x7f) {
      char escaped[5];
      std::snprintf(escaped, sizeof escaped, "\\x%02x", c);
      out += escaped;
    } else {
      out += static_cast<char>(c);
    }
  }
  return out + "'";
}

}  // namespace footfall::detail
