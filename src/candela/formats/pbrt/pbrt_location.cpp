#include "candela/formats/pbrt/pbrt_location.h"

namespace candela::pbrt {

namespace {

std::string position(const Location& at) {
    std::string out = at.file;
    if (at.line > 0) {
        out += ":" + std::to_string(at.line);
        if (at.column > 0) out += ":" + std::to_string(at.column);
    }
    return out;
}

// " (included from a.pbrt:3:1) (included from main.pbrt:10:1)": innermost Include first.
std::string include_chain(const Location& at) {
    std::string out;
    for (const IncludeSite* site = at.included_from.get(); site; site = site->location.included_from.get())
        out += " (included from " + position(site->location) + ")";
    return out;
}

}  // namespace

std::string describe(const Location& at) { return position(at) + include_chain(at); }

void fail(const Location& at, const std::string& message) {
    throw SceneError(SourceLocation{at.file, at.line, at.column, ""}, message + include_chain(at));
}

}  // namespace candela::pbrt
