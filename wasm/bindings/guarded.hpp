// The error boundary of every binding: runs fn (returning JSON text) and wraps its result as
// {"status":"ok","result":...}, or turns any exception into {"status":"error","code","message"} (with
// "details": {"sheet_width"} when an error carries the sheet width that fits).
#pragma once
#include <new>
#include <nlohmann/json.hpp>
#include <string>

#include "util/error.hpp"

namespace billow::bindings {

template <class Fn>
std::string guarded(Fn fn) {
  using nlohmann::json;
  try {
    return "{\"status\":\"ok\",\"result\":" + fn() + "}";
  } catch (const billow::Error& e) {
    json reply = {{"status", "error"}, {"code", e.code}, {"message", e.what()}};
    if (e.sheetWidth > 0) reply["details"] = {{"sheet_width", e.sheetWidth}};
    return reply.dump();
  } catch (const std::bad_alloc&) {
    return json({{"status", "error"},
                 {"code", "memory"},
                 {"message", "Billow ran out of memory. Try a coarser resolution or a smaller mesh."}})
        .dump();
  } catch (const std::exception& e) {
    return json({{"status", "error"}, {"code", "internal"}, {"message", std::string("Internal error: ") + e.what()}})
        .dump();
  }
}

}  // namespace billow::bindings
