// Counts in the words of messages: "3 holes", "1 vertex is", "500,000".
#pragma once
#include <cstdint>
#include <string>

namespace billow {

inline std::string plural(std::int64_t n, const std::string& one, const std::string& many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

// Digits grouped by thousands, as a designer reads a large count: 500000 -> "500,000".
inline std::string grouped(std::int64_t n) {
  std::string digits = std::to_string(n < 0 ? -n : n), out;
  for (size_t k = 0; k < digits.size(); ++k) {
    if (k > 0 && (digits.size() - k) % 3 == 0) out += ',';
    out += digits[k];
  }
  return n < 0 ? "-" + out : out;
}

// The one message for a mesh past what Billow can work with, whichever reader or check finds it. subject: "The OFF
// file", "The mesh"; what: "triangles", "vertices", "distinct vertices"; count: the mesh's own, or -1 where a reader
// stops before it knows it.
inline std::string tooLargeMessage(const std::string& subject, std::int64_t count, std::int64_t limit,
                                   const std::string& what) {
  const std::string has = count > limit ? grouped(count) + " " + what + ", more than the " + grouped(limit)
                                        : "more than " + grouped(limit) + " " + what + ", more than";
  return subject + " has " + has +
         " Billow can work with. Simplify it (for example with Decimate in Blender or MeshLab) and open it again.";
}

// The many form adds an s.
inline std::string plural(std::int64_t n, const std::string& word) { return plural(n, word, word + "s"); }

}  // namespace billow
