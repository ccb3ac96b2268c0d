// Errors that reach a designer. Every failure in the core is a billow::Error with a stable code
// (for tests and the UI) and a message in the designer's words (for people).
#pragma once
#include <stdexcept>
#include <string>

namespace billow {

struct Error : std::runtime_error {
  std::string code;  // e.g. "obj.bad-index", "pattern.unknown-version"
  Error(std::string code_, const std::string& message) : std::runtime_error(message), code(std::move(code_)) {}
};

}  // namespace billow
