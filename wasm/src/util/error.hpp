// Errors that reach a designer. Every failure in the core is a billow::Error with a stable code
// (for tests and the UI) and a message in the designer's words (for people).
#pragma once
#include <stdexcept>
#include <string>

namespace billow {

struct Error : std::runtime_error {
  std::string code;  // e.g. "obj.bad-index", "pattern.unknown-version"
  // Where on the pattern, when the failure has a place (a panel and one of its vertices), so that the
  // pattern builder can show it on the model; -1 otherwise.
  int panel = -1, vertex = -1;
  // export.sheet-too-narrow: the sheet width [mm] every piece fits in, for the app to offer; 0 otherwise.
  double sheetWidth = 0;
  Error(std::string code_, const std::string& message) : std::runtime_error(message), code(std::move(code_)) {}
  Error(std::string code_, const std::string& message, int panel_, int vertex_)
      : std::runtime_error(message), code(std::move(code_)), panel(panel_), vertex(vertex_) {}
};

}  // namespace billow
