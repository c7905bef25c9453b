#include "candela/core/error.h"

namespace candela {

namespace {
std::string format_location(const SourceLocation& w, const std::string& message) {
    std::string out;
    if (!w.file.empty()) {
        out += w.file;
        if (w.line > 0) {
            out += ":" + std::to_string(w.line);
            if (w.column > 0) out += ":" + std::to_string(w.column);
        }
        out += ": ";
    }
    if (!w.json_pointer.empty()) out += w.json_pointer + ": ";
    return out + message;
}
}  // namespace

SceneError::SceneError(SourceLocation where, std::string message)
    : std::runtime_error(format_location(where, message)),
      where_(std::move(where)),
      message_(std::move(message)) {}

std::string SceneError::formatted() const { return what(); }

}  // namespace candela
