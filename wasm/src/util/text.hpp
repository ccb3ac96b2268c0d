// Counts in the words of messages: "3 holes", "1 vertex is".
#pragma once
#include <cstdint>
#include <string>

namespace billow {

inline std::string plural(std::int64_t n, const std::string& one, const std::string& many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

// The many form adds an s.
inline std::string plural(std::int64_t n, const std::string& word) { return plural(n, word, word + "s"); }

}  // namespace billow
